// Without the viewer (WHITTED_BUILD_VIEWER=OFF) its tests are not compiled at all; this one stands
// in for them, so that a run without them is not green unless that was asked for.
#ifndef WHITTED_VIEWER_PATH
#include <gtest/gtest.h>

#include "support/needs.h"

namespace whitted {
namespace {

TEST(Viewer, IsBuiltSoThatItsTestsRun) {
    WHITTED_NEEDS(test::kSkipViewerTests,
                  "the viewer is not built (WHITTED_BUILD_VIEWER=OFF), so neither its controller's tests nor its "
                  "screen tests ran");
}

}  // namespace
}  // namespace whitted
#endif

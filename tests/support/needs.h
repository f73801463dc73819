#pragma once
// Tests that need something from outside this repository (the shared corpus in ../shared, the
// viewer and the X tools of its screen tests) FAIL when it is missing: a green run must mean that
// everything was checked. Only an explicit opt-out turns the failure into a skip, an environment
// variable whose value says why (e.g. WHITTED_SKIP_VIEWER_TESTS="no X server in this container").
// scripts/test.sh fails a run with skipped tests unless such a variable is set.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

namespace whitted::test {

inline constexpr const char* kSkipSharedTests = "WHITTED_SKIP_SHARED_TESTS";  // ../shared is not here
inline constexpr const char* kSkipViewerTests = "WHITTED_SKIP_VIEWER_TESTS";  // no viewer, X server or X tools

// The reason given in `variable`, or "" when it is unset or empty.
inline std::string opt_out_reason(const char* variable) {
    const char* why = std::getenv(variable);
    return why ? why : "";
}

}  // namespace whitted::test

// In a test body (or SetUp): when `missing` (what is missing and how to get it) is not empty,
// skips the test if the opt-out variable `variable` gives a reason, and fails it otherwise.
#define WHITTED_NEEDS(variable, missing)                                                                   \
    do {                                                                                                   \
        const std::string whitted_missing_ = (missing);                                                    \
        if (whitted_missing_.empty()) break;                                                               \
        const std::string whitted_why_ = ::whitted::test::opt_out_reason(variable);                         \
        if (!whitted_why_.empty())                                                                         \
            GTEST_SKIP() << whitted_missing_ << "; skipped as " << (variable) << " asks: " << whitted_why_; \
        FAIL() << whitted_missing_ << " (to skip this test on purpose, set " << (variable)                 \
               << " to the reason)";                                                                       \
    } while (0)

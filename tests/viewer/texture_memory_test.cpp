// The viewer's memory of the user's answers about missing textures, without a display.
#if __has_include("texture_memory.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "texture_memory.h"

#include <gtest/gtest.h>

namespace whitted::viewer {
namespace {

TEST(TextureMemory, AnswersHoldForTheirSceneOnly) {
    TextureMemory m;
    m.pick("a.sc", "wood.png", "/pics/wood.png");
    m.decline("a.sc", "marble.png");
    EXPECT_TRUE(m.declined("a.sc", "marble.png"));
    EXPECT_FALSE(m.declined("b.sc", "marble.png"));
    EXPECT_FALSE(m.declined("a.sc", "wood.png"));

    TextureOptions a, b;
    m.apply("a.sc", a);
    m.apply("b.sc", b);
    EXPECT_EQ(a.overrides, (std::map<std::string, std::string>{{"wood.png", "/pics/wood.png"}}));
    EXPECT_EQ(a.checker_names, (std::set<std::string>{"marble.png"}));
    EXPECT_TRUE(b.overrides.empty());
    EXPECT_TRUE(b.checker_names.empty());
}

}  // namespace
}  // namespace whitted::viewer
#endif

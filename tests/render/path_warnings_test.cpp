// The path-mode warnings of a load (scene-format.md §9.2: one per material whose weights add up to
// more than 1): in the order of the file, whatever order the instances are drawn in.
#include <string>

#include <gtest/gtest.h>

#include "render/load_scene.h"

namespace whitted {
namespace {

TEST(PathWarnings, ComeInFileOrderOncePerMaterial) {
    // The walk meets the cube (line 3) first, then the sphere (line 2) twice, through its subgraph.
    const std::string text =
        "camera [ eye 0 0 5 ]\n"
        "mastersubgraph a [ trans [ object sphere [ diffuse 0.9 0.9 0.9 specular 0.5 0.5 0.5 ] ] ]\n"
        "mastersubgraph root [ trans [ object cube [ diffuse 0.8 0.8 0.8 reflect 0.5 0.5 0.5 ] ]\n"
        "  trans [ subgraph a ] trans [ translate 2 0 0 subgraph a ] ]\n";
    const LoadResult r = load_scene_text(text, "w.sc");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.path_warnings.size(), 2u);
    EXPECT_EQ(r.path_warnings[0].loc.line, 2);
    EXPECT_NE(r.path_warnings[0].message.find("(up to 1.4"), std::string::npos) << r.path_warnings[0].str();
    EXPECT_EQ(r.path_warnings[1].loc.line, 3);
    EXPECT_NE(r.path_warnings[1].message.find("(up to 1.3"), std::string::npos) << r.path_warnings[1].str();
}

}  // namespace
}  // namespace whitted

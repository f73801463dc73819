// Trans blocks: composition order, rotate, matrixRC/CR, singular matrices (scene-format.md §3).
#include <gtest/gtest.h>

#include "base/transforms.h"
#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::error_at;
using parse_test::parse;
using parse_test::parsed_ok;

// The matrix of the first trans block of `root`, parsed from "mastersubgraph root [ trans [ BODY ]
// ]".
glm::mat4 trans_matrix(const std::string& body) {
    const auto r = parse("mastersubgraph root [ trans [ " + body + " ] ]");
    EXPECT_TRUE(parsed_ok(r)) << body;
    if (!r.ok()) return glm::mat4(0.0f);
    return r.scene.subgraphs.at(r.scene.root).children.at(0).matrix;
}

void expect_maps(const glm::mat4& m, glm::vec3 from, glm::vec3 to) {
    const glm::vec4 p = m * glm::vec4(from, 1.0f);
    EXPECT_NEAR(p.x, to.x, 1e-5f);
    EXPECT_NEAR(p.y, to.y, 1e-5f);
    EXPECT_NEAR(p.z, to.z, 1e-5f);
    EXPECT_NEAR(p.w, 1.0f, 1e-6f);
}

TEST(ParseTransform, LastWrittenIsAppliedFirst) {
    // The spec's example: scale the unit cube to 20×1×20, then move it down 2.5:
    // (0.5, 0.5, 0.5) -> (10, 0.5, 10) -> (10, -2, 10).
    expect_maps(trans_matrix("translate 0 -2.5 0 scale 20 1 20 object cube [ ]"),
                {0.5f, 0.5f, 0.5f}, {10, -2, 10});
    // The origin: moved then scaled (1,0,0)·2 = (2,0,0) versus scaled then moved (1,0,0).
    expect_maps(trans_matrix("translate 1 0 0 scale 2 2 2"), {0, 0, 0}, {1, 0, 0});
    expect_maps(trans_matrix("scale 2 2 2 translate 1 0 0"), {0, 0, 0}, {2, 0, 0});
}

TEST(ParseTransform, TransformsAfterTheObjectCountToo) {
    expect_maps(trans_matrix("object cube [ ] translate 1 2 3"), {0, 0, 0}, {1, 2, 3});
    expect_maps(trans_matrix("translate 1 0 0 object cube [ ] scale 2 2 2"), {1, 1, 1}, {3, 2, 2});
}

TEST(ParseTransform, RotateIsRightHandedDegreesAboutANormalisedAxis) {
    expect_maps(trans_matrix("rotate 0 0 1 90"), {1, 0, 0}, {0, 1, 0});
    expect_maps(trans_matrix("rotate 0 0 7 90"), {1, 0, 0}, {0, 1, 0});  // axis length ignored
    expect_maps(trans_matrix("rotate 1 0 0 90"), {0, 1, 0}, {0, 0, 1});
    expect_maps(trans_matrix("rotate 0 1 0 90"), {0, 0, 1}, {1, 0, 0});
    expect_maps(trans_matrix("rotate 0 0 1 -90"), {1, 0, 0}, {0, -1, 0});
    expect_maps(trans_matrix("rotate 0 0 1 180"), {1, 0, 0}, {-1, 0, 0});
    // 120° about (1,1,1) cycles the axes x -> y -> z.
    expect_maps(trans_matrix("rotate 1 1 1 120"), {1, 0, 0}, {0, 1, 0});
}

TEST(ParseTransform, RotateWithZeroAxisIsAnError) {
    EXPECT_TRUE(error_at(parse("mastersubgraph root [\n trans [ rotate 0 0 0 45 ] ]"), 2, 10,
                         "'rotate' axis is zero"));
}

TEST(ParseTransform, MatrixRcIsRowByRowAndMatrixCrColumnByColumn) {
    // Row by row: a translation by (5, 6, 7).
    expect_maps(trans_matrix("matrixRC 1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1"), {0, 0, 0}, {5, 6, 7});
    // Column by column: the same translation.
    expect_maps(trans_matrix("matrixCR 1 0 0 0  0 1 0 0  0 0 1 0  5 6 7 1"), {0, 0, 0}, {5, 6, 7});
    // The same 16 numbers under both keywords give transposed matrices.
    const std::string numbers = " 2 1 0 0  0 3 0 0  0 0 4 0  0 0 0 1";
    const glm::mat4 rc = trans_matrix("matrixRC" + numbers);
    const glm::mat4 cr = trans_matrix("matrixCR" + numbers);
    // Row 0 of the RC matrix is (2 1 0 0): (0,1,0) -> (1, 3, 0).
    expect_maps(rc, {0, 1, 0}, {1, 3, 0});
    // Column 0 of the CR matrix is (2 1 0 0): (1,0,0) -> (2, 1, 0).
    expect_maps(cr, {1, 0, 0}, {2, 1, 0});
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_EQ(rc[c][r], cr[r][c]);
}

TEST(ParseTransform, ProjectiveMatrixIsAnError) {
    // Row by row, the last row is the 4th group; column by column, the 4th number of each group.
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [\n  matrixRC 1 0 0 0  0 1 0 0  0 0 1 0  "
                               "0 0 0.5 1 ] ]"),
                         2, 3, "'matrixRC' is not an affine transform: its last row must be 0 0 0 1, "
                               "found 0 0 0.5 1"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ matrixCR 1 0 0 0  0 1 0 0  0 0 1 0  "
                               "0 0 0 2 ] ]"),
                         1, 31, "found 0 0 0 2"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ matrixCR 1 0 0 1  0 1 0 0  0 0 1 0  "
                               "0 0 0 1 ] ]"),
                         1, 31, "found 1 0 0 1"));
}

TEST(ParseTransform, MatricesComposeWithTheOthers) {
    expect_maps(trans_matrix("translate 0 0 1 matrixRC 2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1"),
                {1, 1, 1}, {2, 2, 3});
}

TEST(ParseTransform, EachTransBlockHasItsOwnMatrix) {
    const auto r = parse(
        "mastersubgraph root [ trans [ translate 1 0 0 object cube [ ] ]\n"
        "trans [ object sphere [ ] subgraph a ] ]\nmastersubgraph a [ ]");
    ASSERT_TRUE(parsed_ok(r));
    const auto& root = r.scene.subgraphs.at(r.scene.root);
    ASSERT_EQ(root.children.size(), 2u);
    EXPECT_EQ(root.children[1].matrix, glm::mat4(1.0f));
    ASSERT_EQ(root.children[1].objects.size(), 1u);
    EXPECT_EQ(root.children[1].objects[0].kind, ShapeKind::Sphere);
    ASSERT_EQ(root.children[1].subgraphs.size(), 1u);
    EXPECT_EQ(root.children[1].subgraphs[0].name, "a");
    EXPECT_EQ(root.children[1].loc.line, 2);
    EXPECT_EQ(root.children[1].loc.col, 1);
}

TEST(ParseTransform, SingularMatrixIsAnErrorAtTheTransBlock) {
    EXPECT_TRUE(error_at(parse("mastersubgraph root [\n  trans [ scale 1 0 1 object cube [ ] ] ]"),
                         2, 3, "singular transform in the trans block opened at 2:3"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ object cube [ ] ]\n"
                               "trans [ scale 2 2 2 object cube [ ] scale 0 0 0 ] ]"),
                         2, 1, "singular"));
    // Rank 2: the second row is twice the first.
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ matrixRC 1 2 3 0 2 4 6 0 0 0 1 0 "
                               "0 0 0 1 ] ]"),
                         1, 23, "singular"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ matrixCR 0 0 0 0 0 0 0 0 0 0 0 0 "
                               "0 0 0 1 ] ]"),
                         1, 23, "singular"));
    // Overflow to infinity.
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ scale 1e30 1 1 scale 1e30 1 1 ] ]"),
                         1, 23, "singular"));
}

TEST(ParseTransform, SmallOrMirroredOrFarAwayIsNotSingular) {
    EXPECT_TRUE(parsed_ok(parse("mastersubgraph root [ trans [ scale 1e-4 1e-4 1e-4 ] ]")));
    EXPECT_TRUE(parsed_ok(parse("mastersubgraph root [ trans [ scale -1 1 1 ] ]")));
    EXPECT_TRUE(
        parsed_ok(parse("mastersubgraph root [ trans [ translate 1e7 0 0 scale 1 1e-3 1 ] ]")));
    EXPECT_TRUE(
        parsed_ok(parse("mastersubgraph root [ trans [ rotate 1 2 3 37 scale 5 0.01 2 ] ]")));
}

TEST(ParseTransform, IsSingularDirectly) {
    EXPECT_FALSE(is_singular(glm::mat4(1.0f)));
    EXPECT_TRUE(is_singular(glm::mat4(0.0f)));
    EXPECT_TRUE(is_singular(scale_matrix({1, 1, 0})));
    EXPECT_FALSE(is_singular(scale_matrix({1e-5f, 1e5f, 1})));
}

}  // namespace
}  // namespace whitted

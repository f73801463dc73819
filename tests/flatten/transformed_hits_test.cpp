// Shapes under the transforms of real scene files, end to end: parse, flatten, intersect in
// object space, normal back by the inverse transpose. Every expected hit distance and normal is
// worked out by hand from the transformed shape's implicit equation (comments give the steps).
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "integrator/surface.h"
#include "render/load_scene.h"

namespace whitted {
namespace {

struct WorldHit {
    float t;
    glm::vec3 normal;
};

class TransformedHits : public ::testing::Test {
protected:
    // A scene holding `body` inside mastersubgraph root (plus any other subgraphs in `extra`).
    void load(const std::string& body, const std::string& extra = "") {
        result_ = load_scene_text(extra + "mastersubgraph root [ " + body + " ]\n", "hits.sc");
        ASSERT_TRUE(result_.ok()) << (result_.diagnostics.empty() ? "" : result_.diagnostics[0].str());
    }
    std::optional<WorldHit> hit(glm::vec3 origin, glm::vec3 direction) const {
        const Scene& s = *result_.scene;
        const Ray ray{origin, direction};
        Hit h;
        if (!intersect_nearest(s.bvh, s.data.instances, ray, 0.0f, 1e30f, h)) return std::nullopt;
        return WorldHit{h.t, surface_at(s, ray, h).normal};
    }
    LoadResult result_;
};

void expect_hit(const std::optional<WorldHit>& got, float t, glm::vec3 normal) {
    ASSERT_TRUE(got.has_value());
    EXPECT_NEAR(got->t, t, 1e-5f);
    const glm::vec3 n = glm::normalize(normal);
    EXPECT_NEAR(got->normal.x, n.x, 1e-5f);
    EXPECT_NEAR(got->normal.y, n.y, 1e-5f);
    EXPECT_NEAR(got->normal.z, n.z, 1e-5f);
}

TEST_F(TransformedHits, NonUniformScaleOfASphere) {
    // scale 4 1 1: the ellipsoid x²/16 + y² + z² = 1/4. Along x = 1, y = 0 from z = 5 going −z:
    // z² = 1/4 − 1/16 = 3/16, z = 0.4330127, t = 5 − z. Normal ∝ ∇ = (2x/16, 2y, 2z) = (1/8, 0, 0.8660254).
    load("trans [ scale 4 1 1 object sphere [ ] ]");
    expect_hit(hit({1, 0, 5}, {0, 0, -1}), 5.0f - 0.4330127f, {0.125f, 0, 0.8660254f});
    // Along the long axis: x = ±2.
    expect_hit(hit({10, 0, 0}, {-1, 0, 0}), 8.0f, {1, 0, 0});
}

TEST_F(TransformedHits, RotatedScaledCube) {
    // rotate 0 0 1 45 then (applied first) scale 2 1 1: a 2 × 1 box turned 45° about z. The world
    // x axis point (s, 0, 0) is (s/√2, −s/√2) in the box's frame, inside while s/√2 ≤ 1/2 (the
    // narrow side binds): entry at s = √2/2, t = 5 − √2/2, through the box's −y face, whose
    // normal (0, −1) turned by 45° is (sin 45°, −cos 45°).
    load("trans [ rotate 0 0 1 45 scale 2 1 1 object cube [ ] ]");
    expect_hit(hit({5, 0, 0}, {-1, 0, 0}), 5.0f - 0.70710678f, {0.70710678f, -0.70710678f, 0});
    // Down the z axis: the front face z = 1/2, unturned.
    expect_hit(hit({0, 0, 5}, {0, 0, -1}), 4.5f, {0, 0, 1});
}

TEST_F(TransformedHits, NegativeScaleMirrorsAConeAndKeepsNormalsOutward) {
    // scale 1 −2 1: the apex goes to y = −1, the base disc (radius 1/2) to y = +1.
    load("trans [ scale 1 -2 1 object cone [ ] ]");
    // From above, the base cap at y = 1: outward is now +y.
    expect_hit(hit({0, 5, 0}, {0, -1, 0}), 4.0f, {0, 1, 0});
    // At y = 0 (object y = 0) the radius is (1/2 − y)/2 = 1/4: t = 5 − 1/4. Object implicit
    // f = x² + z² − (1/2 − y)²/4, ∇f = (2x, (1/2 − y)/2, 2z) = (1/2, 1/4, 0) at (1/4, 0, 0); in the
    // world Y = −2y, so ∂/∂Y = −(1/2)·∂/∂y: normal ∝ (1/2, −1/8, 0), outward and downward.
    expect_hit(hit({5, 0, 0}, {-1, 0, 0}), 4.75f, {0.5f, -0.125f, 0});
}

TEST_F(TransformedHits, MatrixRcIsRowsAndMatrixCrColumnsOfTheSameMatrix) {
    // x' = x + 2, y' = 3y: a sphere stretched to semi-axes (1/2, 3/2, 1/2) centred at x = 2.
    for (const char* m : {"matrixRC 1 0 0 2  0 3 0 0  0 0 1 0  0 0 0 1", "matrixCR 1 0 0 0  0 3 0 0  0 0 1 0  2 0 0 1"}) {
        SCOPED_TRACE(m);
        load(std::string("trans [ ") + m + " object sphere [ ] ]");
        expect_hit(hit({2, 5, 0}, {0, -1, 0}), 3.5f, {0, 1, 0});
        expect_hit(hit({10, 0, 0}, {-1, 0, 0}), 7.5f, {1, 0, 0});
    }
}

TEST_F(TransformedHits, ShearBringsNormalsBackByTheInverseTranspose) {
    // matrixRC x' = x + y: the cube's face x = 1/2 becomes the plane X − Y = 1/2, normal ∝ (1, −1, 0)
    // (not the sheared normal M·(1, 0, 0) = (1, 0, 0)); at Y = 0 it crosses the x axis at X = 1/2.
    load("trans [ matrixRC 1 1 0 0  0 1 0 0  0 0 1 0  0 0 0 1 object cube [ ] ]");
    expect_hit(hit({5, 0, 0}, {-1, 0, 0}), 4.5f, {1, -1, 0});
    // The top face y = 1/2 stays the plane Y = 1/2; at X = 1/4 the object point is x = −1/4, inside.
    expect_hit(hit({0.25f, 5, 0}, {0, -1, 0}), 4.5f, {0, 1, 0});
}

TEST_F(TransformedHits, LastTransformWrittenIsAppliedFirst) {
    // translate 1 0 0 scale 2 1 1: scale first, x ∈ [0, 2]. (Applied the other way round the box
    // would span x ∈ [1, 3], and the ray at x = 2.5 would hit it.)
    load("trans [ translate 1 0 0 scale 2 1 1 object cube [ ] ]");
    expect_hit(hit({0.25f, 5, 0}, {0, -1, 0}), 4.5f, {0, 1, 0});
    EXPECT_FALSE(hit({2.5f, 5, 0}, {0, -1, 0}).has_value());
}

TEST_F(TransformedHits, ParentMatrixTimesChildDownTheHierarchy) {
    // world = translate 10 0 0 · rotate 0 1 0 90 · scale 3 1 1: the long axis (x, semi-axis 3/2)
    // is turned onto z, then moved to x = 10. Along x it is 1/2 thick: t = 20 − 10.5; along z, 3/2.
    load("trans [ translate 10 0 0 subgraph turned ]",
         "mastersubgraph turned [ trans [ rotate 0 1 0 90 subgraph long ] ]\n"
         "mastersubgraph long [ trans [ scale 3 1 1 object sphere [ ] ] ]\n");
    expect_hit(hit({20, 0, 0}, {-1, 0, 0}), 9.5f, {1, 0, 0});
    expect_hit(hit({10, 0, 5}, {0, 0, -1}), 3.5f, {0, 0, 1});
}

TEST_F(TransformedHits, CompositionsFloatCannotHoldAreLocatedErrors) {
    // Each trans block alone is fine; composed, ten levels of 1e5 overflow float and ten of 1e-5
    // collapse to nothing. Both used to render a black image with no word said.
    for (const char* factor : {"1e5", "1e-5"}) {
        SCOPED_TRACE(factor);
        std::string text = "mastersubgraph l0 [ trans [ object sphere [ ] ] ]\n";
        for (int i = 1; i <= 10; ++i)
            text += "mastersubgraph l" + std::to_string(i) + " [ trans [ scale " + factor + " " + factor + " " + factor +
                    " subgraph l" + std::to_string(i - 1) + " ] ]\n";
        text += "mastersubgraph root [ trans [ subgraph l10 ] trans [ object cube [ ] ] ]\n";
        LoadResult r = load_scene_text(text, "deep.sc");
        EXPECT_FALSE(r.ok());
        ASSERT_FALSE(r.diagnostics.empty());
        EXPECT_EQ(r.diagnostics[0].str().rfind("deep.sc:1:29: error: the transforms down to this object, composed", 0), 0u)
            << r.diagnostics[0].str();
    }
    // An object 3e38 away: its bounds would overflow the acceleration structure's arithmetic.
    LoadResult far = load_scene_text(
        "mastersubgraph root [ trans [ translate 3e38 0 0 object sphere [ ] ] trans [ object cube [ ] ] ]\n", "far.sc");
    EXPECT_FALSE(far.ok());
    ASSERT_FALSE(far.diagnostics.empty());
    EXPECT_EQ(far.diagnostics[0].str().rfind("far.sc:1:50: error:", 0), 0u) << far.diagnostics[0].str();
    // Up and back down again is fine: only the composition matters.
    std::string text = "mastersubgraph l0 [ trans [ object sphere [ ] ] ]\n";
    for (int i = 1; i <= 12; ++i) {
        const char* f = i <= 6 ? "1e5" : "1e-5";
        text += "mastersubgraph l" + std::to_string(i) + " [ trans [ scale " + f + " " + f + " " + f + " subgraph l" +
                std::to_string(i - 1) + " ] ]\n";
    }
    text += "mastersubgraph root [ trans [ subgraph l12 ] ]\n";
    result_ = load_scene_text(text, "updown.sc");
    ASSERT_TRUE(result_.ok()) << result_.diagnostics[0].str();
    expect_hit(hit({0, 0, 5}, {0, 0, -1}), 4.5f, {0, 0, 1});
}

}  // namespace
}  // namespace whitted

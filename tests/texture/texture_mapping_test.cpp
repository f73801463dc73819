// Texture mapping seen in real renders (scene-format.md §8): a picture of four solid quadrants
// on every face, side and cap of the four shapes, checked at pixels whose (u, v) is computed by
// hand from the spec's camera (§5) and (u, v) formulas, with repeat counts 1×1 and 2×3.
// Mode raycast shows diffuse × texel unlit, so a pixel is exactly a quadrant colour.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "support/run_process.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

using namespace whitted::test;

constexpr int kSize = 48;        // rendered image, square
constexpr double kAngle = 40;    // vertical field of view
constexpr double kMargin = 0.03; // skip (s, t) this close to a quadrant edge (the texture is 64 px)

struct View {
    const char* name;
    glm::dvec3 eye, look, up;
};

// A camera 2 units from the origin on each axis, looking at it, with `up` chosen so that the
// face (or cap) it looks at shows the image upright — the spec promises that for every cube
// face and every cap seen from outside.
const View kFromPosZ{"+z", {0, 0, 2}, {0, 0, -1}, {0, 1, 0}};
const View kFromNegZ{"-z", {0, 0, -2}, {0, 0, 1}, {0, 1, 0}};
const View kFromPosX{"+x", {2, 0, 0}, {-1, 0, 0}, {0, 1, 0}};
const View kFromNegX{"-x", {-2, 0, 0}, {1, 0, 0}, {0, 1, 0}};
const View kFromPosY{"+y", {0, 2, 0}, {0, -1, 0}, {0, 0, -1}};
const View kFromNegY{"-y", {0, -2, 0}, {0, 1, 0}, {0, 0, 1}};

class TextureMapping : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = make_temp_dir();
        ASSERT_FALSE(dir_.empty());
        texture_ = dir_ + "/quadrants.png";
        ASSERT_TRUE(write_png(texture_, quadrant_picture(64)));
    }

    // One `kind` at the origin under `translate t scale s`, seen from `view`.
    std::string scene(ShapeKind kind, const View& view, double u, double v, glm::dvec3 t = glm::dvec3(0),
                      glm::dvec3 s = glm::dvec3(1), const std::string& material = "") const {
        std::ostringstream o;
        o << "camera [ eye " << fmt(view.eye) << " look " << fmt(view.look) << " up " << fmt(view.up)
          << " angle " << kAngle << " ]\n"
          << "mastersubgraph root [ trans [ translate " << fmt(t) << " scale " << fmt(s) << "\n"
          << "  object " << shape_name(kind) << " [ texture " << texture_ << " " << u << " " << v << " " << material
          << " ] ] ]\n";
        return o.str();
    }

    Rendered render(const std::string& text, RenderMode mode = RenderMode::Raycast) const {
        return render_scene_text(text, dir_ + "/scene.sc", kSize, kSize, mode);
    }

    // Every pixel whose hit lies clearly inside one piece of the shape and whose (s, t) lies
    // clearly inside one quadrant must show that quadrant's colour. Returns how many pixels were
    // checked and which pieces and quadrants they covered.
    struct Coverage {
        int checked = 0;
        std::set<int> pieces;
        std::set<std::tuple<int, int, int>> colours;
    };
    Coverage check_view(ShapeKind kind, const View& view, double U, double V, glm::dvec3 t = glm::dvec3(0),
                        glm::dvec3 s = glm::dvec3(1)) const {
        Coverage cov;
        const Rendered r = render(scene(kind, view, U, V, t, s));
        EXPECT_TRUE(r.load.ok()) << r.messages;
        if (!r.load.ok()) return cov;
        const HandCamera cam(view.eye, view.look, view.up, kAngle, kSize, kSize);
        int failures = 0;
        for (int py = 0; py < kSize; ++py)
            for (int px = 0; px < kSize; ++px) {
                // Into object space: p_object = (p_world − t) / s.
                const glm::dvec3 d = cam.direction(px, py);
                const auto hit = hand_intersect(kind, (view.eye - t) / s, d / s);
                if (!hit || hit->edge < 0.02 || hit->cos_view < 0.2) continue;
                const glm::dvec2 uv = hand_uv(kind, *hit);
                const double ss = frac(uv.x * U), tt = frac(uv.y * V);
                if (quadrant_margin(ss) < kMargin || quadrant_margin(tt) < kMargin) continue;
                const glm::u8vec3 want = quadrant_colour(ss, tt), got = r.image.at(px, py);
                ++cov.checked;
                cov.pieces.insert(int(hit->piece));
                cov.colours.insert({want.x, want.y, want.z});
                const bool same = std::abs(int(got.x) - want.x) <= 1 && std::abs(int(got.y) - want.y) <= 1 &&
                                  std::abs(int(got.z) - want.z) <= 1;
                if (!same && ++failures <= 5)
                    ADD_FAILURE() << shape_name(kind) << " from " << view.name << " repeat " << U << "x" << V
                                  << ": pixel (" << px << ", " << py << ") object point " << fmt(hit->p)
                                  << " piece " << int(hit->piece) << " uv " << uv.x << " " << uv.y << " st " << ss
                                  << " " << tt << ": want " << int(want.x) << " " << int(want.y) << " "
                                  << int(want.z) << ", got " << int(got.x) << " " << int(got.y) << " "
                                  << int(got.z);
            }
        EXPECT_EQ(failures, 0) << shape_name(kind) << " from " << view.name << ": " << failures << " wrong pixels";
        return cov;
    }

    std::string dir_, texture_;
};

::testing::AssertionResult has_colour(const Image& img, int x, int y, glm::u8vec3 want) {
    const glm::u8vec3 got = img.at(x, y);
    if (std::abs(int(got.x) - want.x) <= 1 && std::abs(int(got.y) - want.y) <= 1 && std::abs(int(got.z) - want.z) <= 1)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "pixel (" << x << ", " << y << ") is " << int(got.x) << " " << int(got.y)
                                         << " " << int(got.z) << ", want " << int(want.x) << " " << int(want.y) << " "
                                         << int(want.z);
}

// Worked by hand. Camera at distance 2 with a 40° field of view, 48 × 48 pixels:
// tan 20° = 0.36397. Pixel column 12 has centre x = 12.5, so sx = (2·12.5/48 − 1)·0.36397 = −0.17441;
// row 12 likewise gives sy = +0.17441; column/row 35 give +0.17441 / −0.17441. The face plane is
// 1.5 away along the view, so these rays meet it at in-face offsets ±1.5·0.17441 = ±0.26161.
// On every cube face seen head-on with the views above (image right = the direction in which u
// grows, image up = the direction in which v falls), pixel (12, 12) therefore has
// (u, v) = (0.5 − 0.26161, 0.5 − 0.26161) = (0.2384, 0.2384): top-left quadrant; (35, 12) has
// u = 0.7616: top-right; (12, 35) bottom-left; (35, 35) bottom-right.
// E.g. the front face (+z): p = (−0.26161, 0.26161, 0.5), u = x + 0.5 = 0.2384, v = 0.5 − y = 0.2384.
//      the right face (+x), camera right = (0, 0, −1): p = (0.5, 0.26161, 0.26161), u = 0.5 − z = 0.2384.
//      the top face (+y), camera up = −z: p = (−0.26161, 0.5, −0.26161), u = x + 0.5, v = z + 0.5 = 0.2384.
TEST_F(TextureMapping, EveryCubeFaceShowsTheImageUprightByHand) {
    for (const View& view : {kFromPosZ, kFromNegZ, kFromPosX, kFromNegX, kFromPosY, kFromNegY}) {
        SCOPED_TRACE(std::string("cube seen from ") + view.name);
        const Rendered r = render(scene(ShapeKind::Cube, view, 1, 1));
        ASSERT_TRUE(r.load.ok()) << r.messages;
        EXPECT_TRUE(has_colour(r.image, 12, 12, kTopLeft));
        EXPECT_TRUE(has_colour(r.image, 35, 12, kTopRight));
        EXPECT_TRUE(has_colour(r.image, 12, 35, kBottomLeft));
        EXPECT_TRUE(has_colour(r.image, 35, 35, kBottomRight));
        EXPECT_TRUE(has_colour(r.image, 0, 0, {0, 0, 0}));  // background around the face
    }
}

// Repeats by hand, top face (+y), `texture F 2 3`: pixel (12, 12) has (u, v) = (0.2384, 0.2384),
// so s = frac(2·0.2384) = 0.4768 (left), t = frac(3·0.2384) = 0.7152 (bottom): bottom-left.
// Pixel (6, 6): sx = (13/48 − 1)·0.36397 = −0.26539, offset 1.5·(−0.26539) = −0.39809,
// (u, v) = (0.10191, 0.10191), s = 0.2038, t = 0.3057: top-left.
// Pixel (40, 20): sx = (81/48 − 1)·0.36397 = 0.25023, offset 0.37534, u = x + 0.5 = 0.87534,
// s = frac(1.75069) = 0.75069 (right); sy = (1 − 41/48)·0.36397 = 0.05308, offset 0.07962 toward
// the camera's up, which is −z: z = −0.07962, v = z + 0.5 = 0.42038, t = frac(1.26114) = 0.26114
// (top): top-right.
TEST_F(TextureMapping, CubeTopFaceRepeatedTwoByThreeByHand) {
    const Rendered r = render(scene(ShapeKind::Cube, kFromPosY, 2, 3));
    ASSERT_TRUE(r.load.ok()) << r.messages;
    EXPECT_TRUE(has_colour(r.image, 12, 12, kBottomLeft));
    EXPECT_TRUE(has_colour(r.image, 6, 6, kTopLeft));
    EXPECT_TRUE(has_colour(r.image, 40, 20, kTopRight));
}

TEST_F(TextureMapping, CubeEveryFace) {
    for (const View& view : {kFromPosZ, kFromNegZ, kFromPosX, kFromNegX, kFromPosY, kFromNegY})
        for (auto [U, V] : {std::pair{1.0, 1.0}, std::pair{2.0, 3.0}}) {
            Coverage c = check_view(ShapeKind::Cube, view, U, V);
            EXPECT_GT(c.checked, 400) << view.name;
            EXPECT_EQ(c.pieces.size(), 1u) << view.name;  // head-on: one face only
            EXPECT_EQ(c.colours.size(), 4u) << view.name;
        }
}

// (u, v) come from the object-space hit point: moving and stretching the cube changes nothing
// on the texture's own terms. Also seen from a corner, three faces at once.
TEST_F(TextureMapping, CubeUnderATransformAndFromACorner) {
    Coverage c = check_view(ShapeKind::Cube, kFromPosZ, 2, 3, {0.1, -0.05, 0}, {1.2, 0.9, 0.7});
    EXPECT_GT(c.checked, 300);
    const View corner{"corner", {1.6, 1.3, 1.9}, {-1.6, -1.3, -1.9}, {0, 1, 0}};
    c = check_view(ShapeKind::Cube, corner, 2, 3);
    EXPECT_EQ(c.pieces.size(), 3u);
    EXPECT_EQ(c.colours.size(), 4u);
    EXPECT_GT(c.checked, 200);
}

// Sphere seen from +x: the meridian facing the camera (φ = 0) is u = 0.5, so the image is
// upright around the middle. By hand, pixel (12, 12): ray (−1, 0.17441, 0.17441) from (2, 0, 0)
// meets the sphere at t = 1.74588 (unnormalised), p = (0.25412, 0.30449, 0.30449);
// φ = atan2(0.30449, 0.25412) = 0.87532 → u = 0.5 − φ/2π = 0.36069; v = 0.5 − asin(0.60897)/π = 0.29158:
// top-left; with 2×3: s = 0.72138, t = 0.87475: bottom-right.
TEST_F(TextureMapping, SphereByHand) {
    Rendered r = render(scene(ShapeKind::Sphere, kFromPosX, 1, 1));
    ASSERT_TRUE(r.load.ok()) << r.messages;
    EXPECT_TRUE(has_colour(r.image, 12, 12, kTopLeft));
    EXPECT_TRUE(has_colour(r.image, 35, 12, kTopRight));
    EXPECT_TRUE(has_colour(r.image, 12, 35, kBottomLeft));
    EXPECT_TRUE(has_colour(r.image, 35, 35, kBottomRight));
    r = render(scene(ShapeKind::Sphere, kFromPosX, 2, 3));
    ASSERT_TRUE(r.load.ok()) << r.messages;
    EXPECT_TRUE(has_colour(r.image, 12, 12, kBottomRight));
}

TEST_F(TextureMapping, Sphere) {
    for (const View& view : {kFromPosX, kFromPosZ, kFromNegZ, kFromPosY, kFromNegY})
        for (auto [U, V] : {std::pair{1.0, 1.0}, std::pair{2.0, 3.0}}) {
            Coverage c = check_view(ShapeKind::Sphere, view, U, V);
            EXPECT_GT(c.checked, 250) << view.name;
        }
}

// Seen from −x the camera looks at the seam (φ = ±π, u = 0 = 1): left of the middle column
// u is just below 1 (right-hand quadrants), right of it just above 0 (left-hand quadrants), and no
// pixel of the ball is left unpainted along the seam.
TEST_F(TextureMapping, SphereSeam) {
    Coverage c = check_view(ShapeKind::Sphere, kFromNegX, 1, 1);
    EXPECT_EQ(c.colours.size(), 4u);
    const Rendered r = render(scene(ShapeKind::Sphere, kFromNegX, 1, 1));
    ASSERT_TRUE(r.load.ok());
    EXPECT_TRUE(has_colour(r.image, 20, 16, kTopRight));
    EXPECT_TRUE(has_colour(r.image, 27, 16, kTopLeft));
    for (int y = 10; y < 38; ++y)
        for (int x = 22; x < 26; ++x) EXPECT_NE(r.image.at(x, y), glm::u8vec3(0)) << x << " " << y;
}

// Cylinder side from +x: u = 0.5 − φ/2π, v = 0.5 − y, upright around φ = 0.
// Caps from above and below: top u = x + 0.5, v = z + 0.5; bottom u = x + 0.5, v = 0.5 − z; both
// upright from outside, so by hand the cap pixels (12, 12) etc. are as for the cube faces (the
// cap plane is 1.5 from the camera too; radius 0.37 < 0.5).
TEST_F(TextureMapping, CylinderSideAndCaps) {
    for (auto [U, V] : {std::pair{1.0, 1.0}, std::pair{2.0, 3.0}}) {
        Coverage side = check_view(ShapeKind::Cylinder, kFromPosX, U, V);
        EXPECT_GT(side.checked, 400);
        EXPECT_EQ(side.pieces, std::set<int>{int(Piece::Side)});
        EXPECT_EQ(side.colours.size(), 4u);
        Coverage top = check_view(ShapeKind::Cylinder, kFromPosY, U, V);
        EXPECT_GT(top.checked, 300);
        EXPECT_EQ(top.pieces, std::set<int>{int(Piece::TopCap)});
        EXPECT_EQ(top.colours.size(), 4u);
        Coverage bottom = check_view(ShapeKind::Cylinder, kFromNegY, U, V);
        EXPECT_GT(bottom.checked, 300);
        EXPECT_EQ(bottom.pieces, std::set<int>{int(Piece::BottomCap)});
    }
    for (const View& view : {kFromPosY, kFromNegY}) {
        const Rendered r = render(scene(ShapeKind::Cylinder, view, 1, 1));
        ASSERT_TRUE(r.load.ok()) << r.messages;
        SCOPED_TRACE(view.name);
        EXPECT_TRUE(has_colour(r.image, 12, 12, kTopLeft));
        EXPECT_TRUE(has_colour(r.image, 35, 12, kTopRight));
        EXPECT_TRUE(has_colour(r.image, 12, 35, kBottomLeft));
        EXPECT_TRUE(has_colour(r.image, 35, 35, kBottomRight));
    }
    // Seen slanting from above: side and top cap in one picture.
    const View slant{"slant", {1.5, 1.4, 1.0}, {-1.5, -1.4, -1.0}, {0, 1, 0}};
    Coverage both = check_view(ShapeKind::Cylinder, slant, 2, 3);
    EXPECT_EQ(both.pieces.size(), 2u);
}

// Cone side from +x (v = 0.5 − y: the apex row is v = 0), and the base from below.
TEST_F(TextureMapping, ConeSideAndBase) {
    for (auto [U, V] : {std::pair{1.0, 1.0}, std::pair{2.0, 3.0}}) {
        Coverage side = check_view(ShapeKind::Cone, kFromPosX, U, V);
        EXPECT_GT(side.checked, 200);
        EXPECT_EQ(side.pieces, std::set<int>{int(Piece::Side)});
        EXPECT_EQ(side.colours.size(), 4u);
        Coverage base = check_view(ShapeKind::Cone, kFromNegY, U, V);
        EXPECT_GT(base.checked, 300);
        EXPECT_EQ(base.pieces, std::set<int>{int(Piece::BottomCap)});
        EXPECT_EQ(base.colours.size(), 4u);
        Coverage top = check_view(ShapeKind::Cone, kFromPosY, U, V);  // the side, from above
        EXPECT_GT(top.checked, 100);
    }
    const Rendered r = render(scene(ShapeKind::Cone, kFromNegY, 1, 1));
    ASSERT_TRUE(r.load.ok()) << r.messages;
    EXPECT_TRUE(has_colour(r.image, 12, 12, kTopLeft));
    EXPECT_TRUE(has_colour(r.image, 35, 35, kBottomRight));
}

// The texel multiplies `diffuse` (raycast shows diffuse × texel) and `ambient` (with no light,
// the whitted image is ambient × I_a × texel), and nothing else: emit is added as is.
TEST_F(TextureMapping, TexelMultipliesDiffuseAndAmbient) {
    Rendered r = render(scene(ShapeKind::Cube, kFromPosZ, 1, 1, glm::dvec3(0), glm::dvec3(1), "diffuse 0.5 1 0.25"));
    ASSERT_TRUE(r.load.ok()) << r.messages;
    auto scaled = [](glm::u8vec3 c, glm::dvec3 k) {
        return glm::u8vec3(std::floor(c.x / 255.0 * k.x * 255 + 0.5), std::floor(c.y / 255.0 * k.y * 255 + 0.5),
                           std::floor(c.z / 255.0 * k.z * 255 + 0.5));
    };
    EXPECT_TRUE(has_colour(r.image, 12, 12, scaled(kTopLeft, {0.5, 1, 0.25})));
    EXPECT_TRUE(has_colour(r.image, 35, 35, scaled(kBottomRight, {0.5, 1, 0.25})));

    r = render(scene(ShapeKind::Cube, kFromPosZ, 1, 1, glm::dvec3(0), glm::dvec3(1),
                     "diffuse 0 0 0 ambient 1 0.5 1 emit 0 0.1 0"),
               RenderMode::Whitted);
    ASSERT_TRUE(r.load.ok()) << r.messages;
    auto expected = [&](glm::u8vec3 c) {
        glm::u8vec3 a = scaled(c, {1, 0.5, 1});
        return glm::u8vec3(a.x, std::floor((c.y / 255.0 * 0.5 + 0.1) * 255 + 0.5), a.z);
    };
    EXPECT_TRUE(has_colour(r.image, 12, 12, expected(kTopLeft)));
    EXPECT_TRUE(has_colour(r.image, 35, 12, expected(kTopRight)));
    EXPECT_TRUE(has_colour(r.image, 12, 35, expected(kBottomLeft)));
}

}  // namespace
}  // namespace whitted

// --texture-filter: the texel `nearest` picks, the mip level trilinear reads on a plane seen at a
// known distance and angle (closed form), ray differentials through a flat mirror and a flat
// glass surface (closed form), the mip-maps' memory, bilinear as it was, and the aliasing of a
// checkerboard floor receding to the horizon at one sample per pixel.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "base/read_file.h"
#include "flatten/flatten.h"
#include "film/image.h"
#include "integrator/surface.h"
#include "integrator/texture_footprint.h"
#include "render/load_scene.h"
#include "render/renderer.h"
#include "session/render_settings.h"
#include "texture/texture_filter.h"
#include "texture/texture_sample.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

using namespace whitted::test;

TextureImage image_of(const Picture& p) {
    TextureImage t;
    t.width = p.width;
    t.height = p.height;
    t.rgb = p.rgb;
    return t;
}

glm::vec3 colour(glm::u8vec3 c) { return glm::vec3(c) / 255.0f; }

// The texel whose square [c, c+1) × [r, r+1) (in texels) holds the point, by hand.
TEST(TextureFilter, NearestPicksTheTexelHoldingThePoint) {
    const Picture p = distinct_picture(4, 2);  // every texel differs
    const TextureImage img = image_of(p);
    // u·4 = 1.2 → column 1, v·2 = 1.6 → row 1.
    EXPECT_EQ(sample_texture_nearest(img, {0.30f, 0.80f}, 1, 1), colour(p.at(1, 1)));
    // A square's left edge belongs to it: u·4 = 1 exactly is column 1; just below is column 0.
    EXPECT_EQ(sample_texture_nearest(img, {0.25f, 0.25f}, 1, 1), colour(p.at(1, 0)));
    EXPECT_EQ(sample_texture_nearest(img, {0.2499f, 0.25f}, 1, 1), colour(p.at(0, 0)));
    // Repeated 3 × 2: s = frac(0.45·3) = 0.35 → column 1 (1.4); t = frac(0.9·2) = 0.8 → row 1.
    EXPECT_EQ(sample_texture_nearest(img, {0.45f, 0.90f}, 3, 2), colour(p.at(1, 1)));
    // The last texel up to the edge (no wrap to the first, unlike bilinear's blend there).
    EXPECT_EQ(sample_texture_nearest(img, {0.999f, 0.999f}, 1, 1), colour(p.at(3, 1)));
    // Unlike bilinear, no blend at a texel's corner: bilinear at (0.25, 0.5) is the mean of four.
    EXPECT_NE(sample_texture(img, {0.25f, 0.5f}, 1, 1), sample_texture_nearest(img, {0.25f, 0.5f}, 1, 1));
}

// Each level halves the one above (odd sizes rounded up), down to 1 × 1, a texel the mean of 2 × 2.
TEST(TextureFilter, MipLevelsAreBoxFilteredHalves) {
    Picture p(4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) p.set(x, y, {std::uint8_t(40 * x), std::uint8_t(100 * y), 200});
    const std::vector<TextureImage> levels = build_mip_levels(image_of(p));
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(levels[0].width, 2);
    EXPECT_EQ(levels[0].height, 1);
    EXPECT_EQ(levels[1].width, 1);
    EXPECT_EQ(levels[1].height, 1);
    // Columns 0-1: red (0 + 40) / 2 = 20, green (0 + 100) / 2 = 50; columns 2-3: red 100.
    EXPECT_EQ(levels[0].texel(0), glm::vec3(20, 50, 200) / 255.0f);
    EXPECT_EQ(levels[0].texel(1), glm::vec3(100, 50, 200) / 255.0f);
    EXPECT_EQ(levels[1].texel(0), glm::vec3(60, 50, 200) / 255.0f);
    EXPECT_EQ(mip_levels_bytes(4, 2), 3u * (2 + 1));
    EXPECT_EQ(mip_levels_bytes(5, 3), 3u * (3 * 2 + 2 * 1 + 1));
}

// A camera's auxiliary rays are its rays of the next pixel to the right and the next one down,
// from the same lens point: for a pinhole from the eye, for a thin lens through the point where
// the neighbouring pixel's ray crosses the plane in focus.
TEST(TextureFilter, CameraDifferentialsAreTheNeighbouringPixelsRays) {
    Camera cam;
    cam.eye = {1, 2, 3};
    cam.forward = glm::normalize(glm::vec3(-0.3f, -0.2f, -1));
    cam.right = glm::normalize(glm::cross(cam.forward, glm::vec3(0, 1, 0)));
    cam.up = glm::cross(cam.right, cam.forward);
    cam.tan_half_fov = 0.4f;
    constexpr int kW = 320, kH = 200;
    const float pitch = 2 * cam.tan_half_fov / kH;
    for (float radius : {0.0f, 0.25f}) {
        cam.lens_radius = radius;
        cam.focal_distance = 4.0f;
        for (glm::vec2 lens : {glm::vec2(0.5f), glm::vec2(0.1f, 0.8f), glm::vec2(0.93f, 0.35f)}) {
            SCOPED_TRACE("lens radius " + std::to_string(radius) + " at " + std::to_string(lens.x));
            const float x = 41.3f, y = 150.6f;
            const RayDifferential d = cam.differential(cam.generate_ray(kW, kH, x, y, lens), pitch);
            const Ray right = cam.generate_ray(kW, kH, x + 1, y, lens), down = cam.generate_ray(kW, kH, x, y + 1, lens);
            EXPECT_NEAR(glm::length(d.x.origin - right.origin), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::length(d.y.origin - down.origin), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::length(d.x.direction - right.direction), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::length(d.y.direction - down.direction), 0.0f, 1e-5f);
        }
    }
}

// A camera at height h above the floor y = 0, looking down at β below the horizon: the centre
// ray meets the floor at distance D = h / sin β. One pixel to the right moves the hit by
// D·pitch along x (pitch = 2 tan(fov/2) / rows, the pixel's size on the plane at distance 1);
// one pixel down moves it by D·pitch / (sin β + pitch·cos β) along z, toward the camera (the
// auxiliary ray meets the floor at h / (sin β + pitch cos β) along forward − pitch·up). The
// floor is a cube's top face scaled S, u = x/S + 0.5, v = z/S + 0.5, its texture W texels
// across repeated R times: trilinear reads level log2 of the longer step in texels.
TEST(TextureFilter, TrilinearLevelOnAPlaneIsTheClosedForm) {
    constexpr int kTexels = 256, kRows = 480;
    constexpr double kScale = 20, kRepeat = 64, kFov = 45;
    const std::string scene =
        "camera [ eye 0 2 0 ]\n"
        "mastersubgraph root [ trans [ translate 0 -0.5 0 scale 20 1 20 object cube [ texture T 64 64 ] ] ]\n";
    Picture gray(kTexels, kTexels);
    const std::string dir = make_temp_dir();
    ASSERT_TRUE(write_png(dir + "/t.png", gray));
    std::string text = scene;
    text.replace(text.find(" T "), 3, " t.png ");
    const LoadResult load = load_scene_text(text, dir + "/floor.sc");
    ASSERT_TRUE(load.ok());
    const Scene& sc = *load.scene;
    const TextureImage& img = sc.data.textures.at(0);
    const std::vector<TextureImage> levels = build_mip_levels(img);
    ASSERT_EQ(levels.size(), 8u);
    for (double h : {2.0, 3.5}) {
        for (double beta_deg : {30.0, 55.0, 80.0}) {
            SCOPED_TRACE("h " + std::to_string(h) + ", beta " + std::to_string(beta_deg));
            const double beta = beta_deg * std::numbers::pi / 180, tan_half = std::tan(kFov * std::numbers::pi / 360);
            const double pitch = 2 * tan_half / kRows, D = h / std::sin(beta);
            Camera cam;
            cam.eye = {0, float(h), 0};
            cam.forward = glm::vec3(0, -std::sin(beta), -std::cos(beta));
            cam.up = glm::vec3(0, std::cos(beta), -std::sin(beta));
            cam.right = {1, 0, 0};
            cam.tan_half_fov = float(tan_half);
            const Ray ray{cam.eye, cam.forward};  // the image's centre
            Hit hit;
            ASSERT_TRUE(sc.intersect(ray, hit));
            const Surface s = surface_at(sc, ray, hit);
            SurfaceDifferentials d;
            ASSERT_TRUE(surface_differentials(sc, hit, s, cam.differential(ray, float(pitch)), d));
            const double du_dx = D * pitch / kScale, dv_dy = D * pitch / (std::sin(beta) + pitch * std::cos(beta)) / kScale;
            EXPECT_NEAR(d.uv.dx.x, du_dx, 1e-4 * du_dx);
            EXPECT_NEAR(d.uv.dx.y, 0.0, 1e-6);
            EXPECT_NEAR(d.uv.dy.x, 0.0, 1e-6);
            EXPECT_NEAR(d.uv.dy.y, dv_dy, 1e-3 * dv_dy);  // (+: v = z/S + 0.5 grows toward the camera)
            const double longer = std::max(du_dx, dv_dy) * kTexels * kRepeat;
            const double level = std::clamp(std::log2(longer), 0.0, 8.0);
            EXPECT_NEAR(trilinear_level(img, int(levels.size()), d.uv, float(kRepeat), float(kRepeat)), level, 2e-3);
        }
    }
}

// A flat mirror: the auxiliary rays leaving it are those of the mirrored camera (eye and
// directions reflected in the plane), continued from where the incoming ones meet the mirror.
TEST(TextureFilter, DifferentialsThroughAFlatMirrorAreTheMirroredCamera) {
    const std::string dir = make_temp_dir();
    const LoadResult load = load_scene_text(
        "camera [ eye 0 2 0 ]\nmastersubgraph root [ trans [ translate 0 -0.5 0 scale 50 1 50 object cube [ "
        "reflect 1 1 1 ] ] ]\n",
        dir + "/mirror.sc");
    ASSERT_TRUE(load.ok());
    const Scene& sc = *load.scene;
    Camera cam;
    cam.eye = {0.3f, 2.0f, 0.1f};
    cam.forward = glm::normalize(glm::vec3(0.2f, -0.6f, -1.0f));
    cam.right = glm::normalize(glm::cross(cam.forward, glm::vec3(0, 1, 0)));
    cam.up = glm::cross(cam.right, cam.forward);
    const float pitch = 2 * cam.tan_half_fov / 120;
    auto mirror = [](glm::dvec3 v) { return glm::dvec3(v.x, -v.y, v.z); };  // in the plane y = 0
    for (glm::vec2 px : {glm::vec2(80.5f, 100.5f), glm::vec2(10.5f, 119.5f), glm::vec2(150.5f, 70.5f)}) {
        const Ray ray = cam.pinhole_ray(160, 120, px.x, px.y);
        const RayDifferential rd = cam.differential(ray, pitch);
        Hit hit;
        ASSERT_TRUE(sc.intersect(ray, hit));
        const Surface s = surface_at(sc, ray, hit);
        SurfaceDifferentials d;
        ASSERT_TRUE(surface_differentials(sc, hit, s, rd, d));
        const RayDifferential out = reflected_differential(s.point, s.normal, 1.0f, rd, d);
        const glm::dvec3 eye2 = mirror(glm::dvec3(cam.eye));
        for (const auto& [in, got] : {std::pair{rd.x, out.x}, std::pair{rd.y, out.y}}) {
            // The mirrored camera's ray: from eye2 along the mirrored direction ...
            const glm::dvec3 dir2 = mirror(glm::normalize(glm::dvec3(in.direction)));
            EXPECT_NEAR(glm::length(glm::dvec3(got.direction) - dir2), 0.0, 1e-5);
            // ... starting where the incoming auxiliary ray meets y = 0 (on the mirrored ray's line).
            const glm::dvec3 o(in.origin), dd(in.direction);
            const glm::dvec3 meet = o + (-o.y / dd.y) * dd;
            EXPECT_NEAR(glm::length(glm::dvec3(got.origin) - meet), 0.0, 1e-4);
            EXPECT_NEAR(glm::length(glm::cross(meet - eye2, dir2)), 0.0, 1e-4);
        }
    }
}

// A flat glass surface: each auxiliary ray bends by Snell's law on its own (the tangential part
// of a unit direction scaled by eta, the normal part what keeps it unit length).
TEST(TextureFilter, DifferentialsThroughFlatGlassFollowSnell) {
    const glm::vec3 n(0, 1, 0), p(0.5f, 0, -2);
    RayDifferential in{Ray{{0, 1, 0}, glm::normalize(glm::vec3(0.5f, -1, -2))},
                       Ray{{0, 1, 0}, glm::normalize(glm::vec3(0.5f, -1.1f, -1.7f))}};
    SurfaceDifferentials d;
    d.dpdx = glm::vec3(0.01f, 0, 0);
    d.dpdy = glm::vec3(0, 0, 0.02f);
    d.dndx = d.dndy = glm::vec3(0.0f);
    d.uv = {};
    const float eta = 1.0f / 1.5f;
    RayDifferential out;
    ASSERT_TRUE(refracted_differential(p, n, 1.0f, eta, in, d, out));
    for (const auto& [a, b] : {std::pair{in.x, out.x}, std::pair{in.y, out.y}}) {
        const glm::dvec3 dir = glm::normalize(glm::dvec3(a.direction));
        const glm::dvec3 tangential = double(eta) * glm::dvec3(dir.x, 0, dir.z);
        const glm::dvec3 expect = tangential - glm::dvec3(0, std::sqrt(1 - glm::dot(tangential, tangential)), 0);
        EXPECT_NEAR(glm::length(glm::dvec3(b.direction) - expect), 0.0, 1e-6);
    }
    EXPECT_EQ(out.x.origin, p + d.dpdx);
    EXPECT_EQ(out.y.origin, p + d.dpdy);
    // From inside at a grazing angle (past the critical angle), one is totally reflected: none.
    RayDifferential grazing{Ray{{0, -1, 0}, glm::normalize(glm::vec3(3, 1, 0))}, in.y};
    EXPECT_FALSE(refracted_differential(p, -n, -1.0f, 1.5f, grazing, d, out));
}

// The pyramid counts against the memory a scene may take, and only when a filter reads it.
TEST(TextureFilter, MipMapsCountAgainstTheMemoryLimit) {
    const std::string dir = make_temp_dir();
    ASSERT_TRUE(write_png(dir + "/t.png", Picture(256, 256)));
    const std::string text = "camera [ eye 0 0 3 ]\nmastersubgraph root [ trans [ object cube [ texture t.png 1 1 ] ] ]\n";
    constexpr std::size_t kTexture = 256 * 256 * 3;
    RenderSettings s;
    // One object's estimate (flatten.h's 128 bytes) and the texture fit; its pyramid (a third
    // more) does not.
    for (const char* filter : {"bilinear", "nearest", "trilinear", "ewa"}) {
        SCOPED_TRACE(filter);
        s.texture_filter = filter;
        LoadOptions lo = make_load_options(s);
        lo.max_memory = kBytesPerInstance + kTexture + kTexture / 6;
        const LoadResult r = load_scene_text(text, dir + "/s.sc", lo);
        const bool pyramid = uses_footprint(*parse_texture_filter(filter));
        std::string messages;
        for (const auto& d : r.diagnostics) messages += d.str() + "\n";
        ASSERT_EQ(r.ok(), !pyramid) << messages;
        if (pyramid) {
            ASSERT_FALSE(r.diagnostics.empty());
            EXPECT_NE(r.diagnostics[0].message.find("mip-map"), std::string::npos) << r.diagnostics[0].message;
        } else {
            EXPECT_TRUE(r.scene->data.texture_levels.empty());  // none made
        }
    }
    s.texture_filter = "trilinear";
    LoadOptions lo = make_load_options(s);
    lo.max_memory = std::size_t(64) << 20;
    const LoadResult r = load_scene_text(text, dir + "/s.sc", lo);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.scene->data.texture_levels.size(), 1u);
    EXPECT_EQ(r.scene->data.texture_levels[0].size(), 8u);  // 128, 64, ..., 1
}

// --- rendered ------------------------------------------------------------------------------

Image render_with(const std::string& text, const std::string& path, RenderSettings s, std::string& messages) {
    s.threads = 2;
    const std::string problem = validate(s);
    if (!problem.empty()) return messages = problem, Image();
    const LoadResult load = load_scene_text(text, path, make_load_options(s));
    for (const auto& d : load.diagnostics) messages += d.str() + "\n";
    if (!load.ok()) return Image();
    Image image(s.width, s.height);
    render(*load.scene, make_render_job(s), image);
    return image;
}

// The bundled textured scene (every shape, repeats, blend-free tinting) with the default filter
// and with `--texture-filter bilinear` given: the same bytes, and no pyramid is built for either.
TEST(TextureFilter, BilinearIsTheDefaultAndBuildsNoMipMaps) {
    const std::string path = std::string(WHITTED_SOURCE_DIR) + "/scenes/textures.sc";
    const std::string text = read_regular_file(path, std::size_t(1) << 20).bytes;
    ASSERT_FALSE(text.empty());
    RenderSettings def;
    def.width = 160;
    def.height = 120;
    std::string m1, m2;
    const Image a = render_with(text, path, def, m1);
    RenderSettings given = def;
    given.texture_filter = "bilinear";
    given.given.insert("texture-filter");
    const Image b = render_with(text, path, given, m2);
    ASSERT_EQ(a.width, 160) << m1;
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_FALSE(make_load_options(def).textures.limits.mip_levels);
    // And the other filters do change the picture (the floor recedes to the horizon).
    for (const char* f : {"nearest", "trilinear", "ewa"}) {
        RenderSettings other = def;
        other.texture_filter = f;
        std::string m;
        const Image c = render_with(text, path, other, m);
        ASSERT_EQ(c.width, 160) << m;
        EXPECT_NE(c.rgb, a.rgb) << f;
    }
    // Only whitted mode filters; path mode refuses with a reason.
    RenderSettings path_mode = def;
    path_mode.mode = "path";
    path_mode.texture_filter = "ewa";
    EXPECT_NE(validate(path_mode).find("path mode"), std::string::npos);
}

double rms_error(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        const double d = double(a.rgb[i]) - double(b.rgb[i]);
        sum += d * d;
    }
    return std::sqrt(sum / double(a.rgb.size()));
}

// A black-and-white checkerboard floor, 8 texels a square, to the horizon: at one sample per
// pixel, bilinear look-ups alias where many squares fall in one pixel; trilinear and EWA average
// what the pixel covers, as 256 samples a pixel do. Measured (160 × 100, the floor 800 units
// deep): RMS error against the 256-sample bilinear reference, in 8-bit levels: bilinear 1 spp
// 39.6, trilinear 12.9 (3.1× lower), EWA 5.6 (7.1× lower; trilinear blurs the grazing floor toward
// grey, which the reference does not). Asserted: trilinear at least 2× lower, EWA at least 4×:
// margins of about a third and a half of the measured factors, for another compiler's rounding
// (the renders are deterministic).
TEST(TextureFilter, FilteredFloorAtOneSampleIsCloserToTheReference) {
    const std::string dir = make_temp_dir();
    Picture checker(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const std::uint8_t c = ((x / 8) + (y / 8)) % 2 ? 255 : 0;
            checker.set(x, y, {c, c, c});
        }
    ASSERT_TRUE(write_png(dir + "/checker.png", checker));
    const std::string text =
        "camera [ eye 0 1 0  focus 0 0.8 -10  up 0 1 0  angle 40 ]\n"
        "background [ color 0.5 0.5 0.5 ]\n"
        "light [ ambient 1 1 1 ]\n"
        "mastersubgraph root [ trans [ translate 0 -0.5 -400 scale 800 1 800\n"
        "  object cube [ texture checker.png 400 400  ambient 1 1 1  diffuse 0 0 0 ] ] ]\n";
    RenderSettings s;
    s.width = 160;
    s.height = 100;
    std::string m;
    RenderSettings ref = s;
    ref.spp = 256;
    const Image reference = render_with(text, dir + "/floor.sc", ref, m);
    ASSERT_EQ(reference.width, 160) << m;
    const Image bilinear = render_with(text, dir + "/floor.sc", s, m);
    s.texture_filter = "trilinear";
    const Image trilinear = render_with(text, dir + "/floor.sc", s, m);
    s.texture_filter = "ewa";
    const Image ewa = render_with(text, dir + "/floor.sc", s, m);
    ASSERT_EQ(ewa.width, 160) << m;
    const double e_bilinear = rms_error(bilinear, reference), e_trilinear = rms_error(trilinear, reference),
                 e_ewa = rms_error(ewa, reference);
    RecordProperty("rms_bilinear", std::to_string(e_bilinear));
    RecordProperty("rms_trilinear", std::to_string(e_trilinear));
    RecordProperty("rms_ewa", std::to_string(e_ewa));
    std::printf("RMS error vs 256 spp: bilinear %.2f, trilinear %.2f, ewa %.2f\n", e_bilinear, e_trilinear, e_ewa);
    EXPECT_LT(e_trilinear * 2.0, e_bilinear);
    EXPECT_LT(e_ewa * 4.0, e_bilinear);
}

}  // namespace
}  // namespace whitted

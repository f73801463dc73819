// The image-space driver: pixel-centre rays, packets that change no pixel, thread independence,
// cancellation.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "render/load_scene.h"
#include "integrator/whitted_integrator.h"
#include "render/renderer.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

TEST(CameraRay, GoesThroughPixelCentresWithVerticalFov) {
    Camera cam;  // eye (0,0,1) looking down −z, tan(30°)
    cam.tan_half_fov = 1.0f;  // 90° vertical
    // 4×2 image (aspect 2): pixel (0,0)'s centre is at x = 0.5/4·2−1 = −0.75 of the half width
    // (half width = aspect · tan = 2), y = 1 − 0.5 = 0.5 of the half height.
    Ray r = cam.generate_ray(4, 2, 0.5f, 0.5f, glm::vec2(0.5f));
    glm::vec3 want = glm::normalize(glm::vec3(-0.75f * 2.0f, 0.5f, -1.0f));
    EXPECT_NEAR(r.direction.x, want.x, 1e-6f);
    EXPECT_NEAR(r.direction.y, want.y, 1e-6f);
    EXPECT_NEAR(r.direction.z, want.z, 1e-6f);
}

Scene busy_scene() {
    test::SceneBuilder b;
    Material m;
    m.reflect = glm::vec3(0.5f);
    m.specular = glm::vec3(0.5f);
    m.shine = 20;
    for (int i = 0; i < 60; ++i) {
        float x = float(i % 10) - 4.5f, y = float(i / 10) - 2.5f;
        b.add(ShapeKind(i % 4), test::translate_scale({x, y, -5.0f - 0.5f * float(i % 3)}, glm::vec3(0.9f)), m);
    }
    b.light(test::point_light({2, 5, 5}, {1, 1, 1}));
    return b.build();
}

TEST(Renderer, ImageIsByteIdenticalForAnyThreadCount) {
    Scene scene = busy_scene();
    RenderJob o;
    o.width = 97;  // not a multiple of the tile size
    o.height = 61;
    o.tile_size = 16;
    Image one(o.width, o.height), two(o.width, o.height), five(o.width, o.height);
    o.threads = 1;
    render(scene, o, one);
    o.threads = 2;
    render(scene, o, two);
    o.threads = 5;
    render(scene, o, five);
    EXPECT_EQ(one.rgb, two.rgb);
    EXPECT_EQ(one.rgb, five.rgb);
    size_t lit = 0;
    for (auto v : one.rgb) lit += v != 0;
    EXPECT_GT(lit, one.rgb.size() / 4) << "the test scene should fill much of the image";
}

// The image as it was made before camera rays were traced in packets: pixel by pixel, each
// camera ray traced on its own (WhittedIntegrator::radiance(ray, …) finds its hit itself).
Image one_ray_at_a_time(const Scene& scene, const RenderJob& o, RayCounts& counts) {
    const auto integrator = make_integrator(scene, scene.data.camera, o.integrator);
    const Sampler sampler;
    Image image(o.width, o.height);
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const Ray ray = scene.data.camera.generate_ray(o.width, o.height, x + 0.5f, y + 0.5f, glm::vec2(0.5f));
            const SampleKey key{std::uint32_t(x), std::uint32_t(y), 0};
            glm::vec3 c;
            if (o.integrator.mode == RenderMode::Whitted) {
                c = static_cast<const WhittedIntegrator&>(*integrator).radiance(ray, key, sampler, counts);
            } else {  // the debug views: a batch of one lane
                CameraBatch one;
                one.rays[0] = ray;
                one.keys[0] = key;
                one.active = 1;
                glm::vec3 out[kPacketSize];
                integrator->radiance(one, sampler, out, counts);
                c = out[0];
            }
            std::uint8_t* p = &image.rgb[(std::size_t(y) * o.width + x) * 3];
            p[0] = to_byte(c.x);
            p[1] = to_byte(c.y);
            p[2] = to_byte(c.z);
        }
    return image;
}

// render() finds the camera rays' hits a packet at a time: every byte and every ray count must be
// what tracing them one at a time gives, in every mode, for image and tile sizes that cut packets
// (kPacketWidth × kPacketHeight pixels) at the tiles' and the image's edges.
void expect_packets_change_nothing(const Scene& scene, const char* name) {
    struct Size { int w, h, tile; };
    const Size sizes[] = {{97, 61, 16}, {64, 48, 32}, {33, 17, 5}, {10, 7, 1}, {160, 120, 32}};
    for (RenderMode mode : {RenderMode::Whitted, RenderMode::Raycast, RenderMode::Normals, RenderMode::Depth})
        for (const Size& size : sizes) {
            SCOPED_TRACE(std::string(name) + " " + render_mode_name(mode) + " " + std::to_string(size.w) + "x" +
                         std::to_string(size.h) + " tile " + std::to_string(size.tile));
            RenderJob o;
            o.width = size.w;
            o.height = size.h;
            o.tile_size = size.tile;
            o.integrator.mode = mode;
            o.threads = 2;
            RayCounts want_counts;
            const Image want = one_ray_at_a_time(scene, o, want_counts);
            Image got(o.width, o.height);
            const RenderStats stats = render(scene, o, got);
            ASSERT_EQ(got.rgb, want.rgb);
            EXPECT_EQ(stats.rays.camera, std::uint64_t(o.width) * o.height);
            EXPECT_EQ(stats.rays.camera, want_counts.camera);
            EXPECT_EQ(stats.rays.reflected, want_counts.reflected);
            EXPECT_EQ(stats.rays.refracted, want_counts.refracted);
            EXPECT_EQ(stats.rays.shadow, want_counts.shadow);
        }
}

TEST(Renderer, PacketTracedCameraRaysChangeNoPixel) {
    expect_packets_change_nothing(busy_scene(), "busy");
    // The bundled showcase: every shape, light type, mirror, glass, instancing.
    LoadResult showcase = load_scene(std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc");
    ASSERT_TRUE(showcase.ok());
    expect_packets_change_nothing(*showcase.scene, "showcase");
    // More lights than a packet's shadow rays are traced for (the rest one by one), glass casting
    // tinted shadows in between opaque shapes, and a light inside the cluster.
    test::SceneBuilder b;
    Material glass, matte;
    glass.diffuse = glm::vec3(0.1f);
    glass.transparent = glm::vec3(0.7f, 0.8f, 0.9f);
    glass.ior = 1.4f;
    matte.specular = glm::vec3(0.3f);
    matte.shine = 12;
    for (int i = 0; i < 40; ++i) {
        const float x = float(i % 8) - 3.5f, y = float(i / 8) - 2.0f;
        b.add(ShapeKind(i % 4), test::translate_scale({x, y, -6.0f - float(i % 3)}, glm::vec3(0.8f)), i % 3 ? matte : glass);
    }
    for (int i = 0; i < 11; ++i)
        b.light(test::point_light({float(i % 4) * 2 - 3, float(i % 3) * 2 - 2, i == 10 ? -7.0f : 3.0f},
                                  glm::vec3(0.15f), {1, 0.05f, 0}));
    expect_packets_change_nothing(b.build(), "eleven lights and glass");
}

TEST(Renderer, CancelStopsAfterTheCurrentRowsAndLeavesTheRestBlack) {
    Scene scene = busy_scene();
    std::atomic<bool> cancel{false};
    std::atomic<int> tiles{0};
    RenderJob o;
    o.width = 256;
    o.height = 256;
    o.threads = 2;
    o.cancel = &cancel;
    o.on_tile = [&](const Tile&) {
        if (++tiles == 3) cancel = true;
    };
    Image img(o.width, o.height);
    RenderStats s = render(scene, o, img);
    EXPECT_TRUE(s.cancelled);
    EXPECT_GE(s.tiles_done, 3);
    EXPECT_LT(s.tiles_done, s.tiles_total / 2);
    // The last tile (bottom right) was never reached: still black.
    for (int y = 224; y < 256; ++y)
        for (int x = 224; x < 256; ++x) ASSERT_EQ(img.at(x, y), glm::u8vec3(0)) << x << "," << y;
}

TEST(Renderer, CancelReturnsPromptlyFromABigRender) {
    // Seconds of work if it ran to the end; once the flag is set the workers finish at most the
    // row they are on and take no new tile, so render() returns having done a handful of tiles of
    // 16384 (counted, not timed: a loaded machine makes any time bound flaky).
    Scene scene = busy_scene();
    std::atomic<bool> cancel{false};
    std::atomic<int> tiles{0};
    RenderJob o;
    o.width = 4096;
    o.height = 4096;
    o.threads = 2;
    o.cancel = &cancel;
    o.on_tile = [&](const Tile&) {
        if (++tiles == 2) cancel = true;
    };
    Image img(o.width, o.height);
    RenderStats s = render(scene, o, img);
    EXPECT_TRUE(s.cancelled);
    EXPECT_LT(s.tiles_done, 16);
    EXPECT_EQ(img.at(4095, 4095), glm::u8vec3(0));
}

TEST(Renderer, CancelledBeforeTheStartRendersNothing) {
    Scene scene = busy_scene();
    std::atomic<bool> cancel{true};
    RenderJob o;
    o.width = 64;
    o.height = 64;
    o.cancel = &cancel;
    Image img(o.width, o.height);
    RenderStats s = render(scene, o, img);
    EXPECT_TRUE(s.cancelled);
    EXPECT_EQ(s.tiles_done, 0);
    for (auto v : img.rgb) ASSERT_EQ(v, 0);
}

// A glowing wall filling the image left of a vertical edge that falls at pixel column
// `edge_px` (in pixel units from the image's left side) of a width × height image, the rest
// background. The default camera looks down −z from z = 1; the wall's face is at z = −4.5.
Scene edge_scene(int width, int height, float edge_px, glm::vec3 glow, glm::vec3 background) {
    const Camera cam;
    const float aspect = float(width) / float(height);
    const float edge_x = (2.0f * edge_px / float(width) - 1.0f) * cam.tan_half_fov * aspect * 5.5f;
    test::SceneBuilder b;
    b.add(ShapeKind::Cube, test::translate_scale({edge_x - 50.0f, 0, -5}, {100, 100, 1}), test::emitter(glow));
    b.background(background);
    return b.build();
}

TEST(Renderer, AntiAliasingAveragesTheSubPixelsAPixelIsCutInto) {
    const glm::vec3 red(1, 0, 0), blue(0, 0, 1);
    RenderJob o;
    o.width = 9;
    o.height = 5;
    {
        // Edge through the middle of column 4: with 2×2 rays, two see the wall, two the background.
        o.sampling.aa = 2;
        Image img(o.width, o.height);
        RenderStats s = render(edge_scene(9, 5, 4.5f, red, blue), o, img);
        EXPECT_EQ(s.rays.camera, 9u * 5u * 4u);
        for (int y = 0; y < 5; ++y) {
            EXPECT_EQ(img.at(3, y), glm::u8vec3(255, 0, 0)) << y;
            EXPECT_EQ(img.at(4, y), glm::u8vec3(128, 0, 128)) << y;  // ⌊255 · 0.5 + 0.5⌋
            EXPECT_EQ(img.at(5, y), glm::u8vec3(0, 0, 255)) << y;
        }
    }
    {
        // Edge three quarters across column 4: sub-pixel centres at 4.125, 4.375, 4.625 (wall) and
        // 4.875 (background), so 3/4 red, 1/4 blue.
        o.sampling.aa = 4;
        Image img(o.width, o.height);
        RenderStats s = render(edge_scene(9, 5, 4.75f, red, blue), o, img);
        EXPECT_EQ(s.rays.camera, 9u * 5u * 16u);
        EXPECT_EQ(img.at(4, 2), glm::u8vec3(191, 0, 64));  // ⌊191.25 + 0.5⌋, ⌊63.75 + 0.5⌋
        EXPECT_EQ(img.at(0, 2), glm::u8vec3(255, 0, 0));
        EXPECT_EQ(img.at(8, 2), glm::u8vec3(0, 0, 255));
    }
    {
        // aa = 1 is the single ray through the pixel centre: column 4's centre (4.5) is left of
        // an edge at 4.75.
        o.sampling.aa = 1;
        Image img(o.width, o.height);
        render(edge_scene(9, 5, 4.75f, red, blue), o, img);
        EXPECT_EQ(img.at(4, 2), glm::u8vec3(255, 0, 0));
    }
}

TEST(Renderer, AntiAliasingClampsEachRayBeforeTheMean) {
    // A wall glowing 4× brighter than white beside black: the half-covered pixel shows half of
    // white (what each ray can show), not the clipped mean of 2.
    RenderJob o;
    o.width = 9;
    o.height = 5;
    o.sampling.aa = 2;
    Image img(o.width, o.height);
    render(edge_scene(9, 5, 4.5f, glm::vec3(4.0f), glm::vec3(0.0f)), o, img);
    EXPECT_EQ(img.at(4, 2), glm::u8vec3(128));
}

TEST(Renderer, AntiAliasedImageIsByteIdenticalForAnyThreadCountAndTileSize) {
    Scene scene = busy_scene();
    RenderJob o;
    o.width = 97;
    o.height = 61;
    o.sampling.aa = 3;  // 9 rays a pixel: packets of 16 straddle pixels
    o.tile_size = 16;
    o.threads = 1;
    Image one(o.width, o.height), two(o.width, o.height), other_tiles(o.width, o.height), plain(o.width, o.height);
    const RenderStats s = render(scene, o, one);
    EXPECT_EQ(s.rays.camera, std::uint64_t(97 * 61 * 9));
    o.threads = 2;
    render(scene, o, two);
    o.tile_size = 7;
    render(scene, o, other_tiles);
    EXPECT_EQ(one.rgb, two.rgb);
    EXPECT_EQ(one.rgb, other_tiles.rgb);
    o.sampling.aa = 1;
    render(scene, o, plain);
    EXPECT_NE(one.rgb, plain.rgb) << "anti-aliasing should change the edges of the shapes";
}

TEST(Renderer, AdaptiveAntiAliasingSupersamplesOnlyWhereNeighboursDiffer) {
    // The edge three quarters across column 4 of a 9 × 5 image: column 4's centre (4.5) sees the
    // red wall, column 5's (5.5) the blue background, so exactly columns 4 and 5 differ from a
    // neighbour. They get 4 × 4 rays (column 4: 3/4 red; column 5: all blue); every other pixel
    // keeps its centre ray.
    RenderJob o;
    o.width = 9;
    o.height = 5;
    o.sampling.aa = 4;
    o.sampling.aa_threshold = 0.1f;
    Image img(o.width, o.height);
    RenderStats s = render(edge_scene(9, 5, 4.75f, {1, 0, 0}, {0, 0, 1}), o, img);
    for (int y = 0; y < 5; ++y) {
        EXPECT_EQ(img.at(3, y), glm::u8vec3(255, 0, 0)) << y;
        EXPECT_EQ(img.at(4, y), glm::u8vec3(191, 0, 64)) << y;
        EXPECT_EQ(img.at(5, y), glm::u8vec3(0, 0, 255)) << y;
    }
    // One tile: 45 centre rays, then 16 for each of the 10 pixels of columns 4 and 5.
    EXPECT_EQ(s.rays.camera, 45u + 10u * 16u);
}

TEST(Renderer, AdaptiveAntiAliasingIsEitherTheCentreRayOrTheFullGridPerPixel) {
    Scene scene = busy_scene();
    RenderJob o;
    o.width = 97;
    o.height = 61;
    o.tile_size = 16;
    o.threads = 2;
    Image plain(o.width, o.height), full(o.width, o.height), adaptive(o.width, o.height);
    render(scene, o, plain);
    o.sampling.aa = 3;
    render(scene, o, full);
    o.sampling.aa_threshold = 0.05f;
    render(scene, o, adaptive);
    int centre_only = 0, supersampled = 0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const glm::u8vec3 a = adaptive.at(x, y);
            ASSERT_TRUE(a == plain.at(x, y) || a == full.at(x, y)) << x << "," << y;
            centre_only += a == plain.at(x, y) && a != full.at(x, y);
            supersampled += a == full.at(x, y) && a != plain.at(x, y);
        }
    EXPECT_GT(centre_only, 0) << "smooth areas keep their one ray";
    EXPECT_GT(supersampled, 100) << "edges are anti-aliased";
    // Tiles compare their edge pixels with the next tile's: no seams, whatever the tiling.
    Image one_thread(o.width, o.height), other_tiles(o.width, o.height);
    o.threads = 1;
    render(scene, o, one_thread);
    o.tile_size = 7;
    o.threads = 2;
    render(scene, o, other_tiles);
    EXPECT_EQ(one_thread.rgb, adaptive.rgb);
    EXPECT_EQ(other_tiles.rgb, adaptive.rgb);
    // A threshold no difference of clamped colours exceeds: the one-ray image, byte for byte.
    o.sampling.aa_threshold = 1.0f;
    Image none(o.width, o.height);
    render(scene, o, none);
    EXPECT_EQ(none.rgb, plain.rgb);
}

TEST(Renderer, AThresholdThatIsNotAPositiveNumberMeansEveryPixel) {
    // NaN slipped past the option checks once and sent the sampler down the adaptive path
    // without its buffers.
    Scene scene = busy_scene();
    RenderJob o;
    o.width = 40;
    o.height = 30;
    o.sampling.aa = 2;
    Image every(o.width, o.height), nan_threshold(o.width, o.height), negative(o.width, o.height);
    render(scene, o, every);
    o.sampling.aa_threshold = std::nanf("");
    render(scene, o, nan_threshold);
    o.sampling.aa_threshold = -1.0f;
    render(scene, o, negative);
    EXPECT_EQ(nan_threshold.rgb, every.rgb);
    EXPECT_EQ(negative.rgb, every.rgb);
}

TEST(Renderer, AFarAwayPointLightCastsNoSpecklesOnWhatItLights) {
    // Shapes alone under a point light 10,000 units away (a sun made of a point light), no
    // ambient: nothing but a shape itself can shadow it, and only where it faces away from the
    // light, where the light gives nothing anyway. So where a pixel is lit, its neighbours are
    // lit or dark only as N·L falls off, never a black speck among bright pixels. A shadow query
    // started at the light would find each point's own surface (a hit's float error is about
    // 1e-7 of its distance from the ray's origin, here far more than the surface offset).
    test::SceneBuilder b;
    Material m;
    m.diffuse = glm::vec3(1.0f);
    b.add(ShapeKind::Sphere, test::translate_scale({-1.2f, 0, -5}, glm::vec3(2.0f)), m);
    b.add(ShapeKind::Cylinder, test::translate_scale({1.3f, 0, -5}, glm::vec3(1.5f)), m);
    b.add(ShapeKind::Cone, test::translate_scale({0, -1.5f, -7}, glm::vec3(1.5f)), m);
    b.light(test::point_light({10000, 10000, 5000}, glm::vec3(1.0f)));
    Scene scene = b.build();
    RenderJob o;
    o.width = 160;
    o.height = 120;
    Image img(o.width, o.height);
    render(scene, o, img);
    int lit = 0, specks = 0;
    for (int y = 1; y + 1 < o.height; ++y)
        for (int x = 1; x + 1 < o.width; ++x) {
            const int v = img.at(x, y).x;
            lit += v > 0;
            const int neighbours[] = {img.at(x - 1, y).x, img.at(x + 1, y).x, img.at(x, y - 1).x, img.at(x, y + 1).x};
            specks += v == 0 && std::all_of(std::begin(neighbours), std::end(neighbours), [](int n) { return n > 40; });
        }
    EXPECT_GT(lit, 1000) << "the lit sides of the shapes";
    EXPECT_EQ(specks, 0);
}

TEST(Renderer, ToByteRoundsAndClamps) {
    EXPECT_EQ(to_byte(0.0f), 0);
    EXPECT_EQ(to_byte(1.0f), 255);
    EXPECT_EQ(to_byte(2.5f), 255);
    EXPECT_EQ(to_byte(-1.0f), 0);
    EXPECT_EQ(to_byte(0.5f), 128);           // ⌊127.5 + 0.5⌋
    EXPECT_EQ(to_byte(100.0f / 255.0f), 100);
    EXPECT_EQ(to_byte(std::nanf("")), 0);
}

}  // namespace
}  // namespace whitted

namespace whitted {
namespace {

// An integrator that counts the packets it is given and sets the cancel flag at the `stop_at`-th:
// how soon the renderer looks at the flag, counted (one pixel at --spp 65536
// --aa 16 ran 95 s under --timeout 3, the flag looked at only between rows).
class CountingIntegrator final : public Integrator {
public:
    CountingIntegrator(const Scene& scene, std::atomic<bool>& cancel, int stop_at)
        : Integrator(scene, Camera{}), cancel_(cancel), stop_at_(stop_at) {}
    void radiance(const CameraBatch&, const Sampler&, glm::vec3 (&out)[kPacketSize], RayCounts&) const override {
        for (glm::vec3& c : out) c = glm::vec3(0.5f);
        if (++calls == stop_at_) cancel_ = true;
    }
    mutable std::atomic<int> calls{0};

private:
    std::atomic<bool>& cancel_;
    int stop_at_;
};

TEST(Renderer, CancelIsSeenBetweenPacketsOfOnePixelsSamples) {
    const Scene scene = busy_scene();
    std::atomic<bool> cancel{false};
    const CountingIntegrator counting(scene, cancel, 3);
    RenderJob job;
    job.width = job.height = 1;
    job.threads = 1;
    job.sampling.aa = Sampler::kMaxAa;
    job.sampling.spp = Sampler::kMaxSpp;  // 16.7 million samples, a million packets
    job.cancel = &cancel;
    Film film(1, 1);
    const RenderStats s = render(counting, job, film);
    EXPECT_TRUE(s.cancelled);
    EXPECT_EQ(s.tiles_done, 0);
    EXPECT_EQ(counting.calls, 3);
}

TEST(Renderer, CancelIsSeenBetweenPacketsOfARowOfOneSamplePixels) {
    const Scene scene = busy_scene();
    std::atomic<bool> cancel{false};
    const CountingIntegrator counting(scene, cancel, 2);
    RenderJob job;
    job.width = 1024;  // one tile, a band of 256 packets a row of packets
    job.height = 4;
    job.tile_size = 1024;
    job.threads = 1;
    job.cancel = &cancel;
    Film film(job.width, job.height);
    const RenderStats s = render(counting, job, film);
    EXPECT_TRUE(s.cancelled);
    EXPECT_EQ(counting.calls, 2);
}

}  // namespace
}  // namespace whitted

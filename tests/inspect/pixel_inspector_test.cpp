// The pixel inspector on a scene whose every part is known: objects and the lines above them,
// shadows, mirror rays, the background, and colour parts that add up to the rendered pixel.
#include <gtest/gtest.h>

#include "film/film.h"
#include "inspect/pixel_inspector.h"
#include "inspect/report_text.h"
#include "inspect/inspect_scene.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted {
namespace {

using test::find_in_scene;
using test::project;

std::shared_ptr<const Scene> load_inspect_scene() {
    LoadResult r = load_scene_text(test::kInspectScene, "inspect.sc");
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].str());
    return r.scene;
}

RenderJob job(int aa = 1) {
    RenderJob j;
    j.width = test::kInspectWidth;
    j.height = test::kInspectHeight;
    j.sampling.aa = aa;
    return j;
}

void expect_at(const SourceLoc& loc, const test::TextPos& pos, const char* what) {
    EXPECT_EQ(loc.file, "inspect.sc") << what;
    EXPECT_EQ(loc.line, pos.line) << what;
    EXPECT_EQ(loc.col, pos.col) << what;
}

void expect_link(const ChainLink& l, LinkKind kind, const std::string& name, const test::TextPos& pos) {
    EXPECT_EQ(l.kind, kind) << name;
    EXPECT_EQ(l.name, name);
    EXPECT_EQ(l.loc.line, pos.line) << link_keyword(kind) << " " << name;
    EXPECT_EQ(l.loc.col, pos.col) << link_keyword(kind) << " " << name;
}

// The chain the file spells out for the pillar drawn by trans `pair_trans` of subgraph pair.
void expect_pillar_chain(const std::vector<ChainLink>& chain, const std::string& pair_trans) {
    ASSERT_EQ(chain.size(), 8u);
    const int pair_line = find_in_scene(pair_trans).line;
    expect_link(chain[0], LinkKind::Mastersubgraph, "root", find_in_scene("mastersubgraph root"));
    expect_link(chain[1], LinkKind::Trans, "", find_in_scene("trans [ translate 0 1 0"));
    expect_link(chain[2], LinkKind::Subgraph, "pair", find_in_scene("pair", find_in_scene("    subgraph pair").line));
    expect_link(chain[3], LinkKind::Mastersubgraph, "pair", find_in_scene("mastersubgraph pair"));
    expect_link(chain[4], LinkKind::Trans, "", find_in_scene(pair_trans));
    expect_link(chain[5], LinkKind::Subgraph, "pillar", find_in_scene("pillar", pair_line + 1));
    expect_link(chain[6], LinkKind::Mastersubgraph, "pillar", find_in_scene("mastersubgraph pillar"));
    expect_link(chain[7], LinkKind::Trans, "", find_in_scene("trans [", find_in_scene("mastersubgraph pillar").line));
}

TEST(PixelInspector, OneObjectDrawnTwiceHasOneLineAndTwoChains) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    const glm::ivec2 left = project(test::kLeftPillarFront), right = project(test::kRightPillarFront);
    const PixelReport l = inspect_pixel(*scene, job(), left.x, left.y);
    const PixelReport r = inspect_pixel(*scene, job(), right.x, right.y);
    ASSERT_TRUE(l.hit && r.hit);
    EXPECT_NE(l.hit->object.instance, r.hit->object.instance);
    for (const PixelReport* p : {&l, &r}) {
        EXPECT_EQ(p->hit->object.kind, ShapeKind::Cylinder);
        expect_at(p->hit->object.loc, find_in_scene("object cylinder"), "cylinder");
        EXPECT_EQ(p->material.diffuse, glm::vec3(0, 1, 0));
        EXPECT_EQ(p->material.ambient, glm::vec3(0, 0.1f, 0));
        EXPECT_NEAR(p->hit->point.z, 0.5f, 0.01f);  // the cylinder's front
    }
    EXPECT_NEAR(l.hit->point.x, -3.0f, 0.05f);
    EXPECT_NEAR(r.hit->point.x, 3.0f, 0.05f);
    expect_pillar_chain(l.hit->object.chain, "trans [ translate -3 0 0");
    expect_pillar_chain(r.hit->object.chain, "trans [ translate 3 0 0");
}

// The report's value is the rendered pixel's, and its parts add up to it: linear values to float
// rounding (a few additions of numbers below 2: 1e-5 is hundreds of ulps), 8-bit values exactly
// (the value) or within one step (the sum, which rounding could carry across a .5 boundary).
void expect_parts_sum_to_the_render(const Scene& scene, const RenderJob& j, const std::vector<glm::ivec2>& pixels) {
    const auto integrator = make_integrator(scene, j.camera_for(scene), j.integrator);
    Film film(j.width, j.height);
    render(*integrator, j, film);
    const Image image = film.to_image();
    for (const glm::ivec2& px : pixels) {
        SCOPED_TRACE("pixel " + std::to_string(px.x) + "," + std::to_string(px.y));
        const PixelReport r = inspect_pixel(scene, j, px.x, px.y);
        const glm::vec3 rendered = film.at(px.x, px.y).value();
        EXPECT_EQ(r.value, rendered);
        EXPECT_EQ(r.bytes, image.at(px.x, px.y));
        ASSERT_TRUE(r.decomposed);
        const glm::vec3 sum = r.parts.sum();
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(sum[c], rendered[c], 1e-5f) << "channel " << c;
            EXPECT_LE(std::abs(int(to_byte(sum[c])) - int(image.at(px.x, px.y)[c])), 1) << "channel " << c;
        }
    }
}

std::vector<glm::ivec2> known_pixels() {
    return {project(test::kLeftPillarFront), project(test::kRightPillarFront), project(test::kSphereUpperFront),
            project(test::kFloorInShadow),   project(test::kMirrorTowardSphere), project(test::kEmptySky),
            project({2, -1.9f, 0.3f})};
}

TEST(PixelInspector, PartsSumToTheRenderedPixel) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    expect_parts_sum_to_the_render(*scene, job(), known_pixels());
}

TEST(PixelInspector, PartsAverageOverAntiAliasingSamplesAsTheFilmDoes) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    // The pillar's left silhouette (x = -3.5) and the sphere's top (y = 2.5): pixels whose samples
    // see two things. Plus the known pixels, with 3 x 3 samples each.
    std::vector<glm::ivec2> pixels = known_pixels();
    pixels.push_back(project({-3.5f, 1, 0}));
    pixels.push_back(project({0, 2.5f, 0}));
    expect_parts_sum_to_the_render(*scene, job(3), pixels);
    // The sphere's silhouette crosses the pixels around its upper left side diagonally (within a
    // pixel or two of the projected side point, in perspective): some of them have samples on both
    // sides of it.
    const glm::ivec2 edge = project({-0.5f * 0.70710678f, 2 + 0.5f * 0.70710678f, 0});
    bool split = false;
    for (int d = -9; d <= 9; ++d) {
        const PixelReport r = inspect_pixel(*scene, job(3), edge.x + d % 3, edge.y + d / 3);
        EXPECT_EQ(r.samples, 9);
        int total = 0;
        for (const SeenCount& s : r.seen) total += s.samples;
        EXPECT_EQ(total, 9);
        split = split || r.seen.size() >= 2;  // the sphere and the mirror behind its edge
    }
    EXPECT_TRUE(split);
}

TEST(PixelInspector, AdaptivePixelsAndSoftSamplesAlsoSum) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    RenderJob adaptive = job(4);
    adaptive.sampling.aa_threshold = 0.1f;
    expect_parts_sum_to_the_render(*scene, adaptive, known_pixels());
    RenderJob spp = job(2);
    spp.sampling.spp = 3;
    expect_parts_sum_to_the_render(*scene, spp, known_pixels());
}

TEST(PixelInspector, ClampingShowsAsItsOwnPart) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    const glm::ivec2 p = project(test::kSphereUpperFront);
    const PixelReport r = inspect_pixel(*scene, job(), p.x, p.y);
    ASSERT_TRUE(r.hit);
    expect_at(r.hit->object.loc, find_in_scene("object sphere"), "sphere");
    // red: ambient 0.5 + diffuse n·l ≈ 0.67 (+ specular) > 1: the film keeps 1.
    EXPECT_NEAR(r.parts.ambient.x, 0.5f, 1e-6f);
    EXPECT_GT(r.parts.diffuse.x, 0.5f);
    EXPECT_LT(r.parts.clamp.x, -0.1f);
    EXPECT_EQ(r.value.x, 1.0f);
}

TEST(PixelInspector, NamesWhatShadowsAPoint) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    const glm::ivec2 p = project(test::kFloorInShadow);
    const PixelReport r = inspect_pixel(*scene, job(), p.x, p.y);
    ASSERT_TRUE(r.hit);
    expect_at(r.hit->object.loc, find_in_scene("object cube"), "floor");
    ASSERT_EQ(r.lights.size(), 1u);
    const LightInfo& l = r.lights[0];
    expect_at(l.loc, find_in_scene("light ["), "light");
    EXPECT_TRUE(l.term.faces);
    EXPECT_EQ(l.term.shadow, glm::vec3(0.0f));
    ASSERT_EQ(l.blockers.size(), 1u);
    EXPECT_EQ(l.blockers[0].object.kind, ShapeKind::Sphere);
    expect_at(l.blockers[0].object.loc, find_in_scene("object sphere"), "blocker");
    EXPECT_FALSE(l.blockers[0].transparent);
    // Where the ray from the hit toward the light enters the sphere (centre (0, 2, 0), radius 0.5):
    // the nearer root of |h + t·d - c|² = 0.25 (the report's t starts at the hit, up to the 1e-4 offset).
    const glm::vec3 h = r.hit->point, d = glm::normalize(glm::vec3(0, 10, 0) - h), oc = h - glm::vec3(0, 2, 0);
    const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - 0.25f;
    EXPECT_NEAR(l.blockers[0].t, -b - std::sqrt(b * b - c), 1e-3f);
    // In shadow, the floor is its ambient alone.
    EXPECT_NEAR(r.value.x, 0.1f, 1e-6f);
    EXPECT_EQ(r.parts.diffuse, glm::vec3(0.0f));
}

TEST(PixelInspector, LitFloorMatchesTheHandComputedDiffuse) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    const glm::vec3 point{2, -1.9f, 0.3f};
    const glm::ivec2 p = project(point);
    const PixelReport r = inspect_pixel(*scene, job(), p.x, p.y);
    ASSERT_TRUE(r.hit);
    ASSERT_EQ(r.lights.size(), 1u);
    EXPECT_TRUE(r.lights[0].blockers.empty());
    // n = +y, light (0, 10, 0): n·l = (10 - y) / |light - hit|, diffuse 0.6 · n·l; the pixel's
    // centre lands within a pixel (< 0.1) of `point`, which moves n·l by less than 0.01.
    const glm::vec3 h = r.hit->point;
    EXPECT_NEAR(h.y, -1.9f, 1e-4f);
    EXPECT_NEAR(h.x, point.x, 0.1f);
    const float n_dot_l = (10.0f - h.y) / glm::length(glm::vec3(0, 10, 0) - h);
    EXPECT_NEAR(r.lights[0].term.n_dot_l, n_dot_l, 1e-5f);
    EXPECT_NEAR(r.parts.diffuse.x, 0.6f * n_dot_l, 1e-5f);
    EXPECT_NEAR(r.parts.ambient.x, 0.1f, 1e-6f);
    // The texture coordinates are reported though the floor has no texture: §8's top face of the
    // cube scaled 20 × 0.2 × 20, u = x/20 + 0.5, v = z/20 + 0.5.
    EXPECT_EQ(r.texture_file, "");
    EXPECT_NEAR(r.hit->uv.x, h.x / 20.0f + 0.5f, 1e-5f);
    EXPECT_NEAR(r.hit->uv.y, h.z / 20.0f + 0.5f, 1e-5f);
}

TEST(PixelInspector, NamesWhatTheMirrorReflects) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    const glm::ivec2 p = project(test::kMirrorTowardSphere);
    const PixelReport r = inspect_pixel(*scene, job(), p.x, p.y);
    ASSERT_TRUE(r.hit);
    expect_at(r.hit->object.loc, find_in_scene("object cube", find_in_scene("scale 8 5 0.2").line), "mirror");
    EXPECT_EQ(r.material.reflect, glm::vec3(0.8f));
    EXPECT_EQ(r.reflected.record.outcome, SecondaryRecord::Outcome::Traced);
    ASSERT_TRUE(r.reflected.next);
    EXPECT_EQ(r.reflected.next->object.kind, ShapeKind::Sphere);
    expect_at(r.reflected.next->object.loc, find_in_scene("object sphere"), "reflected hit");
    EXPECT_EQ(r.refracted.record.outcome, SecondaryRecord::Outcome::NoRay);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.parts.reflect[c], 0.8f * r.reflected.record.color[c], 1e-6f);
}

TEST(PixelInspector, BackgroundPixelSaysSo) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    const glm::ivec2 p = project(test::kEmptySky);
    const PixelReport r = inspect_pixel(*scene, job(), p.x, p.y);
    EXPECT_FALSE(r.hit);
    EXPECT_EQ(r.value, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(r.parts.background, glm::vec3(0.1f, 0.2f, 0.3f));
    const std::string text = report_text(r, "");
    EXPECT_NE(text.find("background: the camera ray hits nothing; the background colour is (0.1000 0.2000 0.3000)"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find("object:"), std::string::npos);
}

TEST(PixelInspector, PathModeSaysWhatIsNotSplit) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    RenderJob j = job();
    j.integrator = {RenderMode::Path, 4};
    j.sampling.spp = 4;
    const glm::ivec2 p = project(test::kLeftPillarFront);
    const PixelReport r = inspect_pixel(*scene, j, p.x, p.y);
    EXPECT_FALSE(r.decomposed);
    EXPECT_NE(r.note.find("path mode"), std::string::npos);
    ASSERT_TRUE(r.hit);
    expect_at(r.hit->object.loc, find_in_scene("object cylinder"), "cylinder");
    // The value is still the rendered pixel's.
    const auto integrator = make_integrator(*scene, j.camera_for(*scene), j.integrator);
    Film film(j.width, j.height);
    render(*integrator, j, film);
    EXPECT_EQ(r.value, film.at(p.x, p.y).value());
}

TEST(PixelInspector, ReportTextNamesLinesRelativeToTheSceneFolder) {
    EXPECT_EQ(display_path("/a/b/scene.sc", "/a/b"), "scene.sc");
    EXPECT_EQ(display_path("/a/b/sub/scene.sc", "/a/b"), "sub/scene.sc");
    EXPECT_EQ(display_path("/elsewhere/scene.sc", "/a/b"), "/elsewhere/scene.sc");
    EXPECT_EQ(display_path("scene.sc", ""), "scene.sc");
    EXPECT_EQ(display_loc(SourceLoc{"/a/b/s.sc", 3, 7}, "/a/b"), "s.sc:3:7");
    EXPECT_EQ(display_loc(SourceLoc{}, "/a/b"), "(not from a file)");
}

// A Brown/Tufts file (§9.4) has no mastersubgraph line: its root is the top-level trans blocks,
// and the chain says so instead of naming a `mastersubgraph root` the file does not have.
TEST(PixelInspector, BrownTuftsChainStartsAtTheTopLevelTransBlocks) {
    const char* text =
        "camera [ eye 0 0 5 focus 0 0 0 up 0 1 0 angle 30 ]\n"  // line 1
        "light [ number 0 position 0 0 5 ]\n"                   // line 2
        "trans [ translate 9 0 0 object cube [ ] ]\n"           // line 3: off to the side
        "trans [ object sphere [ diffuse 1 0 0 ] ]\n";          // line 4: in the middle
    LoadResult loaded = load_scene_text(text, "brown.sc");
    ASSERT_TRUE(loaded.ok()) << (loaded.diagnostics.empty() ? "" : loaded.diagnostics[0].str());
    RenderJob j;
    j.width = j.height = 9;
    const PixelReport r = inspect_pixel(*loaded.scene, j, 4, 4);
    ASSERT_TRUE(r.hit);
    EXPECT_EQ(r.hit->object.kind, ShapeKind::Sphere);
    const std::vector<ChainLink>& chain = r.hit->object.chain;
    ASSERT_EQ(chain.size(), 2u);
    expect_link(chain[0], LinkKind::ImplicitRoot, "", {3, 1});
    expect_link(chain[1], LinkKind::Trans, "", {4, 1});
    const std::string report = report_text(r, "");
    EXPECT_NE(report.find("  in the top-level trans blocks at brown.sc:3:1\n  in trans at brown.sc:4:1\n"),
              std::string::npos)
        << report;
    EXPECT_EQ(report.find("mastersubgraph"), std::string::npos) << report;
}

}  // namespace
}  // namespace whitted

namespace whitted {
namespace {

// --inspect honours --timeout and Ctrl-C: it traces every sample of the pixel
// again, millions with --spp 65536 --aa 16; the job's cancel flag stops it, and the report says it
// is incomplete instead of showing half an average.
TEST(PixelInspector, StopsWhenTheJobIsCancelled) {
    const auto scene = load_inspect_scene();
    ASSERT_TRUE(scene);
    RenderJob j = job();
    j.sampling.aa = Sampler::kMaxAa;
    j.sampling.spp = Sampler::kMaxSpp;
    const std::atomic<bool> cancel{true};
    const PixelReport r = inspect_pixel(*scene, j, 3, 3, &cancel);
    EXPECT_TRUE(r.cancelled);
    // The job's own flag is the render's (the viewer's, set when a render is replaced): not the inspector's.
    j.sampling = {};
    j.cancel = &cancel;
    EXPECT_FALSE(inspect_pixel(*scene, j, 3, 3).cancelled);
}

}  // namespace
}  // namespace whitted

// `whitted SCENE --inspect X,Y`: the report as a user reads it, checked against the scene's text
// and against the image the same settings render.
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "inspect/inspect_scene.h"
#include "inspect/ray_tree_scene.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::find_in_scene;
using test::project;

std::string loc(const std::string& needle, int from = 1) {
    const test::TextPos p = find_in_scene(needle, from);
    return "scene.sc:" + std::to_string(p.line) + ":" + std::to_string(p.col);
}

test::ProcessResult inspect(const std::string& scene, glm::ivec2 px, std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{test::cli_path(), scene, "--width", std::to_string(test::kInspectWidth), "--height",
                                  std::to_string(test::kInspectHeight), "--inspect",
                                  std::to_string(px.x) + "," + std::to_string(px.y)};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return test::run_process(argv);
}

bool has(const std::string& text, const std::string& line) { return text.find(line) != std::string::npos; }

// The numbers after `label` on its line.
std::vector<float> numbers_after(const std::string& text, const std::string& label) {
    std::vector<float> out;
    const auto at = text.find(label);
    if (at == std::string::npos) return out;
    std::istringstream in(text.substr(at + label.size(), text.find('\n', at) - at - label.size()));
    float v;
    while (in >> v) out.push_back(v);
    return out;
}

TEST(CliInspect, NamesTheObjectItsChainAndMaterialAndWritesNoImage) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", test::kInspectScene);
    const auto r = inspect(scene, project(test::kRightPillarFront));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(has(r.output, "object: cylinder at " + loc("object cylinder") + "\n")) << r.output;
    const int right_trans = find_in_scene("trans [ translate 3 0 0").line;
    EXPECT_TRUE(has(r.output, "  in mastersubgraph root at " + loc("mastersubgraph root") + "\n")) << r.output;
    EXPECT_TRUE(has(r.output, "  in trans at " + loc("trans [ translate 3 0 0") + "\n")) << r.output;
    EXPECT_TRUE(has(r.output, "  in subgraph pillar at " + loc("pillar", right_trans + 1) + "\n")) << r.output;
    EXPECT_TRUE(has(r.output, "material: ambient 0.0000 0.1000 0.0000, diffuse 0.0000 1.0000 0.0000,")) << r.output;
    // Nothing rendered to a file: the folder holds the scene alone.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(CliInspect, ColourAndPartsMatchTheRenderedImage) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", test::kInspectScene);
    for (const std::string aa : {"1", "3"}) {
        const std::string png = dir + "/render" + aa + ".png";
        auto rendered = test::run_process({test::cli_path(), scene, "--width", std::to_string(test::kInspectWidth),
                                           "--height", std::to_string(test::kInspectHeight), "--aa", aa, "-o", png,
                                           "-q"});
        ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
        Image image;
        ASSERT_EQ(read_image(png, image), "");
        for (const glm::vec3& point : {test::kLeftPillarFront, test::kSphereUpperFront, test::kFloorInShadow,
                                       test::kMirrorTowardSphere, test::kEmptySky}) {
            const glm::ivec2 px = project(point);
            const auto r = inspect(scene, px, {"--aa", aa});
            ASSERT_EQ(r.exit_code, 0) << r.output;
            SCOPED_TRACE(r.output);
            const std::vector<float> bytes = numbers_after(r.output, "= bytes");
            ASSERT_EQ(bytes.size(), 3u);
            const glm::u8vec3 want = image.at(px.x, px.y);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(int(bytes[std::size_t(c)]), int(want[c])) << "channel " << c;
            // The parts are printed to 4 decimals (each off by up to 5e-5): up to 8 of them.
            const std::vector<float> colour = numbers_after(r.output, "colour ");
            ASSERT_GE(colour.size(), 3u);
            glm::vec3 sum(0.0f);
            for (const char* part : {"  ambient ", "  diffuse ", "  specular ", "  reflect ", "  transparent ",
                                     "  emit ", "  background ", "  clamped "}) {
                const std::vector<float> v = numbers_after(r.output, part);
                if (v.empty()) continue;
                ASSERT_EQ(v.size(), 3u) << part;
                sum += glm::vec3(v[0], v[1], v[2]);
            }
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], colour[std::size_t(c)], 8 * 5e-5f + 5e-5f);
        }
    }
}

TEST(CliInspect, NamesTheShadowAndTheMirrorsNextHit) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", test::kInspectScene);
    const auto shadow = inspect(scene, project(test::kFloorInShadow));
    ASSERT_EQ(shadow.exit_code, 0) << shadow.output;
    EXPECT_TRUE(has(shadow.output, "light 1 (point at " + loc("light [") + "): in shadow")) << shadow.output;
    EXPECT_TRUE(has(shadow.output, "  shadowed by sphere at " + loc("object sphere") + " (distance")) << shadow.output;
    const auto mirror = inspect(scene, project(test::kMirrorTowardSphere));
    ASSERT_EQ(mirror.exit_code, 0) << mirror.output;
    EXPECT_TRUE(has(mirror.output, "reflected ray: hits sphere at " + loc("object sphere") + " (t ")) << mirror.output;
    EXPECT_TRUE(has(mirror.output, "refracted ray: none\n")) << mirror.output;
    const auto sky = inspect(scene, project(test::kEmptySky));
    ASSERT_EQ(sky.exit_code, 0) << sky.output;
    EXPECT_TRUE(has(sky.output, "background: the camera ray hits nothing")) << sky.output;
}

TEST(CliInspect, BadPixelsAreUsageErrors) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", test::kInspectScene);
    for (const std::string bad : {"200,0", "0,150", "-1,3", "3", "a,b", "3,4,5", "3,", ",4", "1.5,2"}) {
        const auto r = test::run_process({test::cli_path(), scene, "--width", "200", "--height", "150", "--inspect", bad});
        EXPECT_EQ(r.exit_code, 1) << "--inspect '" << bad << "': " << r.output;
        EXPECT_TRUE(has(r.output, "whitted: error: --inspect")) << bad << ": " << r.output;
    }
    // The last pixel is inside.
    EXPECT_EQ(test::run_process({test::cli_path(), scene, "--width", "200", "--height", "150", "--inspect", "199,149"})
                  .exit_code,
              0);
}

TEST(CliInspect, BadSceneIsStillAnError) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "bad.sc", "mastersubgraph root [ trans [ object blob ] ]\n");
    const auto r = test::run_process({test::cli_path(), scene, "--inspect", "1,1"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(has(r.output, "bad.sc:1:")) << r.output;
}

// --ray-tree FILE.obj / FILE.json and --json: the pixel's ray tree, as the mirror-and-glass scene's
// is known by hand (tests/inspect/ray_tree_scene.h): seven segments, the reflected one from the mirror
// point to the glass.
TEST(CliInspect, ExportsTheRayTreeAsObjAndJson) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "tree.sc", test::kRayTreeScene);
    const std::vector<std::string> base{test::cli_path(), scene, "--width", std::to_string(test::kRayTreeWidth),
                                        "--height", std::to_string(test::kRayTreeHeight), "--inspect",
                                        std::to_string(test::kRayTreeX) + "," + std::to_string(test::kRayTreeY)};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> argv = base;
        argv.insert(argv.end(), extra.begin(), extra.end());
        return test::run_process(argv);
    };
    const auto obj = with({"--ray-tree", dir + "/tree.obj"});
    ASSERT_EQ(obj.exit_code, 0) << obj.output;
    EXPECT_TRUE(has(obj.output, "ray tree of that sample: 7 segments, 3 bounces")) << obj.output;
    std::ifstream in(dir + "/tree.obj");
    std::vector<glm::vec3> v;
    int lines = 0;
    for (std::string line; std::getline(in, line);) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        glm::vec3 p;
        if (tag == "v" && ls >> p.x >> p.y >> p.z) v.push_back(p);
        lines += tag == "l";
    }
    ASSERT_EQ(lines, 7);
    ASSERT_EQ(v.size(), 14u);
    struct stat st{};
    ASSERT_EQ(stat((dir + "/tree.obj").c_str(), &st), 0);
    const mode_t mask = umask(0);
    umask(mask);
    EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask) << "the mode of any new file";
    // Segment 2 (the reflected ray): vertices 5 and 6.
    EXPECT_NEAR(v[4].x, test::kMirrorHit.x, 1e-3f);
    EXPECT_NEAR(v[4].z, test::kMirrorHit.z, 1e-3f);
    EXPECT_NEAR(v[5].x, test::kGlassEntry.x, 1e-3f);
    EXPECT_NEAR(v[5].z, test::kGlassEntry.z, 1e-3f);

    const auto json = with({"--json"});
    ASSERT_EQ(json.exit_code, 0) << json.output;
    EXPECT_EQ(json.output.rfind("{\"pixel\":[100,75],\"image\":[201,151],", 0), 0u) << json.output;
    EXPECT_TRUE(has(json.output, "\"kind\":\"reflected\",\"depth\":1,\"parent\":0,")) << json.output;
    EXPECT_FALSE(has(json.output, "ray tree of that sample")) << "JSON alone on stdout";
    const auto json_file = with({"--ray-tree", dir + "/tree.json"});
    ASSERT_EQ(json_file.exit_code, 0) << json_file.output;
    std::ifstream jin(dir + "/tree.json");
    const std::string written{std::istreambuf_iterator<char>(jin), {}};
    EXPECT_EQ(written, json.output);

    EXPECT_EQ(with({"--ray-tree", dir + "/tree.txt"}).exit_code, 1);
    EXPECT_EQ(with({"--ray-tree", dir + "/no/such/folder/tree.obj"}).exit_code, 3);
    EXPECT_EQ(test::run_process({test::cli_path(), scene, "--json"}).exit_code, 1) << "--json without --inspect";
}

}  // namespace
}  // namespace whitted

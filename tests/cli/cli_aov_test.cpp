// `whitted --aov LIST`: the layers as files (one multi-layer OpenEXR file read back with OpenEXR's
// own reader, or one PNG per layer), the image's bytes as without them, and the refusals.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <gtest/gtest.h>

#include "film/image_io.h"
#include "inspect/inspect_scene.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

test::ProcessResult render(const std::string& scene, const std::string& out, std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{test::cli_path(), scene, "--width", std::to_string(test::kInspectWidth), "--height",
                                  std::to_string(test::kInspectHeight), "-q", "-o", out};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return test::run_process(argv);
}

// The wall of the depth test (tests/render/aov_test.cpp): the plane z = 0 seen from (0, 0, 10).
constexpr const char* kWall = R"(camera [ eye 0 0 10 focus 0 0 0 up 0 1 0 angle 60 ]
light [ position 0 0 10 color 1 1 1 ]
mastersubgraph root [
  trans [ translate 0 0 -0.5 scale 100 100 1 object cube [ diffuse 0.5 0.5 0.5 ] ]
]
)";

TEST(CliAov, OneExrFileHoldsTheImageAndTheLayersAsOpenExrReadsThem) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", kWall);
    const auto plain = render(scene, dir + "/plain.exr");
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    const auto r = render(scene, dir + "/wall.exr", {"--aov", "diffuse,depth,object,shadow.L1"});
    ASSERT_EQ(r.exit_code, 0) << r.output;

    Imf::InputFile in((dir + "/wall.exr").c_str());
    std::set<std::string> names;
    for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c) names.insert(c.name());
    EXPECT_EQ(names, (std::set<std::string>{"R", "G", "B", "diffuse.R", "diffuse.G", "diffuse.B", "depth.Z",
                                            "object.X", "shadow.L1.R", "shadow.L1.G", "shadow.L1.B"}));
    const auto* table = in.header().findTypedAttribute<Imf::StringAttribute>("objects");
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->value(), "1 " + scene + ":4\n");  // the wall's `object` line

    const Imath::Box2i dw = in.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    ASSERT_EQ(w, test::kInspectWidth);
    ASSERT_EQ(h, test::kInspectHeight);
    std::vector<float> depth(std::size_t(w * h)), object(std::size_t(w * h)), shadow(std::size_t(w * h)),
        red(std::size_t(w * h)), diffuse(std::size_t(w * h));
    Imf::FrameBuffer fb;
    auto slice = [&](const char* name, std::vector<float>& v) {
        fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), sizeof(float), sizeof(float) * std::size_t(w)));
    };
    slice("depth.Z", depth);
    slice("object.X", object);
    slice("shadow.L1.G", shadow);
    slice("R", red);
    slice("diffuse.R", diffuse);
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);

    // The image's channels are those of the render without layers.
    {
        Imf::InputFile p((dir + "/plain.exr").c_str());
        std::vector<float> pr(std::size_t(w * h));
        Imf::FrameBuffer pfb;
        pfb.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pr.data()), sizeof(float), sizeof(float) * std::size_t(w)));
        p.setFrameBuffer(pfb);
        p.readPixels(dw.min.y, dw.max.y);
        EXPECT_EQ(pr, red);
    }
    const float tan_half = std::tan(glm::radians(30.0f)), aspect = float(w) / float(h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y * w + x);
            const float sx = 2.0f * (float(x) + 0.5f) / float(w) - 1.0f, sy = 1.0f - 2.0f * (float(y) + 0.5f) / float(h);
            const float expected = 10.0f * glm::length(glm::vec3(sx * tan_half * aspect, sy * tan_half, -1.0f));
            ASSERT_NEAR(depth[i], expected, 1e-4f * expected);
            ASSERT_EQ(object[i], 1.0f);
            ASSERT_EQ(shadow[i], 1.0f);  // the light is at the eye: every point of the wall sees it
            // The wall's only term is diffuse (no ambient light, nothing else): the image's value.
            ASSERT_NEAR(diffuse[i], red[i], 1e-6f);
        }
}

TEST(CliAov, OnePngPerLayerBesideTheImageWhoseBytesAreUnchanged) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", test::kInspectScene);
    ASSERT_EQ(render(scene, dir + "/plain.png").exit_code, 0);
    const auto r = render(scene, dir + "/out.png", {"--aov", "diffuse,normal,depth,object,samples,shadow.L1"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(bytes_of(dir + "/out.png"), bytes_of(dir + "/plain.png"));
    for (const char* layer : {"diffuse", "normal", "depth", "object", "samples", "shadow.L1"}) {
        Image image;
        EXPECT_EQ(read_image(dir + "/out." + layer + ".png", image), "") << layer;
        EXPECT_EQ(image.width, test::kInspectWidth);
    }
    // The normal map: the mirror wall faces the camera, +z: (0.5, 0.5, 1) → (128, 128, 255).
    Image normal;
    ASSERT_EQ(read_image(dir + "/out.normal.png", normal), "");
    const glm::ivec2 mirror = test::project(test::kMirrorTowardSphere);
    EXPECT_EQ(normal.at(mirror.x, mirror.y), glm::u8vec3(128, 128, 255));
    // The object PNG lists its ids, colours and lines.
    const std::string object = bytes_of(dir + "/out.object.png");
    EXPECT_NE(object.find("objects"), std::string::npos);
    EXPECT_NE(object.find(scene + ":" + std::to_string(test::find_in_scene("object sphere").line)), std::string::npos);

    // --aov-file: the layers go by its name; an .exr there holds them all.
    ASSERT_EQ(render(scene, dir + "/b.png", {"--aov", "depth", "--aov-file", dir + "/layers/x.png"}).exit_code, 3)
        << "a missing folder is found before the render";
    fs::create_directory(dir + "/layers");
    ASSERT_EQ(render(scene, dir + "/b.png", {"--aov", "depth", "--aov-file", dir + "/layers/x.png"}).exit_code, 0);
    EXPECT_TRUE(fs::exists(dir + "/layers/x.depth.png"));
    EXPECT_EQ(bytes_of(dir + "/b.png"), bytes_of(dir + "/plain.png"));
    ASSERT_EQ(render(scene, dir + "/c.png", {"--aov", "depth", "--aov-file", dir + "/layers/all.exr"}).exit_code, 0);
    EXPECT_TRUE(fs::exists(dir + "/layers/all.exr"));
    EXPECT_EQ(bytes_of(dir + "/c.png"), bytes_of(dir + "/plain.png"));
}

TEST(CliAov, RefusesWhatItCannotWrite) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", test::kInspectScene);
    auto refused = [&](std::vector<std::string> extra, const std::string& says) {
        const auto r = render(scene, dir + "/x.png", extra);
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(dir + "/x.png"));
    };
    refused({"--aov", "difuse"}, "unknown layer 'difuse'");
    refused({"--aov", "shadow.L2"}, "names light 2, and the scene has 1 light");
    refused({"--aov", "direct"}, "path mode's");
    refused({"--aov", "depth", "--mode", "raycast"}, "whitted and path modes");
    refused({"--aov-file", dir + "/l.exr"}, "give --aov too");
    refused({"--aov", "depth", "--aa", "3", "--aa-threshold", "0.1"}, "adaptive anti-aliasing");
    // 200 x 150 pixels of 14 floats (4 of every pixel, 3 + 3 + 3 + 1 of the layers), three times: 5 MB.
    refused({"--aov", "ambient,shadow.L1,normal,depth", "--max-memory", "1M"}, "layers need about");
}

}  // namespace
}  // namespace whitted

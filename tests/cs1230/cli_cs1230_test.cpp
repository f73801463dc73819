// CSCI 1230 files through the `whitted` command, as a student or a grading script runs it: every
// file of the course's corpus (../shared/scenes/cs1230) renders (the one naming the absent
// dragon.obj fails with a located error, exit 2), the course's image size and depth by default,
// the reader's errors located, --cs1230-stage, and --untrusted holding for their textures and meshes.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cs1230/cs1230_test_support.h"
#include "film/image_io.h"
#include "mesh/mesh_test_support.h"
#include "support/needs.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::run_process;

fs::path corpus_dir() {
    const std::string shared = test::shared_dir();
    if (shared.empty()) return {};
    const fs::path dir = fs::path(shared) / "scenes" / "cs1230";
    return fs::is_directory(dir) ? dir : fs::path();
}

std::vector<fs::path> json_files(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(Cs1230Cli, EveryFileOfTheCoursesCorpusRenders) {
    const fs::path dir = corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests,
                  dir.empty() ? "the CSCI 1230 corpus (shared/scenes/cs1230) not found: set WHITTED_SHARED_DIR" : "");
    const std::string out_dir = test::make_temp_dir();
    int rendered = 0, index = 0;
    const auto files = json_files(dir);
    EXPECT_EQ(files.size(), 58u);
    for (const fs::path& file : files) {
        const std::string name = file.lexically_relative(dir).generic_string();
        const bool intersect = name.rfind("intersect/", 0) == 0;
        const std::string out = out_dir + "/" + std::to_string(index++) + ".png";
        std::vector<std::string> argv = {test::cli_path(), file.string(), "-o", out, "--width", "64", "--height", "48", "-q"};
        if (intersect) argv.insert(argv.end(), {"--cs1230-stage", "intersect"});
        const test::ProcessResult r = run_process(argv);
        if (name == "intersect/extra_credit/mesh.json") {  // names meshes/dragon.obj, which does not ship
            EXPECT_EQ(r.exit_code, 2) << r.output;
            EXPECT_NE(r.output.find(file.string() + ":34:27: error: mesh file 'meshes/dragon.obj' not found"),
                      std::string::npos)
                << r.output;
            EXPECT_FALSE(fs::exists(out));
            continue;
        }
        EXPECT_EQ(r.exit_code, 0) << name << ":\n" << r.output;
        Image img;
        EXPECT_EQ(read_image(out, img), "") << name;
        EXPECT_EQ(img.width, 64) << name;
        ++rendered;
    }
    EXPECT_EQ(rendered, 57);
}

TEST(Cs1230Cli, TheCoursesImageSizeAndDepthByDefault) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(
        dir, "s.json", test::json_scene(test::primitive_group(R"("type": "sphere")")));
    const test::ProcessResult r = run_process({test::cli_path(), scene, "--inspect", "512,384"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("pixel 512,384 of 1024x768: whitted mode, max depth 4"), std::string::npos) << r.output;
    // The object is named by its line in the JSON file.
    EXPECT_NE(r.output.find("object: sphere at s.json:"), std::string::npos) << r.output;
    const std::string out = dir + "/s.png";
    ASSERT_EQ(run_process({test::cli_path(), scene, "-q"}).exit_code, 0);
    Image img;
    ASSERT_EQ(read_image(out, img), "");
    EXPECT_EQ(img.width, 1024);
    EXPECT_EQ(img.height, 768);
    // Given sizes and depths win.
    EXPECT_NE(run_process({test::cli_path(), scene, "--inspect", "1,1", "--width", "8", "--height", "4", "--max-depth", "2"})
                  .output.find("of 8x4: whitted mode, max depth 2"),
              std::string::npos);
}

TEST(Cs1230Cli, ReaderErrorsExitTwoLocated) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "bad.json", "{\n  \"globalData\": {\"ambientCoeff\": 1},\n  \"cameraDat\": {}\n}\n");
    const test::ProcessResult r = run_process({test::cli_path(), scene, "-q"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(scene + ":2:17: error: globalData has no 'diffuseCoeff'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(scene + ":3:3: error: unknown key 'cameraDat' in the scene file (did you mean 'cameraData'?)"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir + "/bad.png"));
}

TEST(Cs1230Cli, TheIntersectStageNeedsNoTextures) {
    // A texture that is not there: an error where textures are drawn, none in the Intersect stage.
    const std::string dir = test::make_temp_dir();
    fs::create_directories(dir + "/scenes");
    const std::string scene = test::write_file(
        dir + "/scenes", "t.json",
        test::json_scene(test::primitive_group(R"("type": "cube", "blend": 1, "textureFile": "textures/none.png")")));
    const test::ProcessResult lit = run_process({test::cli_path(), scene, "-o", dir + "/a.png", "--width", "8", "--height", "8"});
    EXPECT_EQ(lit.exit_code, 2) << lit.output;
    EXPECT_NE(lit.output.find("texture 'textures/none.png': not found"), std::string::npos) << lit.output;
    EXPECT_NE(lit.output.find(dir + "/textures/none.png"), std::string::npos) << lit.output;  // the parent's folder
    EXPECT_EQ(run_process({test::cli_path(), scene, "-o", dir + "/b.png", "--width", "8", "--height", "8", "-q",
                           "--cs1230-stage", "intersect"})
                  .exit_code,
              0);
}

TEST(Cs1230Cli, UntrustedConfinesTexturesAndMeshesToTheParentOfTheFilesFolder) {
    // The course's layout: <class>/alice/scenes/x.json names textures/ and meshes/ in <class>/alice.
    const std::string root = test::make_temp_dir();
    const std::string alice = root + "/class/alice";
    for (const char* d : {"/scenes", "/textures", "/meshes"}) fs::create_directories(alice + d);
    ASSERT_EQ(write_image(Image(2, 2), alice + "/textures/mine.png"), "");
    ASSERT_EQ(write_image(Image(2, 2), root + "/secret.png"), "");
    test::write_file(alice + "/meshes", "cube.obj", test::cube_obj());
    test::write_file(root, "secret.obj", test::cube_obj());
    auto run = [&](const std::string& primitive) {
        const std::string scene =
            test::write_file(alice + "/scenes", "x.json", test::json_scene(test::primitive_group(primitive)));
        return run_process({test::cli_path(), "--untrusted", scene, "-o", root + "/out.png", "--width", "8", "--height",
                            "8", "-q"});
    };
    EXPECT_EQ(run(R"("type": "cube", "textureFile": "textures/mine.png")").exit_code, 0);
    EXPECT_EQ(run(R"("type": "mesh", "meshFile": "meshes/cube.obj")").exit_code, 0);
    const test::ProcessResult texture = run(R"("type": "cube", "textureFile": "../../secret.png")");
    EXPECT_EQ(texture.exit_code, 2) << texture.output;
    EXPECT_NE(texture.output.find("not found inside the scene's folder"), std::string::npos) << texture.output;
    const test::ProcessResult mesh = run(R"("type": "mesh", "meshFile": "../../secret.obj")");
    EXPECT_EQ(mesh.exit_code, 2) << mesh.output;
    EXPECT_NE(mesh.output.find("not found inside the scene's folder"), std::string::npos) << mesh.output;
    const test::ProcessResult absolute = run(R"("type": "mesh", "meshFile": ")" + root + R"(/secret.obj")");
    EXPECT_EQ(absolute.exit_code, 2) << absolute.output;
    EXPECT_NE(absolute.output.find("an absolute path, refused"), std::string::npos) << absolute.output;
    // Without --untrusted the same files are read.
    const std::string scene = test::write_file(
        alice + "/scenes", "x.json", test::json_scene(test::primitive_group(R"("type": "mesh", "meshFile": "../../secret.obj")")));
    EXPECT_EQ(run_process({test::cli_path(), scene, "-o", root + "/out.png", "--width", "8", "--height", "8", "-q"}).exit_code, 0);
}

}  // namespace
}  // namespace whitted

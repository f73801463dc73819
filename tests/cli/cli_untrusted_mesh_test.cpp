// `whitted --untrusted` and meshes: an OBJ file named by a scene from
// others is looked up exactly as a texture is (only inside the scene's folder and --texture-path,
// one message for outside and missing, nothing of its words printed), within a size limit and the
// memory limit; the scene file itself may not be a link out of its folder.
#include <signal.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::run_process;
using test::TimedSignal;
using test::write_file;

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

std::string mesh_scene(const std::string& mesh) {
    return "camera [ eye 0.3 0.3 3 focus 0.3 0.3 0 ]\nlight [ position 2 2 5 color 1 1 1 ]\n"
           "mastersubgraph root [ trans [ object mesh [ file " + mesh + " diffuse 1 1 1 ] ] ]\n";
}

class CliUntrustedMesh : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = test::make_temp_dir();
        in_ = root_ + "/class/alice";
        fs::create_directories(in_);
        write_file(in_, "mine.obj", kTriangle);
        write_file(root_, "outside.obj", kTriangle);
        write_file(root_, "secret.txt", "SECRET_TOKEN_1 SECRET_TOKEN_2 SECRET_TOKEN_3\n");
    }
    test::ProcessResult run(const std::string& mesh, std::vector<std::string> extra = {}) {
        const std::string scene = write_file(in_, "s.sc", mesh_scene(mesh));
        std::vector<std::string> args = {test::cli_path(), "--untrusted", scene, "-o", root_ + "/out.png",
                                         "--width", "8", "--height", "8", "-q"};
        args.insert(args.end(), extra.begin(), extra.end());
        return run_process(args, std::vector<TimedSignal>{{60000, SIGKILL}});
    }
    std::string root_, in_;
};

TEST_F(CliUntrustedMesh, OnlyFromTheScenesFolderAndOneMessageForOutsideAndMissing) {
    EXPECT_EQ(run("mine.obj").exit_code, 0);
    const auto missing = run("../../nothing.obj");
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_NE(missing.output.find("s.sc:3:45: error: mesh file '../../nothing.obj' not found inside the scene's "
                                  "folder and the --texture-path folders (--untrusted)"),
              std::string::npos)
        << missing.output;
    // Out through `..`, through a link, by an absolute name: refused, the first two as if missing.
    const auto outside = run("../../outside.obj");
    EXPECT_EQ(outside.exit_code, 2) << outside.output;
    EXPECT_NE(outside.output.find("'../../outside.obj' not found inside the scene's folder"), std::string::npos)
        << outside.output;
    fs::create_symlink("../../outside.obj", in_ + "/link.obj");
    const auto link = run("link.obj");
    EXPECT_EQ(link.exit_code, 2) << link.output;
    EXPECT_NE(link.output.find("'link.obj' not found inside the scene's folder"), std::string::npos) << link.output;
    const auto absolute = run(root_ + "/outside.obj");
    EXPECT_EQ(absolute.exit_code, 2) << absolute.output;
    EXPECT_NE(absolute.output.find("an absolute path, refused for a file from others (--untrusted)"),
              std::string::npos)
        << absolute.output;
    // A --texture-path folder is allowed; without --untrusted the usual places are looked in.
    EXPECT_EQ(run("outside.obj", {"--texture-path", root_}).exit_code, 0);
    const std::string scene = write_file(in_, "s.sc", mesh_scene("../../outside.obj"));
    EXPECT_EQ(run_process({test::cli_path(), scene, "-o", root_ + "/out.png", "--width", "8", "--height", "8", "-q"})
                  .exit_code,
              0);
}

// Words of a file that is not an OBJ (or not a scene) are never printed: a file from others must not
// be able to read a secret out, a word at a time, through error messages.
TEST_F(CliUntrustedMesh, NothingOfAFileThatIsNotAMeshOrASceneIsPrinted) {
    fs::copy_file(root_ + "/secret.txt", in_ + "/secret.obj");
    auto r = run("secret.obj");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.find("SECRET"), std::string::npos) << r.output;
    // The scene file a link out of its folder: refused as not found, its target not parsed.
    fs::create_symlink(root_ + "/secret.txt", in_ + "/evil.sc");
    r = run_process({test::cli_path(), "--untrusted", in_ + "/evil.sc", "-o", root_ + "/out.png", "-q"});
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("cannot read scene file: not found inside its folder"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("SECRET"), std::string::npos) << r.output;
    // A link to a scene inside its folder is fine.
    write_file(in_, "real.sc", mesh_scene("mine.obj"));
    fs::create_symlink("real.sc", in_ + "/alias.sc");
    r = run_process({test::cli_path(), "--untrusted", in_ + "/alias.sc", "-o", root_ + "/out.png", "--width", "8",
                     "--height", "8", "-q"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
}

// A mesh file is read through the door textures take: at most 32 MiB under --untrusted (a 3 GiB
// sparse OBJ took 6.8 GB), refused from its size; a FIFO is refused at once.
TEST_F(CliUntrustedMesh, SizeLimitAndSpecialFiles) {
    const std::string big = write_file(in_, "big.obj", kTriangle);
    fs::resize_file(big, (std::uintmax_t(32) << 20) + 1);
    auto r = run("big.obj");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("it is 33554433 bytes, more than the limit of 32.0 MiB"), std::string::npos) << r.output;
    ASSERT_EQ(mkfifo((in_ + "/fifo.obj").c_str(), 0600), 0);
    r = run("fifo.obj");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("it is not a regular file"), std::string::npos) << r.output;
}

// The triangles count in the --max-memory estimate (a 64 MB OBJ took 1.48 GB under the 1 GiB
// promise): a mesh needing more than is left is refused, saying so.
TEST_F(CliUntrustedMesh, TrianglesCountAgainstTheMemoryLimit) {
    std::string text;
    for (int i = 0; i < 100000; ++i) {
        const std::string x = std::to_string(i);
        text += "v " + x + " 0 0\nv " + x + " 1 0\nv " + x + " 0 1\nf -3 -2 -1\n";
    }
    write_file(in_, "many.obj", text);
    auto r = run("many.obj", {"--max-memory", "8M"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("the mesh needs more than the"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(--max-memory"), std::string::npos) << r.output;
    EXPECT_EQ(run("many.obj", {"--max-memory", "200M"}).exit_code, 0);
}

}  // namespace
}  // namespace whitted

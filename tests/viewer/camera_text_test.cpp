// The camera written back into scene text: numbers that read back exactly, and the camera block
// replaced with every other byte kept. Checked against the real parser.
#if __has_include("camera_text.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "camera_text.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "flatten/flatten.h"
#include "parse/number.h"
#include "parse/parser.h"
#include "support/run_process.h"

namespace whitted::viewer {
namespace {

namespace fs = std::filesystem;

const char* kRest = "mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]\n";

CameraDesc parsed_camera(const std::string& text) {
    ParseResult r = parse_scene_text(text, "t.sc");
    EXPECT_TRUE(r.ok()) << text << (r.diagnostics.empty() ? "" : r.diagnostics[0].str());
    return r.scene.camera;
}

void expect_same_camera(const CameraDesc& a, const CameraDesc& b) {
    const Camera ca = make_camera(a), cb = make_camera(b);
    EXPECT_EQ(ca.eye, cb.eye);
    EXPECT_EQ(ca.forward, cb.forward);
    EXPECT_EQ(ca.right, cb.right);
    EXPECT_EQ(ca.up, cb.up);
    EXPECT_EQ(ca.tan_half_fov, cb.tan_half_fov);
    EXPECT_EQ(ca.lens_radius, cb.lens_radius);
    if (!ca.is_pinhole()) {
        EXPECT_EQ(ca.focal_distance, cb.focal_distance);  // a pinhole ray does not use it
    }
}

// The numbers of a vector as a block writes them.
std::string V(glm::vec3 v) { return format_number(v.x) + " " + format_number(v.y) + " " + format_number(v.z); }

CameraDesc odd_camera() {
    CameraDesc c;
    c.eye = {0.1f, -1.0f / 3.0f, 12345.678f};
    c.focus = {1e-7f, 2.5f, -0.3f};
    c.use_focus = true;
    c.up = {0.01f, 1, 0.2f};
    c.angle_deg = 37.123456f;
    return c;
}

TEST(CameraText, NumbersReadBackExactlyAsTheParserReadsThem) {
    std::mt19937 rng(12);
    std::uniform_int_distribution<std::uint32_t> bits;
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        float v;
        const std::uint32_t b = bits(rng);
        std::memcpy(&v, &b, sizeof v);
        if (!std::isfinite(v)) continue;
        const std::string s = format_number(v);
        const NumberParse p = parse_number(s);
        ASSERT_EQ(p.status, NumberStatus::Ok) << s;
        ASSERT_EQ(p.value, v == 0.0f ? 0.0f : v) << s;  // -0 is written 0
        ++checked;
    }
    EXPECT_GT(checked, 19000);
    EXPECT_EQ(format_number(0.1f), "0.1");
    EXPECT_EQ(format_number(-2.0f), "-2");
    EXPECT_EQ(format_number(-0.0f), "0");
}

TEST(CameraText, TheBlockReadsBackAsTheSameCamera) {
    CameraDesc c = odd_camera();
    const std::string block = camera_block(c);
    EXPECT_EQ(block.rfind("camera [ eye ", 0), 0u) << block;
    EXPECT_EQ(block.find("aperture"), std::string::npos) << block;
    expect_same_camera(parsed_camera(block + "\n" + kRest), c);

    c.aperture = 0.25f;  // a lens: its distance in focus is stated
    const std::string lens = camera_block(c);
    EXPECT_NE(lens.find("aperture 0.25 focaldistance "), std::string::npos) << lens;
    expect_same_camera(parsed_camera(lens + "\n" + kRest), c);
}

// Only the numbers that change are rewritten, and what the block lacks is added before its `]`:
// its comment, line breaks and tabs stay, and so does every byte around it.
TEST(CameraText, TheCameraBlockIsEditedInPlaceKeepingItsCommentsAndLayout) {
    const std::string before = "# a scene\n# camera [ eye 9 9 9 ]  (a comment, not a block)\n\tlight[position 1 2 3]\n";
    const std::string old_block = "camera[eye 0 0 5  # the eye\n   focus 0 0 0\tangle 40]";
    const std::string after =
        "\r\nmastersubgraph camera [ trans [ object cube [ texture camera 0 0 ] ] ]\n"
        "mastersubgraph root [ trans [ subgraph camera ] ]\n";
    const CameraDesc c = odd_camera();
    const CameraReplacement r = replace_camera_block(before + old_block + after, c);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.blocks, 1);
    const std::string block = "camera[eye " + V(c.eye) + "  # the eye\n   focus " + V(c.focus) + "\tangle " +
                              format_number(c.angle_deg) + " up " + V(c.up) + "]";
    EXPECT_EQ(r.block, block);
    EXPECT_EQ(r.text, before + block + after);
}

TEST(CameraText, NumbersThatHoldAreKeptAsWritten) {
    const std::string text = std::string("camera [ eye 0 0 5.0   # mine\n focus 0 0 0 ]\n") + kRest;
    CameraDesc c = parsed_camera(text);
    c.angle_deg = 30;
    const CameraReplacement r = replace_camera_block(text, c);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.block, "camera [ eye 0 0 5.0   # mine\n focus 0 0 0 angle 30 ]");
    EXPECT_EQ(r.text, r.block + "\n" + kRest);
}

TEST(CameraText, ALookBecomesAFocusWhereItStands) {
    const std::string text = std::string("camera [ eye 0 1 6 look 0 0 -1 angle 40 ]\n") + kRest;
    CameraDesc c = parsed_camera(text);
    c.focus = {0, 0, 0};
    c.use_focus = true;
    const CameraReplacement r = replace_camera_block(text, c);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.block, "camera [ eye 0 1 6 focus 0 0 0 angle 40 ]");
    expect_same_camera(parsed_camera(r.text), c);
}

TEST(CameraText, ABlockWithoutItsOpeningBracketIsFound) {
    const std::string text = std::string("camera eye 0 0 5 focus 0 0 0 ]\n") + kRest;
    const CameraDesc c = odd_camera();
    const CameraReplacement r = replace_camera_block(text, c);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.text, "camera eye " + V(c.eye) + " focus " + V(c.focus) + " up " + V(c.up) + " angle " +
                          format_number(c.angle_deg) + " ]\n" + kRest);
}

TEST(CameraText, WithSeveralBlocksTheLastIsEditedToOverrideWhatTheEarlierOnesSet) {
    // §5: blocks merge keyword by keyword, later ones winning; the first sets a lens.
    const std::string first = "camera [ eye 1 1 1 aperture 0.5 focaldistance 3 near-far 1 50 ]\n";
    const std::string middle = std::string("light [ position 0 5 0 ]\n");
    const std::string text = first + middle + "camera [ angle 30 ]\n" + kRest;
    const CameraDesc c = odd_camera();
    const CameraReplacement r = replace_camera_block(text, c);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.blocks, 2);
    // The pinhole must be stated (the first block's lens would stay), its distance in focus need not.
    const std::string block = "camera [ angle " + format_number(c.angle_deg) + " eye " + V(c.eye) + " focus " +
                              V(c.focus) + " up " + V(c.up) + " near-far 0.1 1000 aperture 0 ]";
    EXPECT_EQ(r.block, block);
    EXPECT_EQ(r.text, first + middle + block + "\n" + kRest);
    expect_same_camera(parsed_camera(r.text), c);
}

// Two pinhole blocks: nothing about a lens is added (the block shown is the block written).
TEST(CameraText, WithSeveralPinholeBlocksNoLensIsStated) {
    const std::string first = "camera [ eye 1 1 1 up 0 1 0 ]\n";
    const std::string text = first + "camera [ angle 30 ]\n" + kRest;
    const CameraDesc c = odd_camera();
    const CameraReplacement r = replace_camera_block(text, c);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.block, "camera [ angle " + format_number(c.angle_deg) + " eye " + V(c.eye) + " focus " + V(c.focus) +
                           " up " + V(c.up) + " ]");
    EXPECT_EQ(r.text, first + r.block + "\n" + kRest);
    expect_same_camera(parsed_camera(r.text), c);
}

// A lens: its distance in focus is stated only when the file would give another one.
TEST(CameraText, ALensStatesItsFocalDistanceOnlyWhereTheFileWouldDiffer) {
    CameraDesc c = parsed_camera(std::string("camera [ eye 0 0 5 focus 0 0 0 ]\n") + kRest);
    c.aperture = 0.25f;  // in focus at |focus - eye| = 5, the default distance of this camera
    const CameraReplacement plain = replace_camera_block(std::string("camera [ eye 0 0 5 focus 0 0 0 ]\n") + kRest, c);
    ASSERT_EQ(plain.error, "");
    EXPECT_EQ(plain.block, "camera [ eye 0 0 5 focus 0 0 0 aperture 0.25 ]");
    expect_same_camera(parsed_camera(plain.text), c);

    const std::string first = "camera [ focaldistance 3 ]\n";  // an earlier block moves the plane in focus
    const CameraReplacement r = replace_camera_block(first + "camera [ eye 0 0 5 focus 0 0 0 ]\n" + kRest, c);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.block, "camera [ eye 0 0 5 focus 0 0 0 aperture 0.25 focaldistance 5 ]");
    expect_same_camera(parsed_camera(r.text), c);
}

TEST(CameraText, AFileWithoutACameraGetsOneAtTheTop) {
    const CameraReplacement r = replace_camera_block(kRest, odd_camera());
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.blocks, 0);
    EXPECT_EQ(r.text, camera_block(odd_camera()) + "\n" + kRest);
    expect_same_camera(parsed_camera(r.text), odd_camera());
}

TEST(CameraText, AnUnclosedCameraBlockIsAnErrorNotAGuess) {
    const CameraReplacement r = replace_camera_block("camera [ eye 0 0 5\n", odd_camera());
    EXPECT_NE(r.error, "");
}

TEST(CameraText, SavingReplacesTheBlockAtomicallyAndKeepsThePermissions) {
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/s.sc";
    const std::string text = std::string("# mine\ncamera [ eye 0 0 5 ]\n") + kRest;
    std::ofstream(path) << text;
    ASSERT_EQ(chmod(path.c_str(), 0640), 0);
    EXPECT_EQ(save_camera_into_file(path, odd_camera()), "");
    std::ifstream in(path);
    std::stringstream got;
    got << in.rdbuf();
    EXPECT_EQ(got.str(), "# mine\n" + camera_block(odd_camera()) + "\n" + kRest);
    struct stat st{};
    ASSERT_EQ(stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1) << "no temporary file is left behind";

    // A file it cannot make sense of is left as it was.
    const std::string bad = "camera [ eye 0 0 5\n";
    std::ofstream(path, std::ios::trunc) << bad;
    EXPECT_NE(save_camera_into_file(path, odd_camera()), "");
    std::ifstream again(path);
    std::stringstream kept;
    kept << again.rdbuf();
    EXPECT_EQ(kept.str(), bad);
    EXPECT_NE(save_camera_into_file(dir + "/missing.sc", odd_camera()), "");
}

// The block the user was asked about is the one written: a file changed after the question is
// not written over.
TEST(CameraText, APlannedSaveIsNotWrittenOverAFileChangedSince) {
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/s.sc";
    const std::string text = std::string("camera [ eye 0 0 5 ]\n") + kRest;
    std::ofstream(path) << text;
    const CameraSave plan = plan_camera_save(path, odd_camera());
    ASSERT_EQ(plan.error, "");
    const std::string edited = std::string("camera [ eye 0 0 6 ]\n") + kRest;
    std::ofstream(path, std::ios::trunc) << edited;
    EXPECT_NE(commit_camera_save(plan), "");
    std::ifstream in(path);
    std::stringstream kept;
    kept << in.rdbuf();
    EXPECT_EQ(kept.str(), edited);

    std::ofstream(path, std::ios::trunc) << text;
    EXPECT_EQ(commit_camera_save(plan), "");
    std::ifstream again(path);
    std::stringstream written;
    written << again.rdbuf();
    EXPECT_EQ(written.str(), plan.replacement.text);
    EXPECT_NE(written.str().find(plan.replacement.block), std::string::npos);
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Save camera into a scene reached through a symbolic link replaced the link
// with a new file and left the scene itself as it was; into one with two hard links, it broke the
// link. The file itself gets the camera, keeping its permissions; the link stays a link, and
// every name of a hard-linked file sees the new text.
TEST(CameraText, SavingThroughALinkOrIntoAHardLinkedFileWritesTheFileItself) {
    const std::string dir = test::make_temp_dir();
    fs::create_directories(dir + "/real");
    const std::string real = dir + "/real/s.sc", via = dir + "/link.sc";
    const std::string text = std::string("camera [ eye 0 0 5 ]\n") + kRest;
    const std::string want = camera_block(odd_camera()) + "\n" + kRest;
    std::ofstream(real) << text;
    ASSERT_EQ(chmod(real.c_str(), 0600), 0);
    fs::create_symlink("real/s.sc", via);
    ASSERT_EQ(save_camera_into_file(via, odd_camera()), "");
    EXPECT_TRUE(fs::is_symlink(via));
    EXPECT_EQ(read_text(real), want);
    struct stat st {};
    ASSERT_EQ(stat(real.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u);
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir + "/real")) ++files;
    EXPECT_EQ(files, 1) << "no temporary file is left behind";

    const std::string other = dir + "/other-name.sc";
    std::ofstream(real, std::ios::trunc) << text;
    ASSERT_EQ(link(real.c_str(), other.c_str()), 0);
    ASSERT_EQ(save_camera_into_file(other, odd_camera()), "");
    EXPECT_EQ(read_text(other), want);
    EXPECT_EQ(read_text(real), want);
    ASSERT_EQ(stat(real.c_str(), &st), 0);
    EXPECT_EQ(st.st_nlink, 2u);
    EXPECT_EQ(st.st_mode & 0777, 0600u);
}

}  // namespace
}  // namespace whitted::viewer
#endif

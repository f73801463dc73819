// `whitted grade SCENES SUBMISSIONS -o REPORT` as a teacher runs it, on a class made here: two
// scenes, a student who hands in whitted's own images, one whose images have named mistakes (one
// bounce short, upside down), one who hands in nothing. The CSV and JSON rows, explain's verdicts,
// the exit codes, a broken scene reported in its row, and the page as headless Chromium shows it.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/json.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::Json;
using test::run_process;

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image im(w, h);
    for (std::size_t i = 0; i < im.rgb.size(); i += 3) im.rgb[i] = r, im.rgb[i + 1] = g, im.rgb[i + 2] = b;
    return im;
}

struct CliGrade : ::testing::Test {
    std::string dir = test::make_temp_dir();
    std::string scenes = dir + "/scenes", subs = dir + "/subs", out = dir + "/report";
    void SetUp() override {
        fs::create_directories(scenes);
        fs::create_directories(subs);
        fs::copy_file(test::source_dir() + "/scenes/features/reflection.sc", scenes + "/mirror.sc");
        fs::copy_file(test::source_dir() + "/scenes/features/shapes.sc", scenes + "/shapes.sc");
    }
    void TearDown() override { fs::remove_all(dir); }
    test::ProcessResult whitted(std::vector<std::string> args) {
        args.insert(args.begin(), test::cli_path());
        return run_process(args);
    }
    // whitted's own render of a scene at 48x36 into a student's folder.
    void render(const std::string& scene, const std::string& student, std::vector<std::string> extra = {}) {
        fs::create_directories(subs + "/" + student);
        std::vector<std::string> args{scenes + "/" + scene + ".sc", "-q", "--width", "48", "--height", "36",
                                      "-o", subs + "/" + student + "/" + scene + ".png"};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto r = whitted(args);
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    void flip_vertically(const std::string& path) {
        Image im;
        ASSERT_EQ(read_image(path, im), "");
        Image f(im.width, im.height);
        for (int y = 0; y < im.height; ++y)
            std::copy_n(&im.rgb[std::size_t(im.height - 1 - y) * im.width * 3], im.width * 3,
                        &f.rgb[std::size_t(y) * im.width * 3]);
        ASSERT_EQ(write_image(f, path), "");
    }
    // The class is graded with --max-depth 3 (a render setting, as `whitted` takes it): at 48x36 the
    // mirror scene's fourth bounce changes no pixel, its third does.
    void make_class() {
        render("mirror", "alice", {"--max-depth", "3"});
        render("shapes", "alice", {"--max-depth", "3"});
        render("mirror", "bob", {"--max-depth", "2"});  // one bounce short
        render("shapes", "bob");
        flip_vertically(subs + "/bob/shapes.png");
        fs::create_directories(subs + "/carol");  // hands in nothing
    }
    const Json* cell(const Json& j, const std::string& scene, const std::string& student) {
        for (const Json& c : j["cells"].array)
            if (c["scene"].string == scene && c["student"].string == student) return &c;
        return nullptr;
    }
};

TEST_F(CliGrade, AClassOfTwoScenesAndThreeStudents) {
    make_class();
    const auto r = whitted({"grade", scenes, subs, "-o", out, "--max-depth", "3"});
    EXPECT_EQ(r.exit_code, 2) << r.output;  // bob fails, carol is missing
    ASSERT_TRUE(fs::exists(out + "/index.html"));
    ASSERT_TRUE(fs::exists(out + "/report.csv"));
    const Json j = Json::parse(slurp(out + "/report.json"));
    EXPECT_EQ(j["exit_code"].number, 2);
    ASSERT_EQ(j["cells"].array.size(), 6u);

    for (const char* scene : {"mirror", "shapes"}) {
        const Json* a = cell(j, scene, "alice");
        ASSERT_TRUE(a) << scene;
        EXPECT_EQ((*a)["result"].string, "pass") << scene;
        EXPECT_TRUE((*a)["psnr"].is_null()) << scene;  // identical: infinite PSNR
        EXPECT_EQ((*a)["flip_mean"].number, 0.0) << scene;
        EXPECT_EQ((*a)["explanation"].string, "") << scene;  // --explain failing: a pass is not explained
        EXPECT_TRUE(fs::exists(out + "/" + (*a)["image"].string));
        EXPECT_TRUE(fs::exists(out + "/" + (*a)["reference"].string));

        const Json* c = cell(j, scene, "carol");
        ASSERT_TRUE(c);
        EXPECT_EQ((*c)["result"].string, "missing");
        EXPECT_TRUE((*c)["psnr"].is_null());
    }
    const Json* depth = cell(j, "mirror", "bob");
    ASSERT_TRUE(depth);
    EXPECT_EQ((*depth)["result"].string, "fail");
    EXPECT_LT((*depth)["psnr"].number, 60.0);
    EXPECT_GT((*depth)["flip_mean"].number, 0.0);
    EXPECT_NE((*depth)["explanation"].string.find("looks like: recursion one level shallower"), std::string::npos)
        << (*depth)["explanation"].string;
    EXPECT_TRUE(fs::exists(out + "/" + (*depth)["error_image"].string));
    const Json* flipped = cell(j, "shapes", "bob");
    ASSERT_TRUE(flipped);
    EXPECT_EQ((*flipped)["result"].string, "fail");
    EXPECT_LT((*flipped)["ssim_worst"].number, 0.9);
    EXPECT_NE((*flipped)["explanation"].string.find("looks like: the image upside down"), std::string::npos)
        << (*flipped)["explanation"].string;

    // The CSV: a header and a row per cell, rows in scene order, students in name order.
    const std::string csv = slurp(out + "/report.csv");
    EXPECT_EQ(csv.rfind("scene,student,result,psnr,flip_mean,ssim_worst,explanation,problem,scene_file\n", 0), 0u)
        << csv;
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);
    EXPECT_NE(csv.find("\nmirror,alice,pass,inf,0,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nmirror,carol,missing,,,,,no mirror.png,\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nshapes,bob,fail,"), std::string::npos) << csv;
}

TEST_F(CliGrade, ExitCodesPassAndWarn) {
    render("mirror", "alice");
    render("shapes", "alice");
    auto r = whitted({"grade", scenes, subs, "-o", out});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("all pass"), std::string::npos) << r.output;
    render("mirror", "bob", {"--max-depth", "2"});
    render("shapes", "bob");
    // No pixel differs by more than 1: nothing fails, the differences only warn.
    r = whitted({"grade", scenes, subs, "-o", out, "--fail", "1", "--explain", "none"});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    const Json j = Json::parse(slurp(out + "/report.json"));
    EXPECT_EQ((*cell(j, "mirror", "bob"))["result"].string, "warn");
    EXPECT_EQ((*cell(j, "mirror", "bob"))["explanation"].string, "");  // --explain none
}

TEST_F(CliGrade, WrongSizeAndABrokenSceneAreReportedInTheirCells) {
    render("mirror", "alice");
    render("shapes", "alice");
    test::write_file(scenes, "broken.sc", "camera [\n  eye 0 0 oops\n]\n");
    ASSERT_EQ(write_image(solid(10, 8, 9, 9, 9), subs + "/alice/broken.png"), "");
    const auto r = whitted({"grade", scenes, subs, "-o", out, "--width", "48", "--height", "36"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    const Json j = Json::parse(slurp(out + "/report.json"));
    const Json* b = cell(j, "broken", "alice");
    ASSERT_TRUE(b);
    EXPECT_EQ((*b)["result"].string, "scene error");
    EXPECT_NE((*b)["problem"].string.find("broken.sc:2:"), std::string::npos) << (*b)["problem"].string;
    EXPECT_NE((*b)["problem"].string.find(": error: "), std::string::npos) << (*b)["problem"].string;
    EXPECT_EQ((*cell(j, "mirror", "alice"))["result"].string, "pass");

    // With a size given, an image of another size is "wrong size", not rendered at its size.
    fs::remove(scenes + "/broken.sc");
    ASSERT_EQ(write_image(solid(10, 8, 9, 9, 9), subs + "/alice/shapes.png"), "");
    const auto w = whitted({"grade", scenes, subs, "-o", out, "--width", "48", "--height", "36"});
    EXPECT_EQ(w.exit_code, 2) << w.output;
    const Json k = Json::parse(slurp(out + "/report.json"));
    EXPECT_EQ((*cell(k, "shapes", "alice"))["result"].string, "wrong size");
    EXPECT_EQ((*cell(k, "shapes", "alice"))["problem"].string, "10x8, not 48x36");
}

// A student's own scene file beside their image: under a class scene's name, the reference is
// rendered from it (their image is of their scene); under a new name, it is a row of its own, with
// nothing asked of the other students. Loaded as --untrusted loads: files only from their folder.
TEST_F(CliGrade, StudentsOwnScenesAreRenderedForTheirOwnImages) {
    render("mirror", "alice");
    render("shapes", "alice");
    // dave's mirror.sc is the shapes scene: his image of it passes only against a render of it.
    fs::create_directories(subs + "/dave");
    fs::copy_file(scenes + "/shapes.sc", subs + "/dave/mirror.sc");
    auto made = whitted({subs + "/dave/mirror.sc", "-q", "--width", "48", "--height", "36", "-o",
                         subs + "/dave/mirror.png"});
    ASSERT_EQ(made.exit_code, 0) << made.output;
    render("shapes", "dave");
    // And a scene of his own, with its image.
    fs::copy_file(test::source_dir() + "/scenes/features/soft_shadows.sc", subs + "/dave/lamp.sc");
    made = whitted({subs + "/dave/lamp.sc", "-q", "--width", "48", "--height", "36", "-o", subs + "/dave/lamp.png"});
    ASSERT_EQ(made.exit_code, 0) << made.output;
    // A scene of erin's that reads a texture outside her folder: refused, as --untrusted refuses it.
    fs::create_directories(subs + "/erin");
    fs::create_directories(dir + "/outside");
    ASSERT_EQ(write_image(solid(4, 4, 200, 10, 10), dir + "/outside/t.png"), "");
    test::write_file(subs + "/erin", "wall.sc",
                     "camera [ eye 0 0 5 ]\nlight [ type point position 0 0 5 ]\nmastersubgraph root [ trans [\n"
                     "  object sphere [ diffuse 1 1 1 texture ../../outside/t.png 1 1 ]\n] ]\n");
    ASSERT_EQ(write_image(solid(48, 36, 9, 9, 9), subs + "/erin/wall.png"), "");

    const auto r = whitted({"grade", scenes, subs, "-o", out, "--explain", "none"});
    const Json j = Json::parse(slurp(out + "/report.json"));
    const Json* mine = cell(j, "mirror", "dave");
    ASSERT_TRUE(mine);
    EXPECT_EQ((*mine)["result"].string, "pass") << "the reference is his scene's";
    EXPECT_EQ((*mine)["scene_file"].string, "mirror.sc");
    EXPECT_EQ((*cell(j, "shapes", "dave"))["scene_file"].string, "");  // the class's scene
    EXPECT_EQ((*cell(j, "mirror", "alice"))["result"].string, "pass");
    const Json* lamp = cell(j, "lamp", "dave");
    ASSERT_TRUE(lamp);
    EXPECT_EQ((*lamp)["result"].string, "pass");
    EXPECT_EQ(cell(j, "lamp", "alice"), nullptr) << "no cell of another student's own scene";
    const Json* wall = cell(j, "wall", "erin");
    ASSERT_TRUE(wall);
    EXPECT_EQ((*wall)["result"].string, "scene error");
    EXPECT_NE((*wall)["problem"].string.find("not found inside the scene's folder"), std::string::npos)
        << (*wall)["problem"].string;
    // erin misses both class scenes and her own scene fails: 2; the rows of others' scenes count for nobody.
    EXPECT_EQ(r.exit_code, 2) << r.output;
    std::vector<std::string> rows;
    for (const Json& s : j["scenes"].array) rows.push_back(s.string);
    EXPECT_EQ(rows, (std::vector<std::string>{"mirror", "shapes", "lamp", "wall"}));
    const std::string html = slurp(out + "/index.html");
    EXPECT_NE(html.find("rendered from the student's mirror.sc"), std::string::npos);

    // Without erin, every image of the class passes against its own reference: 0.
    fs::remove_all(subs + "/erin");
    EXPECT_EQ(whitted({"grade", scenes, subs, "-o", out, "--explain", "none"}).exit_code, 0);
}

TEST_F(CliGrade, BadUsageExitsFiveAndWritesNothing) {
    EXPECT_EQ(whitted({"grade", dir + "/nowhere", subs, "-o", out}).exit_code, 5);
    EXPECT_EQ(whitted({"grade", scenes, subs, "-o", out, "--explain", "sometimes"}).exit_code, 5);
    EXPECT_EQ(whitted({"grade", subs, subs, "-o", out}).exit_code, 5);  // no NAME.sc there
    EXPECT_FALSE(fs::exists(out));
}

// --timeout (60 s by default, as --untrusted's) is each scene's: one over it gets "time limit" in its
// cells and the run goes on, as for a Ctrl-C it would not. 1 ms is far less than 64 rays a pixel
// over 48x36 pixels take.
TEST_F(CliGrade, AScenePastItsTimeLimitIsReportedInItsCells) {
    render("mirror", "alice");
    fs::remove(scenes + "/shapes.sc");
    const auto r = whitted({"grade", scenes, subs, "-o", out, "--timeout", "0.001", "--aa", "8"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    const Json j = Json::parse(slurp(out + "/report.json"));
    const Json* c = cell(j, "mirror", "alice");
    ASSERT_TRUE(c);
    EXPECT_EQ((*c)["result"].string, "time limit");
    EXPECT_EQ((*c)["problem"].string, "the time limit of 0.001 s (--timeout) ran out rendering this scene");
}

TEST_F(CliGrade, NamesFromTheFileSystemAreEscapedInThePage) {
    render("mirror", "a<b&\"c");
    const auto r = whitted({"grade", scenes, subs, "-o", out, "--explain", "none"});
    EXPECT_EQ(r.exit_code, 2) << r.output;  // shapes is missing
    const std::string html = slurp(out + "/index.html");
    EXPECT_NE(html.find("<th>a&lt;b&amp;&quot;c</th>"), std::string::npos);
    EXPECT_EQ(html.find("a<b&\"c"), std::string::npos);
}

// The page as a browser shows it from a file:// URL: two students whose images are solid colours
// found nowhere else on the page (the report's backgrounds are pale). Their thumbnails must appear
// in the screenshot, 96 px wide as the page's CSS draws a 48-px image, magenta's column left of
// cyan's as the names sort, and the page must log nothing to the console.
TEST_F(CliGrade, TheReportInHeadlessChromium) {
    const std::string chromium = "/usr/bin/chromium";
    if (!fs::exists(chromium)) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh installs it)";
    fs::remove(scenes + "/shapes.sc");
    fs::create_directories(subs + "/m");
    fs::create_directories(subs + "/n");
    ASSERT_EQ(write_image(solid(48, 36, 255, 0, 255), subs + "/m/mirror.png"), "");
    ASSERT_EQ(write_image(solid(48, 36, 0, 255, 255), subs + "/n/mirror.png"), "");
    const auto g = whitted({"grade", scenes, subs, "-o", out, "--explain", "none"});
    ASSERT_EQ(g.exit_code, 2) << g.output;

    const std::string shot = dir + "/shot.png";
    const auto r = run_process({chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                                "--force-device-scale-factor=1", "--user-data-dir=" + dir + "/profile",
                                "--enable-logging=stderr", "--v=0", "--window-size=1000,600",
                                "--screenshot=" + shot, "file://" + fs::absolute(out).string() + "/index.html"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // Chromium logs each console message as "INFO:CONSOLE:LINE"; a failed image load is not one of
    // them (it shows only in the pixels, checked below).
    EXPECT_EQ(r.output.find(":CONSOLE"), std::string::npos) << r.output;
    Image im;
    ASSERT_EQ(read_image(shot, im), "");
    // The bounding box of each colour, and how many pixels have it.
    struct Box {
        int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
        long n = 0;
    };
    auto find = [&](glm::u8vec3 c) {
        Box b;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                if (im.at(x, y) == c) {
                    b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x),
                    b.y1 = std::max(b.y1, y), ++b.n;
                }
        return b;
    };
    const Box m = find({255, 0, 255}), n = find({0, 255, 255});
    EXPECT_EQ(m.n, 96L * 72L);
    EXPECT_EQ(n.n, 96L * 72L);
    EXPECT_EQ(m.x1 - m.x0 + 1, 96);
    EXPECT_EQ(m.y1 - m.y0 + 1, 72);
    EXPECT_LT(m.x1, n.x0);   // the columns in name order
    EXPECT_EQ(m.y0, n.y0);   // in the same row of the table
}

}  // namespace
}  // namespace whitted

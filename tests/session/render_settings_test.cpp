// The one table of render settings: what each front end takes (whitted, whitted-view and
// whitted-mpi on their command lines, or whitted-mpi's refusal with the table's reason), the mode
// defaults, and the checkpoint key that every pixel-changing setting is part of.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "session/render_settings.h"
#include "support/run_process.h"

namespace whitted {
namespace {

// A value other than the default for each setting, as text on a command line ("" for a flag).
std::string other_value(const Setting& s) {
    const std::string name = s.name;
    if (name == "mode") return "path";
    if (name == "missing-textures") return "checker";
    if (name == "texture-path") return "/tmp";
    if (name == "max-memory") return "512M";
    if (name == "timeout" || name == "time-limit") return "100";
    if (name == "aa-threshold" || name == "noise-threshold") return "0.25";
    if (name == "time") return "0.5";
    // The checkpoint comes before the resume in the table: the resume reads the file it made.
    if (name == "checkpoint" || name == "resume") return "/tmp/whitted-settings-test.ckpt";
    if (name == "aov") return "depth";
    if (name == "frames") return "1..2";
    if (name == "fps") return "30";
    if (name == "shutter") return "0,1";
    if (name == "aov-file") return "/tmp/whitted-settings-test-layers.png";
    if (!s.choices.empty()) return s.choices.back();  // the defaults come first
    if (std::holds_alternative<bool RenderSettings::*>(s.field)) return "";
    return std::to_string(int(s.min) + 2);  // ints: a value in range other than the default
}

TEST(RenderSettings, ModeDefaultsApplyOnlyWhereTheUserGaveNothing) {
    RenderSettings s;
    s.mode = "path";
    apply_mode_defaults(s);
    EXPECT_EQ(s.spp, 64);
    EXPECT_EQ(s.max_depth, 64);
    RenderSettings t;
    t.mode = "path";
    t.spp = 4;
    t.given = {"spp"};
    apply_mode_defaults(t);
    EXPECT_EQ(t.spp, 4);
    EXPECT_EQ(t.max_depth, 64);
    t.mode = "whitted";  // back: the lab model's depth, the user's samples
    apply_mode_defaults(t);
    EXPECT_EQ(t.spp, 4);
    EXPECT_EQ(t.max_depth, 5);
}

TEST(RenderSettings, AaThresholdWithSamplesIsTheNoiseThreshold) {
    RenderSettings s;
    s.aa_threshold = 0.1f;
    s.spp = 16;
    EXPECT_EQ(validate(s), "");
    EXPECT_EQ(s.noise_threshold, 0.1f);
    EXPECT_EQ(s.aa_threshold, 0.0f);
    RenderSettings one;
    one.noise_threshold = 0.1f;
    EXPECT_NE(validate(one).find("--spp 2 or more"), std::string::npos);
}

// Every setting that changes pixels is in the key a checkpoint is made for (a resume after a
// change of any of them is refused); the thread count is not.
// --shutter T0,T1: an interval of scene time relative to the image's (--time, or each frame's),
// refused where its rays would not carry the sample's time yet.
TEST(RenderSettings, ShutterIsAnIntervalRelativeToTheImagesTime) {
    for (const char* bad : {"1", "1,", ",1", "a,b", "2,1", "0,inf", "0,1,2", "0;1"}) {
        RenderSettings s;
        s.shutter = bad;
        EXPECT_NE(validate(s).find("--shutter " + std::string(bad) + " is not an interval"), std::string::npos) << bad;
    }
    RenderSettings s;
    s.shutter = "-0.25,0.5";
    s.time = 2;
    EXPECT_EQ(validate(s), "");
    const LoadOptions lo = make_load_options(s);
    EXPECT_TRUE(lo.shutter);
    EXPECT_EQ(lo.time, 2.0f);
    EXPECT_EQ(lo.shutter_open, -0.25f);
    EXPECT_EQ(lo.shutter_close, 0.5f);
    EXPECT_FALSE(make_load_options(RenderSettings{}).shutter);  // the default: the instant
    for (const char* mode : {"path", "raycast", "normals", "depth"}) {  // every mode's rays carry the time
        s.mode = mode;
        EXPECT_EQ(validate(s), "") << mode;
    }
    s.mode = "whitted";
    for (const char* filter : {"trilinear", "ewa"}) {  // the footprint follows a moving object
        s.texture_filter = filter;
        EXPECT_EQ(validate(s), "") << filter;
    }
}

TEST(RenderSettings, EverySettingThatChangesPixelsChangesTheCheckpointKey) {
    const RenderSettings base;
    for (const Setting& setting : render_settings_table()) {
        SCOPED_TRACE(setting.name);
        RenderSettings changed = base;
        std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(changed.*member)>;
                if constexpr (std::is_same_v<T, bool>) changed.*member = !(changed.*member);
                else if constexpr (std::is_same_v<T, std::string>) changed.*member = other_value(setting);
                else if constexpr (std::is_same_v<T, std::vector<std::string>>) changed.*member = {"/tmp"};
                else changed.*member = T(changed.*member + 1);
            },
            setting.field);
        EXPECT_EQ(pixel_key(changed) != pixel_key(base), setting.changes_pixels);
    }
    EXPECT_NE(pixel_key(base).find("time="), std::string::npos) << "a change of --time changes the frame";
}

TEST(RenderSettings, EveryFrontEndTakesEverySettingOrRefusesItWithAReason) {
    const std::string cli_help = test::run_process({test::cli_path(), "--help"}).output;
#ifdef WHITTED_VIEWER_PATH
    const std::string view_help = test::run_process({WHITTED_VIEWER_PATH, "--help"}).output;
#endif
#ifdef WHITTED_MPI_PATH
    // Open MPI's own allocations outlive MPI_Finalize: no leak check of whitted-mpi (as tests/mpi/mpi_test.sh).
    const char* asan = std::getenv("ASAN_OPTIONS");
    const std::string no_leak_check =
        "ASAN_OPTIONS=" + std::string(asan ? asan : "") + (asan ? ":" : "") + "detect_leaks=0";
    const std::vector<std::string> mpirun = {"/usr/bin/env", no_leak_check, "/usr/bin/mpirun", "--oversubscribe",
                                             "--allow-run-as-root", "--mca", "btl", "self,vader", "-np", "1",
                                             WHITTED_MPI_PATH};
    std::vector<std::string> help = mpirun;
    help.push_back("--help");
    const std::string mpi_help = test::run_process(help).output;
#endif
    const std::string scene = std::string(WHITTED_SOURCE_DIR) + "/scenes/features/shapes.sc";
    for (const Setting& setting : render_settings_table()) {
        SCOPED_TRACE(setting.name);
        const std::string flag = "--" + std::string(setting.name);
        EXPECT_NE(cli_help.find(flag), std::string::npos) << "whitted does not take " << flag;
#ifdef WHITTED_VIEWER_PATH
        EXPECT_NE(view_help.find(flag), std::string::npos) << "whitted-view does not take " << flag;
#endif
        // whitted renders with it.
        std::vector<std::string> args = {test::cli_path(), scene, "-o", "/tmp/whitted-settings-test.png", "-q", flag};
        if (const std::string v = other_value(setting); !v.empty()) args.push_back(v);
        if (std::string(setting.name) == "noise-threshold") args.insert(args.end(), {"--spp", "4"});
        if (std::string(setting.name) != "width") args.insert(args.end(), {"--width", "8"});
        if (std::string(setting.name) != "height") args.insert(args.end(), {"--height", "6"});
        std::vector<std::string> whitted = args;  // --aov-file names where --aov's layers go
        if (std::string(setting.name) == "aov-file") whitted.insert(whitted.end(), {"--aov", "depth"});
        if (std::string(setting.name) == "fps") whitted.insert(whitted.end(), {"--frames", "1..2"});
        const auto r = test::run_process(whitted);
        EXPECT_EQ(r.exit_code, 0) << r.output;
#ifdef WHITTED_VIEWER_PATH
        // whitted-view refuses what it cannot honour, before it opens a window, with the table's reason.
        if (setting.refused(Frontend::Viewer)) {
            std::vector<std::string> view = {WHITTED_VIEWER_PATH, scene, flag};
            if (const std::string v = other_value(setting); !v.empty()) view.push_back(v);
            const auto v = test::run_process(view);
            EXPECT_EQ(v.exit_code, 1) << v.output;
            EXPECT_NE(v.output.find(flag + " is not for this program: " + setting.why_refused(Frontend::Viewer)),
                      std::string::npos)
                << v.output;
        }
#endif
#ifdef WHITTED_MPI_PATH
        if (!setting.refused(Frontend::Mpi)) {
            EXPECT_NE(mpi_help.find(flag), std::string::npos) << "whitted-mpi does not take " << flag;
            continue;
        }
        std::vector<std::string> refused = mpirun;
        refused.insert(refused.end(), args.begin() + 1, args.end());
        const auto m = test::run_process(refused);
        EXPECT_EQ(m.exit_code, 1) << m.output;
        EXPECT_NE(m.output.find(flag + " is not for this program: " + setting.refusal), std::string::npos) << m.output;
#endif
    }
    std::remove("/tmp/whitted-settings-test.png");
    for (const char* frame : {"/tmp/whitted-settings-test.0001.png", "/tmp/whitted-settings-test.0002.png"})
        std::remove(frame);
    std::remove("/tmp/whitted-settings-test.ckpt");
    std::remove("/tmp/whitted-settings-test.depth.png");
    std::remove("/tmp/whitted-settings-test-layers.depth.png");
}

}  // namespace
}  // namespace whitted

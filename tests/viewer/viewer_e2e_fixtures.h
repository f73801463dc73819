#pragma once
// whitted-view's end-to-end tests: the fixtures (a scene in a temporary folder; the viewer on its own
// X server; the workbench's mouse and keys) and the scenes they render.
#include "viewer/viewer_e2e_support.h"

namespace whitted::viewer_e2e {

inline const char* kScene = R"(camera [ eye 0 1 6 focus 0 0 0 angle 40 ]
light [ position 3 4 5 color 1 1 1 ]
light [ position -4 2 3 color 0.4 0.4 0.6 ]
background [ color 0.1 0.15 0.3 ]
mastersubgraph root [
  trans [ translate -1.2 0 0  object sphere [ diffuse 0.9 0.2 0.1 specular 0.5 0.5 0.5 shine 30 reflect 0.3 0.3 0.3 ] ]
  trans [ translate 1.2 0 0 rotate 0 1 0 30 object cube [ diffuse 0.2 0.7 0.3 ] ]
  trans [ translate 0 -1 0 scale 8 0.1 8 object cube [ diffuse 0.6 0.6 0.6 reflect 0.4 0.4 0.4 ] ]
  trans [ translate 0 1.2 -1 object cone [ diffuse 0.9 0.8 0.2 ] ]
]
)";

class ViewerE2E : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test::make_temp_dir();
        scene_ = dir_ + "/scene.sc";
        std::ofstream(scene_) << kScene;
    }
    std::string dir_, scene_;
};

// A one-sphere scene in the given diffuse colour: quick to render, easy to tell apart.
inline std::string sphere_scene(const std::string& diffuse, const std::string& texture = "") {
    return "camera [ eye 0 0 5 focus 0 0 0 angle 40 ]\n"
           "light [ position 3 4 5 color 1 1 1 ]\n"
           "background [ color 0.1 0.1 0.1 ]\n"
           "mastersubgraph root [ trans [ object sphere [ diffuse " + diffuse +
           (texture.empty() ? "" : " texture " + texture + " 1 1") + " ] ] ]\n";
}

// The command-line renderer's image of `scene` at W×H.
inline Image cli_image(const std::string& scene, int W, int H, const std::string& png) {
    auto cli = run_process({test::cli_path(), scene, "-o", png, "--width", std::to_string(W), "--height",
                            std::to_string(H), "-q"});
    EXPECT_EQ(cli.exit_code, 0) << cli.output;
    Image img;
    EXPECT_EQ(read_image(png, img), "");
    return img;
}

// Rewrites a file in place with text of the same length (as an editor saving a colour change)
// and moves its modification time on, whatever the file system's timestamp resolution.
inline void rewrite_scene(const std::string& path, const std::string& text) {
    const auto before = fs::last_write_time(path);
    std::ofstream(path) << text;
    fs::last_write_time(path, before + 2s);
}

class ViewerOnScreen : public ViewerE2E {
protected:
    void SetUp() override {
        ViewerE2E::SetUp();
        ready_ = dir_ + "/ready.txt";
        WHITTED_NEEDS(test::kSkipViewerTests, x_.start(dir_, why_) ? "" : "no X server for the screen test: " + why_);
        WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xwd", "convert"}));
        std::ofstream(scene_) << sphere_scene("0.9 0.1 0.1");
        red_ = cli_image(scene_, kW, kH, dir_ + "/red.png");
        std::ofstream(dir_ + "/blue.sc") << sphere_scene("0.1 0.1 0.9");
        blue_ = cli_image(dir_ + "/blue.sc", kW, kH, dir_ + "/blue.png");
    }
    std::unique_ptr<Child> start_viewer(const std::vector<std::string>& extra) {
        EXPECT_TRUE(x_.ensure_running(dir_, why_)) << why_;
        std::vector<std::string> argv{WHITTED_VIEWER_PATH, scene_, "--width", std::to_string(kW), "--height",
                                      std::to_string(kH), "--threads", "2", "--ready-file", ready_};
        argv.insert(argv.end(), extra.begin(), extra.end());
        return std::make_unique<Child>(argv, dir_ + "/viewer.log",
                                       std::vector<std::pair<std::string, std::string>>{
                                           {"DISPLAY", x_.display()},
                                           {"ASAN_OPTIONS", asan_options_for_viewer()},
                                           {"WHITTED_VIEW_TEST_DIR", dir_}});  // see processes_left()
    }
    // Processes the viewer started (it included) that are still running: they have its environment.
    std::vector<pid_t> processes_left() const {
        const std::string marker = "WHITTED_VIEW_TEST_DIR=" + dir_;
        std::vector<pid_t> left;
        for (const auto& entry : fs::directory_iterator("/proc")) {
            const std::string name = entry.path().filename().string();
            if (name.find_first_not_of("0123456789") != std::string::npos) continue;
            std::ifstream in(entry.path() / "environ");
            for (std::string var; std::getline(in, var, '\0');)
                if (var == marker) left.push_back(pid_t(std::stoi(name)));
        }
        return left;
    }
    static constexpr int kW = 160, kH = 120;
    Xvfb x_;
    std::string why_, ready_;
    Image red_, blue_;
};

class ViewerWorkbench : public ViewerOnScreen {
protected:
    void SetUp() override {
        ViewerOnScreen::SetUp();
        WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    }
    // A real left drag with the mouse from the image's centre, `dx` pixels to the right.
    void drag(const Ready& r, int dx) {
        const int cx = r.image.x + r.image.w / 2, cy = r.image.y + r.image.h / 2;
        std::string moves;
        for (int step = 1; step <= 4; ++step) moves += " mousemove " + std::to_string(cx + dx * step / 4) + " " + std::to_string(cy) + " sleep 0.05";
        xdotool(x_.display(), "mousemove " + std::to_string(cx) + " " + std::to_string(cy) + " mousedown 1" + moves +
                                  " mouseup 1");
    }
    void keys(const std::string& k) {
        const std::string window = xdotool(x_.display(), "search --name whitted-view");
        xdotool(x_.display(), "windowfocus --sync " + window + " key " + k);
    }
    static constexpr const char* kShapes = R"(camera [ eye 0 1 6 focus 0 0 0 angle 40 ]
light [ position 3 4 5 color 1 1 1 ]
background [ color 0.1 0.15 0.3 ]
mastersubgraph root [
  trans [ translate -1.2 0 0  object sphere [ diffuse 0.9 0.2 0.1 specular 0.5 0.5 0.5 shine 30 ] ]
  trans [ translate 1.2 0 0 rotate 0 1 0 30 object cube [ diffuse 0.2 0.7 0.3 ] ]
  trans [ translate 0 -1 0 scale 8 0.1 8 object cube [ diffuse 0.6 0.6 0.6 ] ]
]
)";
};

}  // namespace whitted::viewer_e2e

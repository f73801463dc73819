// The viewer window's commands that ask something: scene time, missing textures, open, save image,
// and the camera's way back into the scene text (copy, save into the scene).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <FL/Fl.H>
#include <FL/fl_ask.H>

#include "camera_text.h"
#include "file_chooser.h"
#include "film/image_io.h"
#include "inspect_action.h"
#include "inspector_window.h"
#include "texture_dialog.h"
#include "viewer_util.h"
#include "viewer_window.h"

namespace whitted::viewer {
namespace {

namespace fs = std::filesystem;

}  // namespace

// Scene time t of `velocity` / `angularrate` (scene-format.md §9.4): asked for, then rendered.
void ViewerWindow::ask_time() {
    char current[32];
    std::snprintf(current, sizeof current, "%g", double(options_.time));
    const char* answer = fl_input("Scene time t ('velocity' moves by t times its vector, 'angularrate' turns by "
                                  "t times its rate; 0 is the still image):", current);
    if (!answer) return;
    char* end = nullptr;
    const float t = std::strtof(answer, &end);
    if (end == answer || !std::isfinite(t)) {
        fl_alert("Not a finite number: %s", answer);
        return;
    }
    options_.time = t;
    render();
}

void ViewerWindow::ask_for_textures(const RenderStatus& st) {
    const TextureAnswers answers = whitted::viewer::ask_for_textures(st.missing_textures, scene_, scene_dir(), textures_,
                                                                     *this, [this] { return quitting_; });
    if (answers.interrupted) return;
    render(true);
    if (!answers.declined.empty())
        set_message("warning: texture " + answers.declined + " drawn as a checkerboard (not found)");
}

void ViewerWindow::choose_and_open() {
    const FileChoice choice = choose_file_to_open("Open scene", "Scenes (*.sc)\tAll Files (*)", scene_dir());
    if (!choice.path.empty()) open_scene(choice.path);
}

void ViewerWindow::save_image_as() {
    if (controller_.image().width == 0) {
        set_message("error: nothing rendered yet");
        return;
    }
    // In the scene's folder, named after it.
    // .exr and .pfm keep the film's linear values, unclamped, as whitted -o does (§7).
    const FileChoice choice = choose_file_to_save(
        "Save image as", "PNG (*.png)\tBMP (*.bmp)\tPPM (*.ppm)\tJPEG (*.{jpg,jpeg})\tOpenEXR (*.exr)\tPFM (*.pfm)",
        scene_dir(), scene_.empty() ? "image.png" : fs::path(scene_).stem().string() + ".png");
    if (choice.path.empty()) return;
    std::string path = choice.path;
    if (fs::path(path).extension().empty()) {  // the extension of the filter shown (PNG for All Files)
        static const char* exts[] = {".png", ".bmp", ".ppm", ".jpg", ".exr", ".pfm"};
        path += exts[choice.filter >= 0 && choice.filter < 6 ? choice.filter : 0];
    }
    if (!is_supported_output(path)) {
        set_message("error: cannot write '" + path + "': use .png, .bmp, .ppm, .jpg, .jpeg, .exr or .pfm");
        return;
    }
    // The image as it is now, when the dialog has closed (the render went on meanwhile), not as it
    // was when it opened; a render still running is saved as it stands, and the message says so.
    const bool partial = is_busy(controller_.status().state);
    const std::string err = is_linear_output(path) ? write_linear_image(controller_.linear_image(), path)
                                                   : write_image(controller_.image(), path);
    // An 8-bit file is what is shown (view transform and exposure); .exr and .pfm keep radiance.
    const std::string kept = exposure_ == 0.0f           ? ""
                             : is_linear_output(path) ? " (the radiance, without the exposure)"
                                                      : " (as shown, with the exposure)";
    set_message(!err.empty() ? "error: " + err
                : partial    ? "saved " + path + kept + " while still rendering: the image is partial"
                             : "saved " + path + kept);
}

// The camera on screen as a `camera [ … ]` block, on the clipboard (and the selection buffer).
void ViewerWindow::copy_camera() {
    const std::optional<CameraDesc> cam = camera_.current();
    if (!cam) {
        set_message("error: no camera yet: open a scene that loads");
        return;
    }
    const std::string text = camera_block(*cam);
    Fl::copy(text.c_str(), int(text.size()), 1);
    Fl::copy(text.c_str(), int(text.size()), 0);
    set_message("copied: " + text);
}

// Writes the camera on screen into the scene file's camera block (asked first, showing the block as
// it will be written; atomic). The file is then loaded again: its camera is now the one on screen,
// the same image.
void ViewerWindow::save_camera_into_scene() {
    if (scene_.empty() || !camera_.current()) {
        set_message("error: no camera to save: open a scene that loads");
        return;
    }
    const CameraSave plan = camera_.plan_save(scene_);
    if (!plan.error.empty()) {
        set_message("error: " + plan.error);
        return;
    }
    fl_message_title("Save camera into scene");
    const std::string question = std::string(plan.replacement.blocks ? "Write the camera on screen into the camera block of "
                                                                     : "Add the camera on screen to the top of ") +
                                 base_name(scene_) + ":\n\n" + plan.replacement.block +
                                 "\n\nEvery other byte of the file stays as it is.";
    const int answer = fl_choice("%s", "Cancel", "Replace", nullptr, question.c_str());
    if (quitting_ || answer != 1) return;
    const std::string err = camera_.save(plan);
    if (!err.empty()) {
        set_message("error: " + err);
        return;
    }
    render(true);
    set_message("saved the camera into " + scene_);
}

// A double-clicked line of the messages panel: the FILE:LINE:COL it names, in the editor (paths
// there are relative to the scene's folder, as in the inspector's report).
void ViewerWindow::open_message_line(const std::string& line) {
    if (const auto loc = location_in_line(line, scene_dir())) open_in_editor(*loc);
}

}  // namespace whitted::viewer

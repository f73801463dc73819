// The viewer window's dialogs: scene time, missing textures, open, save image, and the camera's
// way back into the scene text (copy, save into the scene).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/Fl_Browser.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_Double_Window.H>
#include <FL/Fl_Return_Button.H>
#include <FL/fl_ask.H>
#include <FL/fl_draw.H>

#include "camera_text.h"
#include "file_chooser.h"
#include "film/image_io.h"
#include "viewer_util.h"
#include "viewer_window.h"

namespace whitted::viewer {
namespace {

namespace fs = std::filesystem;

// Asks whether to pick the file for a texture that was not found, listing every path tried (in a
// browser, which scrolls when there are many). 1 = choose a file, 0 = use the checkerboard.
int ask_texture_dialog(const MissingTexture& mt, const std::string& where, const Fl_Window& parent) {
    const int W = 640, line_h = 17, rows = std::clamp(int(mt.tried.size()), 2, 14);
    const std::string about = escape_label("The texture \"" + mt.name + "\" (" + where + ") could not be loaded: " +
                                           mt.reason + ".\n\nLooked at " + std::to_string(mt.tried.size()) +
                                           (mt.tried.size() == 1 ? " place:" : " places:"));
    int text_w = W - 20, text_h = 0;
    fl_font(FL_HELVETICA, FL_NORMAL_SIZE);
    fl_measure(about.c_str(), text_w, text_h);  // wrapped at the dialog's width
    const int list_y = 10 + text_h + 6, list_h = rows * line_h + 6, question_y = list_y + list_h + 6;
    Fl_Double_Window dlg(W, question_y + 24 + 50, "Texture not found");
    auto* text = new Fl_Box(10, 10, W - 20, text_h);
    text->align(FL_ALIGN_LEFT | FL_ALIGN_TOP | FL_ALIGN_INSIDE | FL_ALIGN_WRAP);
    text->copy_label(about.c_str());
    auto* list = new Fl_Browser(10, list_y, W - 20, list_h);
    list->textfont(FL_COURIER);
    list->textsize(13);
    for (const std::string& p : mt.tried) list->add(("@." + p).c_str());
    auto* question = new Fl_Box(10, question_y, W - 20, 24, "Choose the image file to use for it?");
    question->align(FL_ALIGN_LEFT | FL_ALIGN_INSIDE);
    int answer = 0;
    auto* cancel = new Fl_Button(W - 340, dlg.h() - 38, 180, 28, "Cancel (checkerboard)");
    auto* choose = new Fl_Return_Button(W - 150, dlg.h() - 38, 140, 28, "Choose file...");
    cancel->callback([](Fl_Widget* b, void*) { b->window()->hide(); });
    choose->callback([](Fl_Widget* b, void* a) {
        *static_cast<int*>(a) = 1;
        b->window()->hide();
    }, &answer);
    dlg.end();
    dlg.resizable(list);
    dlg.set_modal();
    dlg.position(parent.x() + (parent.w() - dlg.w()) / 2, parent.y() + std::max(0, (parent.h() - dlg.h()) / 2));
    dlg.show();
    // Ends when a button or Escape closes it, or when quitting hides every window.
    while (dlg.shown()) Fl::wait();
    return answer;
}


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
    bool declined = false;
    std::string declined_names;  // for the status bar: which textures are checkerboards now
    std::set<std::string>& declined_here = declined_textures_[scene_];
    for (const MissingTexture& mt : st.missing_textures) {
        if (declined_here.count(mt.name)) continue;  // answered before: drawn as a checkerboard
        std::string where = base_name(mt.loc.file.empty() ? scene_ : mt.loc.file) + " line " + std::to_string(mt.loc.line);
        const int answer = ask_texture_dialog(mt, where, *this);
        if (quitting_) return;
        std::string picked;
        if (answer == 1)
            picked = choose_file_to_open("Texture \"" + mt.name + "\"",
                                         "Images (*.{bmp,png,jpg,jpeg,ppm,pgm,tga,gif,psd,hdr,pic})\tAll Files (*)",
                                         scene_dir())
                         .path;
        if (quitting_) return;
        if (picked.empty()) {
            declined = true;
            declined_here.insert(mt.name);
            declined_names += (declined_names.empty() ? "'" : ", '") + mt.name + "'";
        } else {
            texture_overrides_[scene_][mt.name] = picked;
        }
    }
    if (declined) extra_message_ = "";
    render(true);
    if (declined) set_message("warning: texture " + declined_names + " drawn as a checkerboard (not found)");
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
    const FileChoice choice =
        choose_file_to_save("Save image as", "PNG (*.png)\tBMP (*.bmp)\tPPM (*.ppm)\tJPEG (*.{jpg,jpeg})", scene_dir(),
                            scene_.empty() ? "image.png" : fs::path(scene_).stem().string() + ".png");
    if (choice.path.empty()) return;
    std::string path = choice.path;
    if (fs::path(path).extension().empty()) {  // the extension of the filter shown (PNG for All Files)
        static const char* exts[] = {".png", ".bmp", ".ppm", ".jpg"};
        path += exts[choice.filter >= 0 && choice.filter < 4 ? choice.filter : 0];
    }
    if (!is_supported_output(path)) {
        set_message("error: cannot write '" + path + "': use .png, .bmp, .ppm, .jpg or .jpeg");
        return;
    }
    // The image as it is now, when the dialog has closed (the render went on meanwhile), not as it
    // was when it opened; a render still running is saved as it stands, and the message says so.
    const Image img = controller_.image();
    const bool partial = is_busy(controller_.status().state);
    std::string err = write_image(img, path);
    set_message(!err.empty() ? "error: " + err
                : partial    ? "saved " + path + " while still rendering: the image is partial"
                             : "saved " + path);
}


// The camera on screen as a `camera [ … ]` block, on the clipboard (and the selection buffer).
void ViewerWindow::copy_camera() {
    const std::optional<CameraDesc> cam = current_camera();
    if (!cam) {
        set_message("error: no camera yet: open a scene that loads");
        return;
    }
    const std::string text = camera_block(*cam);
    Fl::copy(text.c_str(), int(text.size()), 1);
    Fl::copy(text.c_str(), int(text.size()), 0);
    set_message("copied: " + text);
}

// Replaces the camera block of the scene file with the camera on screen (asked first; atomic).
// The file is then loaded again: its camera is now the one on screen, the same image.
void ViewerWindow::save_camera_into_scene() {
    const std::optional<CameraDesc> cam = current_camera();
    if (scene_.empty() || !cam) {
        set_message("error: no camera to save: open a scene that loads");
        return;
    }
    fl_message_title("Save camera into scene");
    const std::string question = "Replace the camera block of " + base_name(scene_) +
                                 " with the camera on screen?\n\n" + camera_block(*cam) +
                                 "\n\nEvery other byte of the file stays as it is.";
    const int answer = fl_choice("%s", "Cancel", "Replace", nullptr, question.c_str());
    if (quitting_ || answer != 1) return;
    const std::string err = save_camera_into_file(scene_, *cam);
    if (!err.empty()) {
        set_message("error: " + err);
        return;
    }
    camera_.reset();  // the file's camera is this one now
    render(true);
    set_message("saved the camera into " + scene_);
}

}  // namespace whitted::viewer

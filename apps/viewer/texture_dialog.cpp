#include "texture_dialog.h"

#include <algorithm>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/Fl_Browser.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_Double_Window.H>
#include <FL/Fl_Return_Button.H>
#include <FL/fl_draw.H>

#include "file_chooser.h"
#include "viewer_util.h"

namespace whitted::viewer {
namespace {

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

TextureAnswers ask_for_textures(const std::vector<MissingTexture>& missing, const std::string& scene,
                                const std::string& dir, TextureMemory& memory, const Fl_Window& parent,
                                const std::function<bool()>& quitting) {
    TextureAnswers answers;
    for (const MissingTexture& mt : missing) {
        if (memory.declined(scene, mt.name)) continue;  // answered before: drawn as a checkerboard
        std::string where = base_name(mt.loc.file.empty() ? scene : mt.loc.file) + " line " + std::to_string(mt.loc.line);
        const int answer = ask_texture_dialog(mt, where, parent);
        if (quitting()) return {true, ""};
        std::string picked;
        if (answer == 1)
            picked = choose_file_to_open("Texture \"" + mt.name + "\"",
                                         "Images (*.{bmp,png,jpg,jpeg,ppm,pgm,tga,gif,psd,hdr,pic})\tAll Files (*)",
                                         dir)
                         .path;
        if (quitting()) return {true, ""};
        if (picked.empty()) {
            memory.decline(scene, mt.name);
            answers.declined += (answers.declined.empty() ? "'" : ", '") + mt.name + "'";
        } else {
            memory.pick(scene, mt.name, picked);
        }
    }
    return answers;
}

}  // namespace whitted::viewer

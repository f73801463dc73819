#include "file_chooser.h"

#include <filesystem>

#include <FL/Fl.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_File_Chooser.H>
#include <FL/Fl_Input.H>
#include <FL/fl_ask.H>

namespace whitted::viewer {
namespace {

namespace fs = std::filesystem;

// FLTK 1.3.8's Filename field takes a name typed without a folder as relative to the working
// directory, and then puts the cursor at the start, so that the next key lands before it (typing
// "x.png" gave "/cwd/g/cwd/n/..."). Here such a name is put in the folder shown, cursor kept, before
// FLTK's own handler (completion, Enter) sees it.
struct NameField {
    Fl_File_Chooser* chooser;
    Fl_Callback* fltk_callback;
    void* fltk_data;
};

//
// A path typed from the root ('/', '~' or '$' first) went wrong another way: at each '/' FLTK moved
// the chooser to the folder typed so far (the first '/' to the list of file systems, emptying the
// field) and rewrote the field, garbling it ("/tmp/x/out.png" became "/tmpx/out.png/x/..."). Such a
// path is left alone while it is typed; Enter hands it to FLTK, which opens a folder or takes the file.
void name_typed(Fl_Widget* w, void* data) {
    auto* field = static_cast<NameField*>(data);
    auto* input = static_cast<Fl_Input*>(w);
    const std::string typed = input->value();
    const char* dir = field->chooser->directory();
    const bool from_root = !typed.empty() && (typed[0] == '/' || typed[0] == '~' || typed[0] == '$');
    const bool enter = Fl::event_key() == FL_Enter || Fl::event_key() == FL_KP_Enter;
    if (from_root && !enter) return;
    if (!typed.empty() && !from_root && dir && dir[0]) {
        std::string folder = dir;
        if (folder.back() != '/') folder += '/';
        const int shift = int(folder.size()), position = input->position(), mark = input->mark();
        input->value((folder + typed).c_str());
        input->position(position + shift, mark + shift);
    }
    field->fltk_callback(w, field->fltk_data);
}

FileChoice run(Fl_File_Chooser& chooser, bool save) {
    chooser.preview(0);
    if (!save) chooser.newButton->hide();
    chooser.show();  // the Filename field has the focus now
    NameField field{&chooser, nullptr, nullptr};
    auto* input = dynamic_cast<Fl_Input*>(Fl::focus());
    if (input) {
        field.fltk_callback = input->callback();
        field.fltk_data = input->user_data();
        input->callback(name_typed, &field);
        // A suggested name selected without its folder: what is typed replaces the name only.
        const std::string value = input->value() ? input->value() : "";
        const std::size_t slash = value.rfind('/');
        if (save && slash != std::string::npos) input->position(int(value.size()), int(slash + 1));
    }
    // Ends on OK, Cancel or Escape, or when quitting hides every window.
    while (chooser.shown()) Fl::wait();
    if (input) input->callback(field.fltk_callback, field.fltk_data);
    // Quitting hid every window, the main one too: nothing was chosen (the name field still holds one).
    if (!Fl::first_window()) return {};
    FileChoice choice{chooser.value() ? chooser.value() : "", chooser.filter_value()};
    std::error_code ec;
    if (save && !choice.path.empty() && fs::is_regular_file(choice.path, ec)) {
        fl_message_title("Save");
        if (fl_choice("%s exists. Replace it?", "Cancel", "Replace", nullptr, choice.path.c_str()) != 1)
            choice.path.clear();
    }
    return choice;
}

}  // namespace

FileChoice choose_file_to_open(const std::string& title, const std::string& filters, const std::string& dir) {
    Fl_File_Chooser chooser(dir.c_str(), filters.c_str(), Fl_File_Chooser::SINGLE, title.c_str());
    return run(chooser, false);
}

FileChoice choose_file_to_save(const std::string& title, const std::string& filters, const std::string& dir,
                               const std::string& name) {
    Fl_File_Chooser chooser(dir.c_str(), filters.c_str(), Fl_File_Chooser::CREATE, title.c_str());
    // With its folder: FLTK takes a bare name as relative to the working directory.
    chooser.value((fs::path(dir) / name).string().c_str());
    return run(chooser, true);
}

}  // namespace whitted::viewer

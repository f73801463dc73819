#pragma once
// The viewer's file dialogs: FLTK's own chooser, run in FLTK's event loop (GTK's ran a loop of its
// own, in which the window stopped updating and a render's end went unseen while it was open).
#include <string>

namespace whitted::viewer {

struct FileChoice {
    std::string path;  // "" when cancelled
    int filter = 0;    // the index of the filter shown when it closed
};

// A file to open, starting in `dir`. `filters`: FLTK's form, "Scenes (*.sc)\tAll Files (*)".
FileChoice choose_file_to_open(const std::string& title, const std::string& filters, const std::string& dir);

// A file to save, suggesting `name` in `dir` (the name selected, so that typing replaces it); asks
// before replacing a file that exists.
FileChoice choose_file_to_save(const std::string& title, const std::string& filters, const std::string& dir,
                               const std::string& name);

}  // namespace whitted::viewer

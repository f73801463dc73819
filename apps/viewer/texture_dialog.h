#pragma once
// Asking the user about textures that were not found: for each, a dialog listing every path tried,
// then (if they want) a file chooser. The answers go into the session's TextureMemory.
#include <functional>
#include <string>
#include <vector>

#include "texture_memory.h"

class Fl_Window;

namespace whitted::viewer {

struct TextureAnswers {
    bool interrupted = false;  // quitting ended the questions
    std::string declined;      // the names declined now, "'a', 'b'" ("" = none)
};

// Asks about each of `missing` that was not declined before (those stay checkerboards), in dialogs
// centred on `parent`; the file chooser starts in `dir`. Stops when `quitting` says so.
TextureAnswers ask_for_textures(const std::vector<MissingTexture>& missing, const std::string& scene,
                                const std::string& dir, TextureMemory& memory, const Fl_Window& parent,
                                const std::function<bool()>& quitting);

}  // namespace whitted::viewer

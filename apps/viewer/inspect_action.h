#pragma once
// The viewer's pixel inspector without the display: the report of a pixel of the image the
// render controller shows (its scene, camera and settings), the locations the report's lines
// name, and the command that opens the user's editor at one of them. Tested without a display.
#include <optional>
#include <string>
#include <vector>

#include "inspect/pixel_inspector.h"
#include "render_controller.h"

namespace whitted::viewer {

struct InspectResult {
    bool ok = false;
    std::string message;  // why not, when !ok (no image yet, pixel outside it)
    PixelReport report;
    std::string text;      // report_text, paths relative to the scene's folder
    std::string base_dir;  // that folder
};

// A result that is only a message (no report).
inline InspectResult inspect_message(const std::string& message) {
    InspectResult r;
    r.message = message;
    return r;
}

// Pixel (x, y) of the image shown (column, row; row 0 at the top).
InspectResult inspect_shown_pixel(const RenderController& controller, int x, int y);

// The first FILE:LINE:COL on a line of the report text, resolved against the scene's folder
// (relative paths in the text are relative to it). None when the line names no location.
std::optional<SourceLoc> location_in_line(const std::string& line, const std::string& base_dir);

// $VISUAL if set and not empty, else $EDITOR, else "".
std::string chosen_editor(const char* visual, const char* editor);

// The command (argv) that opens `editor` (as the variable holds it: a program and maybe
// arguments, split at spaces) at loc's line: `EDITOR +LINE FILE`, the form vi, vim, nvim,
// emacs, nano, micro, kak, gedit and kate take; VS Code and its kin get `-g FILE:LINE:COL`.
// Empty when there is no editor or the location has no line.
std::vector<std::string> editor_command(const std::string& editor, const SourceLoc& loc);

// Runs argv detached (its own session, not waited for). False if it could not be started.
bool launch_detached(const std::vector<std::string>& argv);

}  // namespace whitted::viewer

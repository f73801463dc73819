#pragma once
// The pixel inspector's report as text: what `whitted SCENE --inspect X,Y` prints and the
// viewer's inspector window shows. One fact per line, each line starting with what it is
// (docs/inspector.md explains every line).
#include <string>

#include "inspect/pixel_inspector.h"

namespace whitted {

// `file` as shown to the user: relative to `base_dir` (the scene's folder) when it lies inside
// it, as given otherwise (and as given when base_dir is "").
std::string display_path(const std::string& file, const std::string& base_dir);

// "FILE:LINE:COL" with the file shown as display_path gives; "(not from a file)" for a location
// that was not recorded (a scene built in code).
std::string display_loc(const SourceLoc& loc, const std::string& base_dir);

std::string report_text(const PixelReport& report, const std::string& base_dir);

}  // namespace whitted

#pragma once
// scene file → SceneDescription. Never throws, never crashes: problems come back as diagnostics.
#include <string>
#include <string_view>
#include <vector>

#include "parse/diagnostic.h"
#include "scene/scene_description.h"

namespace whitted {

struct ParseOptions {
    // Skip unknown keywords (with the numbers or bracketed block that follow) and unknown
    // object types (with their block), each with a warning, instead of failing.
    bool lenient = false;
};

struct ParseResult {
    SceneDescription scene;            // meaningful only when ok()
    std::vector<Diagnostic> diagnostics;  // warnings and errors in file order
    bool unreadable = false;              // the file itself could not be read (an I/O failure)
    bool ok() const { return !has_errors(diagnostics); }
};

// `file_name` is used in diagnostics and becomes scene.path.
ParseResult parse_scene_text(std::string_view text, const std::string& file_name,
                             const ParseOptions& options = {});

// Reads the file; an unreadable file is an error diagnostic with no position.
ParseResult parse_scene_file(const std::string& path, const ParseOptions& options = {});

}  // namespace whitted

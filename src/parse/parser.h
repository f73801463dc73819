#pragma once
// scene file → SceneDescription. Never throws, never crashes: problems come back as diagnostics.
#include <atomic>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "description/scene_description.h"

namespace whitted {

// Warnings listed in ParseResult::diagnostics, the first in position order; the rest are only
// counted (front ends print this many and the count of the rest).
constexpr std::size_t kMaxWarningsListed = 50;

struct ParseOptions {
    // Skip unknown keywords (with the numbers or bracketed block that follow) and unknown
    // object types (with their block), each with a warning, instead of failing.
    bool lenient = false;
    // The scene time t of `velocity` and `angularrate` (scene-format.md §9.4): 0 is the still image.
    float time = 0;
    // parse_scene_file reads no more than this (a scene of a million objects written out one by
    // one is about 170 MB).
    std::size_t max_file_bytes = std::size_t(256) << 20;
    // Reading and parsing give up when this is set (by another thread or a signal handler): the
    // parse looks at it after every 64 KiB of text.
    const std::atomic<bool>* cancel = nullptr;
};

struct ParseResult {
    SceneDescription scene;            // meaningful only when ok()
    // Warnings and errors ordered by position (the parser recovers after an error and goes on:
    // every problem of the file, up to a limit, then one error giving the count of the rest).
    // At most kMaxWarningsListed warnings, the first in position order.
    std::vector<Diagnostic> diagnostics;
    std::size_t unlisted_warnings = 0;    // warnings past those, only counted
    bool unreadable = false;              // the file itself could not be read (an I/O failure)
    bool cancelled = false;               // ParseOptions::cancel was set while the file was read or parsed
    bool ok() const { return !has_errors(diagnostics); }
};

// `file_name` is used in diagnostics and becomes scene.path.
ParseResult parse_scene_text(std::string_view text, const std::string& file_name,
                             const ParseOptions& options = {});

// Reads the file (a regular file only, at most max_file_bytes); an unreadable file is an error
// diagnostic with no position.
ParseResult parse_scene_file(const std::string& path, const ParseOptions& options = {});

}  // namespace whitted

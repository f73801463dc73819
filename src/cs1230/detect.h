#pragma once
// Which scene files are Brown CSCI 1230's JSON (scene-format.md §9.5), decided by the file: its
// name ends in `.json` (in any case), or its first byte that is not white space is `{` (after a
// UTF-8 byte order mark). Every other file is the bracket format.
#include <string>
#include <string_view>

namespace whitted::cs1230 {

bool is_json_scene(std::string_view path, std::string_view text);

// The same for a file on disk, from its name and first bytes (a file that cannot be read: false,
// and the reader that opens it next reports why).
bool is_json_scene_file(const std::string& path);

}  // namespace whitted::cs1230

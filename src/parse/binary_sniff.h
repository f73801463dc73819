#pragma once
// Tells a binary file (an image given by mistake, an archive, a program) from scene text, so that
// it gets "this is not a scene file" instead of a keyword error on its first bytes.
#include <optional>
#include <string>
#include <string_view>

namespace whitted {

// What the text looks like ("a PNG image", "binary data", ...) when it cannot be a scene file;
// nullopt for text. Looks at the first 4 KiB only: known signatures first, then NUL or other
// control bytes, which no scene text holds (UTF-8 bytes >= 0x80 are text).
std::optional<std::string> binary_file_kind(std::string_view text);

}  // namespace whitted

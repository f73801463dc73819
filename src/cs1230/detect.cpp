#include "cs1230/detect.h"

#include <cctype>

#include "base/read_file.h"

namespace whitted::cs1230 {
namespace {

bool has_json_extension(std::string_view path) {
    if (path.size() < 5) return false;
    const std::string_view ext = path.substr(path.size() - 5);
    static constexpr std::string_view kJson = ".json";
    for (std::size_t i = 0; i < ext.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(ext[i])) != kJson[i]) return false;
    return true;
}

}  // namespace

bool is_json_scene(std::string_view path, std::string_view text) {
    if (has_json_extension(path)) return true;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    for (const char c : text) {
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        return c == '{';
    }
    return false;
}

bool is_json_scene_file(const std::string& path) {
    if (has_json_extension(path)) return true;
    // White space before the `{` is rare; 4 KiB of it is a file of nothing.
    const FileContents start = read_file_start(path, 4096);
    return start.ok() && is_json_scene(path, start.bytes);
}

}  // namespace whitted::cs1230

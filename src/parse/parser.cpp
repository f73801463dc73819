#include "parse/parser_impl.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace whitted {


ParseResult parse_scene_text(std::string_view text, const std::string& file_name,
                             const ParseOptions& options) {
    return parse_detail::Parser(text, file_name, options).run();
}

ParseResult parse_scene_file(const std::string& path, const ParseOptions& options) {
    ParseResult result;
    auto fail = [&](const std::string& why) {
        result.diagnostics.push_back(
            {Severity::Error, SourceLoc{path, 0, 0}, "cannot read scene file: " + why});
        result.unreadable = true;
        return result;
    };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return fail("it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(std::strerror(errno));
    std::string text;
    char buffer[65536];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
        text.append(buffer, static_cast<size_t>(in.gcount()));
    if (in.bad()) return fail("read error");
    return parse_scene_text(text, path, options);
}

}  // namespace whitted

#include "parse/parser_impl.h"

#include "base/read_file.h"

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
    FileContents file = read_regular_file(path, options.max_file_bytes, options.cancel);
    if (file.cancelled) {
        result.cancelled = true;
        return result;
    }
    if (!file.ok()) return fail(file.error);
    const std::string& text = file.bytes;
    return parse_scene_text(text, path, options);
}

}  // namespace whitted

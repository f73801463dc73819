#include "parse/binary_sniff.h"

#include <algorithm>

namespace whitted {

std::optional<std::string> binary_file_kind(std::string_view text) {
    const std::string_view head = text.substr(0, 4096);
    using namespace std::string_view_literals;
    auto starts = [&](std::string_view magic) { return head.substr(0, magic.size()) == magic; };
    const bool has_nul = head.find('\0') != std::string_view::npos;
    if (starts("\x89PNG\r\n\x1a\n")) return "a PNG image";
    if (starts("\xFF\xD8\xFF")) return "a JPEG image";
    if (starts("GIF87a") || starts("GIF89a")) return "a GIF image";
    if (starts("BM") && has_nul) return "a BMP image";
    if ((starts("P6") || starts("P5")) && head.size() > 2 && (head[2] == ' ' || head[2] == '\n' || head[2] == '\r'))
        return "a binary PPM/PGM image";
    if (starts("II*\0"sv) || starts("MM\0*"sv)) return "a TIFF image";
    if (starts("%PDF")) return "a PDF document";
    if (starts("PK\x03\x04")) return "a ZIP archive";
    if (starts("\x1f\x8b")) return "gzip-compressed data";
    if (starts("\x7f" "ELF")) return "an executable program";
    if (starts("v/1\x01")) return "an OpenEXR image";
    if (has_nul) return "binary data";
    // Control bytes other than whitespace: a handful is a damaged text file, many is binary.
    const auto controls = std::count_if(head.begin(), head.end(), [](char ch) {
        const unsigned char c = static_cast<unsigned char>(ch);
        return c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f';
    });
    if (controls > 0 && controls * 10 > std::ptrdiff_t(head.size())) return "binary data";
    return std::nullopt;
}

}  // namespace whitted

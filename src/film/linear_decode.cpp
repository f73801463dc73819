#include "film/linear_decode.h"

#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "film/exr_decode.h"

namespace whitted {
namespace {

constexpr std::string_view kExrMagic("\x76\x2f\x31\x01", 4);

bool is_pfm(std::string_view b) {
    return b.size() >= 3 && b[0] == 'P' && (b[1] == 'F' || b[1] == 'f') && std::isspace(static_cast<unsigned char>(b[2]));
}

// The next whitespace-separated field of a PFM header at `i` (moved past it), or "" at the end.
std::string_view next_field(std::string_view b, std::size_t& i) {
    while (i < b.size() && std::isspace(static_cast<unsigned char>(b[i]))) ++i;
    const std::size_t start = i;
    while (i < b.size() && !std::isspace(static_cast<unsigned char>(b[i]))) ++i;
    return b.substr(start, i - start);
}

// A side of at most 9 digits (anything larger is over every limit anyway), or -1.
long long parse_side(std::string_view s) {
    if (s.empty() || s.size() > 9) return -1;
    long long v = 0;
    for (char c : s) {
        if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
        v = v * 10 + (c - '0');
    }
    return v;
}

std::string decode_pfm(std::string_view b, const ImageLimits& limits, LinearImage& out) {
    const int channels = b[1] == 'F' ? 3 : 1;
    std::size_t i = 2;
    const long long w = parse_side(next_field(b, i)), h = parse_side(next_field(b, i));
    if (w < 0 || h < 0) return "a PFM header without a width and a height";
    if (std::string problem = image_size_problem(w, h, limits); !problem.empty()) return problem;
    const std::string scale_text(next_field(b, i));
    char* end = nullptr;
    const double scale = scale_text.empty() ? NAN : std::strtod(scale_text.c_str(), &end);
    if (scale_text.empty() || *end != '\0' || !std::isfinite(scale) || scale == 0.0)
        return "a PFM header without its scale (negative for little-endian floats)";
    if (i >= b.size()) return "the file ends before its pixels (truncated)";
    ++i;  // the single whitespace byte before the pixels
    const std::uint64_t need = std::uint64_t(w) * std::uint64_t(h) * std::uint64_t(channels) * 4;
    if (b.size() - i < need)
        return "the file ends before its last pixel (truncated: " + std::to_string(b.size()) + " of " +
               std::to_string(i + need) + " bytes)";
    const bool swap = (scale < 0) != (std::endian::native == std::endian::little);
    LinearImage image{int(w), int(h), std::vector<glm::vec3>(std::size_t(w) * std::size_t(h)), {}};
    const char* p = b.data() + i;
    for (long long y = h - 1; y >= 0; --y)  // the file's first row is the image's bottom row
        for (long long x = 0; x < w; ++x) {
            float v[3];
            for (int c = 0; c < channels; ++c, p += 4) {
                std::uint32_t u;
                std::memcpy(&u, p, 4);
                if (swap) u = __builtin_bswap32(u);
                std::memcpy(&v[c], &u, 4);
            }
            image.rgb[std::size_t(y) * std::size_t(w) + std::size_t(x)] =
                channels == 3 ? glm::vec3(v[0], v[1], v[2]) : glm::vec3(v[0]);
        }
    out = std::move(image);
    return "";
}

}  // namespace

std::string image_size_problem(long long width, long long height, const ImageLimits& limits) {
    const std::string dims = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) return "the image is empty (" + dims + ")";
    if (width > limits.max_side || height > limits.max_side)
        return dims + " pixels: more than " + std::to_string(limits.max_side) + " across or down";
    if (std::uint64_t(width) * std::uint64_t(height) > limits.max_pixels)
        return dims + " pixels: more than the limit of " + std::to_string(limits.max_pixels);
    return "";
}

bool is_linear_image_data(std::string_view bytes) { return bytes.substr(0, 4) == kExrMagic || is_pfm(bytes); }

std::string decode_linear_image(std::string_view bytes, const ImageLimits& limits, LinearImage& out) {
    if (bytes.substr(0, 4) == kExrMagic) return decode_exr(bytes, limits, out);
    if (is_pfm(bytes)) return decode_pfm(bytes, limits, out);
    return "neither an OpenEXR nor a PFM file";
}

}  // namespace whitted

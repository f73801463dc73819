#include "texture/ascii_ppm.h"

#include <cctype>

namespace whitted {
namespace {

// Reads the next unsigned decimal number, skipping whitespace and `#` comments to end of line.
bool next_number(std::string_view s, std::size_t& i, long long& value) {
    while (i < s.size()) {
        if (s[i] == '#') {
            while (i < s.size() && s[i] != '\n' && s[i] != '\r') ++i;
        } else if (std::isspace(static_cast<unsigned char>(s[i]))) {
            ++i;
        } else {
            break;
        }
    }
    if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
    value = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
        value = value * 10 + (s[i++] - '0');
        if (value > (1LL << 40)) return false;
    }
    return true;
}

}  // namespace

bool is_ascii_ppm(std::string_view bytes) {
    return bytes.size() > 2 && bytes[0] == 'P' && bytes[1] == '3' &&
           std::isspace(static_cast<unsigned char>(bytes[2]));
}

bool decode_ascii_ppm(std::string_view bytes, TextureImage& out, std::string& reason, const TextureLimits& limits) {
    std::size_t i = 2;
    long long w = 0, h = 0, maxval = 0;
    if (!next_number(bytes, i, w) || !next_number(bytes, i, h) || !next_number(bytes, i, maxval)) {
        reason = "malformed plain PPM header";
        return false;
    }
    if (w <= 0 || h <= 0 || maxval <= 0 || maxval > 65535) {
        reason = "unsupported plain PPM size or maximum value";
        return false;
    }
    const std::string dims = std::to_string(w) + "x" + std::to_string(h);
    // The sides first: each is below 2^40 here, their product need not fit in 64 bits (the fuzzer's
    // 61000000000 × 90000000000 overflowed).
    if (w > limits.max_side || h > limits.max_side) {
        reason = dims + " texels: more than " + std::to_string(limits.max_side) + " across or down";
        return false;
    }
    const std::size_t texels = std::size_t(w) * std::size_t(h);
    if (texels > limits.max_texels)
        reason = dims + " texels: more than the limit of " + std::to_string(limits.max_texels) + " texels";
    else if (texels * 3 > limits.max_total_bytes)
        reason = dims + " texels need more than the memory left for textures";
    if (!reason.empty()) return false;
    TextureImage img;
    img.width = int(w);
    img.height = int(h);
    img.rgb.resize(texels * 3);
    for (std::uint8_t& byte : img.rgb) {
        long long v = 0;
        if (!next_number(bytes, i, v)) {
            reason = "the plain PPM ends before its last pixel (truncated or malformed)";
            return false;
        }
        if (v > maxval) {
            reason = "a plain PPM value is above its maximum " + std::to_string(maxval);
            return false;
        }
        byte = std::uint8_t((v * 510 + maxval) / (2 * maxval));  // v / maxval · 255, rounded (integers: no ties lost)
    }
    out = std::move(img);
    return true;
}

}  // namespace whitted

#include "texture/texture_decode.h"
#include "texture/texture_filter.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <vector>

#include <stb/stb_image.h>

#include "base/read_file.h"
#include "texture/ascii_ppm.h"
#include "texture/jpeg_decode.h"
#include "texture/png_check.h"

namespace whitted {
namespace {

bool starts_with(std::string_view bytes, std::string_view magic) { return bytes.substr(0, magic.size()) == magic; }

// The formats Debian's stb_image also decodes that whitted does not document (nor test): refused
// rather than handed to code nobody here has looked at.
const char* undocumented_format(std::string_view b) {
    if (starts_with(b, "GIF8")) return "GIF";
    if (starts_with(b, "8BPS")) return "PSD";
    if (starts_with(b, "#?RADIANCE") || starts_with(b, "#?RGBE")) return "Radiance HDR";
    if (starts_with(b, "S\x80\xf6\x34")) return "Softimage PIC";
    if (starts_with(b, "P1") || starts_with(b, "P2") || starts_with(b, "P4"))
        return "plain-text PBM/PGM or bitmap PNM";
    return nullptr;
}

// stb reads the pixels of a binary PNM and of an uncompressed TGA with one copy that it does not
// check: a file shorter than its header says decodes into uninitialised memory
// (docs/robustness.md). The bytes the header promises, or 0 if these are not such a file (or a header
// stb will refuse anyway).
std::uint64_t promised_bytes(std::string_view b) {
    if (b.size() >= 2 && b[0] == 'P' && (b[1] == '5' || b[1] == '6')) {
        // P6 <ws> width <ws> height <ws> maxval <one ws> pixels; '#' comments between fields.
        std::size_t i = 2;
        std::uint64_t field[3] = {};
        for (std::uint64_t& f : field) {
            for (;;) {
                while (i < b.size() && std::isspace(static_cast<unsigned char>(b[i]))) ++i;
                if (i < b.size() && b[i] == '#') {
                    while (i < b.size() && b[i] != '\n' && b[i] != '\r') ++i;
                    continue;
                }
                break;
            }
            if (i >= b.size() || !std::isdigit(static_cast<unsigned char>(b[i]))) return 0;
            for (; i < b.size() && std::isdigit(static_cast<unsigned char>(b[i])); ++i)
                f = std::min<std::uint64_t>(f * 10 + std::uint64_t(b[i] - '0'), UINT32_MAX);
        }
        ++i;  // the single whitespace byte after maxval
        const std::uint64_t channels = b[1] == '6' ? 3 : 1, depth = field[2] > 255 ? 2 : 1;
        return i + field[0] * field[1] * channels * depth;
    }
    // TGA: an 18-byte header, an id, a colour map, then width·height pixels of bpp bits for the
    // uncompressed types 1 (colour-mapped), 2 (true colour) and 3 (grey).
    if (b.size() >= 18 && (b[2] == 1 || b[2] == 2 || b[2] == 3) && (b[1] == 0 || b[1] == 1)) {
        auto u16 = [&](int at) { return std::uint64_t(std::uint8_t(b[at])) | std::uint64_t(std::uint8_t(b[at + 1])) << 8; };
        const std::uint64_t id = std::uint8_t(b[0]);
        const std::uint64_t palette = b[1] == 1 ? u16(5) * ((std::uint64_t(std::uint8_t(b[7])) + 7) / 8) : 0;
        const std::uint64_t bpp = std::uint8_t(b[16]);
        return 18 + id + palette + u16(12) * u16(14) * ((bpp + 7) / 8);
    }
    return 0;
}

// stb_image reads zeros past the end of a truncated BMP (or TGA) and reports success; such a file
// decodes differently once bytes are appended. PNG's own checks already catch truncation.
bool decoded_past_the_end(std::string_view bytes, const unsigned char* data, int w, int h) {
    if (starts_with(bytes, "\x89PNG")) return false;
    std::vector<unsigned char> padded(bytes.begin(), bytes.end());
    padded.resize(bytes.size() + 4096, 0xFF);  // more than any one pixel's bytes
    int pw = 0, ph = 0, pn = 0;
    unsigned char* again = stbi_load_from_memory(padded.data(), int(padded.size()), &pw, &ph, &pn, 3);
    const bool same = again && pw == w && ph == h && std::equal(data, data + std::size_t(w) * h * 3, again);
    stbi_image_free(again);
    return !same;
}

}  // namespace

std::size_t stored_texture_bytes(int width, int height, const TextureLimits& limits) {
    return std::size_t(width) * std::size_t(height) * 3 + (limits.mip_levels ? mip_levels_bytes(width, height) : 0);
}

std::string decode_texture(std::string_view bytes, const TextureLimits& limits, TextureImage& out) {
    if (bytes.size() > std::size_t(INT_MAX)) return "the file is too large";
    if (const char* format = undocumented_format(bytes); format && !(limits.gif && starts_with(bytes, "GIF8")))
        return std::string("unsupported format (") + format + "): use PNG, JPEG, BMP, TGA or PPM";
    if (is_ascii_ppm(bytes)) {  // plain PPM (P3), which stb does not read: ascii_ppm.h
        std::string why;
        return decode_ascii_ppm(bytes, out, why, limits) ? "" : why;
    }
    if (starts_with(bytes, "\xff\xd8")) return decode_jpeg(bytes, limits, out);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const int size = int(bytes.size());
    int w = 0, h = 0, n = 0;
    if (!stbi_info_from_memory(data, size, &w, &h, &n))
        return stbi_failure_reason() ? stbi_failure_reason() : "not an image";
    // A BMP stored top-down says so with a negative height, which stbi_info passes on.
    if (h < 0 && h != INT_MIN) h = -h;
    const std::string dims = std::to_string(w) + "x" + std::to_string(h);
    if (w <= 0 || h <= 0) return "the image is empty (" + dims + ")";
    if (w > limits.max_side || h > limits.max_side)
        return dims + " texels: more than " + std::to_string(limits.max_side) + " across or down";
    const std::size_t texels = std::size_t(w) * std::size_t(h);
    if (texels > limits.max_texels)
        return dims + " texels: more than the limit of " + std::to_string(limits.max_texels) + " texels";
    if (const std::size_t stored = stored_texture_bytes(w, h, limits); stored > limits.max_total_bytes)
        return dims + " texels need " + describe_bytes(stored) + (limits.mip_levels ? " with their mip-map" : "") +
               ", more than the " +
               describe_bytes(limits.max_total_bytes) + " left for textures";
    if (const std::uint64_t promised = promised_bytes(bytes); promised > bytes.size())
        return "the file ends before its last pixel (truncated: " + std::to_string(bytes.size()) + " of " +
               std::to_string(promised) + " bytes)";
    if (starts_with(bytes, "\x89PNG\r\n\x1a\n"))
        if (std::string why = check_png(bytes); !why.empty()) return why;
    unsigned char* rgb = stbi_load_from_memory(data, size, &w, &h, &n, 3);
    if (!rgb) return stbi_failure_reason() ? stbi_failure_reason() : "?";
    if (decoded_past_the_end(bytes, rgb, w, h)) {
        stbi_image_free(rgb);
        return "the file ends before its last pixel (truncated)";
    }
    out.width = w;
    out.height = h;
    out.rgb.assign(rgb, rgb + std::size_t(w) * h * 3);
    stbi_image_free(rgb);
    return "";
}

}  // namespace whitted

#include "texture/png_check.h"

#include <array>
#include <cstdint>
#include <string>

#include <zlib.h>

namespace whitted {
namespace {

std::uint32_t be32(std::string_view b, std::size_t at) {
    return std::uint32_t(std::uint8_t(b[at])) << 24 | std::uint32_t(std::uint8_t(b[at + 1])) << 16 |
           std::uint32_t(std::uint8_t(b[at + 2])) << 8 | std::uint32_t(std::uint8_t(b[at + 3]));
}

int samples_per_pixel(int colour_type) {
    switch (colour_type) {
        case 0: return 1;  // grey
        case 2: return 3;  // RGB
        case 3: return 1;  // palette index
        case 4: return 2;  // grey + alpha
        case 6: return 4;  // RGBA
        default: return 0;
    }
}

// What inflating a PNG's IDAT data told: the bytes it gave (counting stops a scratch buffer past
// the limit) and zlib's complaint, if any.
struct Inflated {
    unsigned long long bytes = 0;
    std::string error;
};

// Inflates the IDAT chunks' data as one zlib stream (a raw deflate stream in Apple's CgBI PNGs,
// which stb also reads) into a small scratch buffer, counting the bytes, and stops once there are
// more than `limit` or zlib finds an error.
Inflated inflate_idat(std::string_view bytes, unsigned long long limit, bool raw_deflate) {
    Inflated result;
    z_stream z{};
    if (inflateInit2(&z, raw_deflate ? -MAX_WBITS : MAX_WBITS) != Z_OK) return result.error = "out of memory", result;
    std::array<unsigned char, 64 * 1024> scratch;
    int status = Z_OK;
    for (std::size_t at = 8; at + 12 <= bytes.size() && status != Z_STREAM_END && result.bytes <= limit;) {
        const std::size_t length = be32(bytes, at);
        const std::string_view type = bytes.substr(at + 4, 4);
        if (type == "IEND") break;
        if (type == "IDAT") {
            z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + at + 8));
            z.avail_in = uInt(length);
            while (z.avail_in > 0 && result.bytes <= limit) {
                z.next_out = scratch.data();
                z.avail_out = uInt(scratch.size());
                status = inflate(&z, Z_NO_FLUSH);
                result.bytes += scratch.size() - z.avail_out;
                if (status == Z_STREAM_END) break;
                if (status == Z_BUF_ERROR && z.avail_out != 0) break;  // wants input the chunk no longer has
                if (status != Z_OK && status != Z_BUF_ERROR) {
                    result.error = z.msg ? z.msg : status == Z_NEED_DICT ? "a preset dictionary" : "corrupt data";
                    inflateEnd(&z);
                    return result;
                }
            }
        }
        at += 12 + length;
    }
    inflateEnd(&z);
    return result;
}

}  // namespace

unsigned long long png_filtered_bytes(unsigned width, unsigned height, int bit_depth, int colour_type, int interlace) {
    const int samples = samples_per_pixel(colour_type);
    if (width == 0 || height == 0 || samples == 0 || bit_depth <= 0 || bit_depth > 16) return 0;
    const unsigned long long bits = (unsigned long long)samples * unsigned(bit_depth);
    auto pass = [&](unsigned long long w, unsigned long long h) {
        return w == 0 || h == 0 ? 0ULL : h * (1 + (w * bits + 7) / 8);
    };
    if (interlace == 0) return pass(width, height);
    // Adam7: the passes' first column and row, and their steps.
    static constexpr int x0[7] = {0, 4, 0, 2, 0, 1, 0}, y0[7] = {0, 0, 4, 0, 2, 0, 1};
    static constexpr int dx[7] = {8, 8, 4, 4, 2, 2, 1}, dy[7] = {8, 8, 8, 4, 4, 2, 2};
    unsigned long long total = 0;
    for (int p = 0; p < 7; ++p)
        total += pass((width + unsigned(dx[p] - x0[p] - 1)) / unsigned(dx[p]),
                      (height + unsigned(dy[p] - y0[p] - 1)) / unsigned(dy[p]));
    return total;
}

std::string check_png(std::string_view bytes) {
    // The chunks: length, type, data, CRC; each must end inside the file.
    std::size_t at = 8;
    unsigned long long needed = 0;
    bool raw_deflate = false;
    for (bool ended = false; !ended && at + 8 <= bytes.size();) {
        const std::uint32_t length = be32(bytes, at);
        std::string type(bytes.substr(at + 4, 4));
        for (char& c : type)
            if (!(c >= 'A' && c <= 'Z') && !(c >= 'a' && c <= 'z')) c = '?';  // a corrupt type, printable
        ended = type == "IEND";  // stb reads nothing after it (and does not need its CRC)
        if (!ended && (length > 0x7fffffffu || 12 + (unsigned long long)length > bytes.size() - at))
            return "the file ends inside its " + type + " chunk (" + std::to_string(length) +
                   " bytes of data announced at byte " + std::to_string(at) + " of " +
                   std::to_string(bytes.size()) + "): truncated or corrupt";
        if (type == "IHDR" && length >= 13)
            needed = png_filtered_bytes(be32(bytes, at + 8), be32(bytes, at + 12), std::uint8_t(bytes[at + 16]),
                                        std::uint8_t(bytes[at + 17]), std::uint8_t(bytes[at + 20]));
        raw_deflate |= type == "CgBI";
        at += 12 + std::size_t(length);
    }
    if (needed == 0) return "";  // no valid header: stb says what is wrong
    const unsigned long long limit = 2 * needed + 64 * 1024;
    const Inflated inflated = inflate_idat(bytes, limit, raw_deflate);
    // zlib's errors: corrupt data stb refuses too, and a window size in the stream's header over
    // 32 KB, which stb does not check (it would inflate such data without the count above). The
    // checksum at the end, which stb does not check either, comes after all the data was counted:
    // such files decode as they always did.
    if (!inflated.error.empty() && inflated.error != "incorrect data check")
        return "its pixel data is not a valid zlib stream (zlib: " + inflated.error + ")";
    if (inflated.bytes > limit)
        return "its pixel data inflates to more than twice the " + std::to_string(needed) +
               " bytes its pixels need (a zip bomb?)";
    return "";
}

}  // namespace whitted

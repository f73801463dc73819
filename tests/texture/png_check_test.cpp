// PNGs that lie about their chunks or inflate without end are refused before stb decodes them
// (the fuzzer's 282-byte file made stb reallocate 2 GB); honest ones decode as before.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>

#include "texture/png_check.h"
#include "texture/texture_decode.h"

namespace whitted {
namespace {

void put32(std::string& s, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xFF);
}

void chunk(std::string& png, const char* type, const std::string& data) {
    put32(png, std::uint32_t(data.size()));
    const std::string typed = std::string(type, 4) + data;
    png += typed;
    put32(png, std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
}

// A raw deflate stream (no zlib header or checksum), as Apple's CgBI PNGs hold.
std::string deflated_raw(const std::string& raw) {
    z_stream z{};
    EXPECT_EQ(deflateInit2(&z, 9, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
    std::string out(deflateBound(&z, uLong(raw.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
    z.avail_in = uInt(raw.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = uInt(out.size());
    EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

std::string deflated(const std::string& raw) {
    uLongf n = compressBound(uLong(raw.size()));
    std::string out(n, '\0');
    EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(out.data()), &n, reinterpret_cast<const Bytef*>(raw.data()),
                        uLong(raw.size()), 9),
              Z_OK);
    out.resize(n);
    return out;
}

// An 8-bit RGB PNG of w × h whose IDAT holds `idat` (by default the zlib stream of `filtered`:
// rows of a filter byte and the pixels), built by hand with zlib, independent of the code under test.
std::string png_with_idat(std::uint32_t w, std::uint32_t h, const std::string& idat, bool cgbi = false) {
    std::string png("\x89PNG\r\n\x1a\n", 8), ihdr;
    if (cgbi) chunk(png, "CgBI", std::string("\x50\x00\x20\x02", 4));
    put32(ihdr, w);
    put32(ihdr, h);
    ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, filter 0, not interlaced
    chunk(png, "IHDR", ihdr);
    chunk(png, "IDAT", idat);
    chunk(png, "IEND", "");
    return png;
}

std::string rgb_png(std::uint32_t w, std::uint32_t h, const std::string& filtered) {
    return png_with_idat(w, h, deflated(filtered));
}

// Rows with filter 0 ("none") and pixel (x, y) = (x, y, x + y): 1 + 3w bytes a row.
std::string rows(std::uint32_t w, std::uint32_t h) {
    std::string s;
    for (std::uint32_t y = 0; y < h; ++y) {
        s += '\0';
        for (std::uint32_t x = 0; x < w; ++x) s += {char(x), char(y), char(x + y)};
    }
    return s;
}

TEST(PngCheck, FilteredBytesOfEveryKindOfHeader) {
    // Non-interlaced: rows of a filter byte and ceil(w · samples · depth / 8) bytes.
    EXPECT_EQ(png_filtered_bytes(64, 64, 8, 2, 0), 64u * (1 + 192));
    EXPECT_EQ(png_filtered_bytes(10, 3, 1, 0, 0), 3u * (1 + 2));       // 10 one-bit greys: 2 bytes
    EXPECT_EQ(png_filtered_bytes(5, 2, 16, 6, 0), 2u * (1 + 5 * 8));   // 16-bit RGBA
    EXPECT_EQ(png_filtered_bytes(3, 1, 4, 3, 0), 1u * (1 + 2));        // 4-bit palette: 12 bits
    EXPECT_EQ(png_filtered_bytes(7, 7, 8, 4, 0), 7u * (1 + 14));       // grey + alpha
    // Adam7, 8 × 8 RGB: the passes are 1×1, 1×1, 2×1, 2×2, 4×2, 4×4 and 8×4 pixels, so the 192
    // pixel bytes of the plain image with 1+1+1+2+2+4+4 = 15 filter bytes instead of 8.
    EXPECT_EQ(png_filtered_bytes(8, 8, 8, 2, 1), 192u + 15);
    // A 1 × 1 interlaced image has its pixel in the first pass only.
    EXPECT_EQ(png_filtered_bytes(1, 1, 8, 2, 1), 4u);
    // Invalid colour types and depths.
    EXPECT_EQ(png_filtered_bytes(4, 4, 8, 5, 0), 0u);
    EXPECT_EQ(png_filtered_bytes(4, 4, 0, 2, 0), 0u);
    EXPECT_EQ(png_filtered_bytes(0, 4, 8, 2, 0), 0u);
}

TEST(PngCheck, AnHonestPngDecodesToItsPixels) {
    const std::string png = rgb_png(16, 8, rows(16, 8));
    EXPECT_EQ(check_png(png), "");
    TextureImage img;
    ASSERT_EQ(decode_texture(png, {}, img), "");
    ASSERT_EQ(img.width, 16);
    ASSERT_EQ(img.height, 8);
    EXPECT_EQ(img.rgb[(3 * 16 + 5) * 3 + 0], 5);
    EXPECT_EQ(img.rgb[(3 * 16 + 5) * 3 + 1], 3);
    EXPECT_EQ(img.rgb[(3 * 16 + 5) * 3 + 2], 8);
}

TEST(PngCheck, ALittleDataAfterTheLastRowIsAccepted) {
    // Some writers leave a few bytes after the last row; decoders ignore them and so do we.
    TextureImage img;
    EXPECT_EQ(decode_texture(rgb_png(16, 8, rows(16, 8) + std::string(100, '\0')), {}, img), "");
    EXPECT_EQ(img.width, 16);
}

TEST(PngCheck, AChunkLongerThanTheFileIsRefused) {
    // The fuzzer's file: a good 64 × 64 image, then an IDAT that announces 1,828,716,644 bytes
    // and has a hundred. stb reallocated its buffer to 2 GB before noticing the data was not there.
    std::string png = rgb_png(64, 64, rows(64, 64));
    png.resize(png.size() - 12);  // without its IEND
    put32(png, 1828716644u);
    png += "IDAT" + std::string(100, 'x');
    TextureImage img;
    const std::string why = decode_texture(png, {}, img);
    EXPECT_NE(why.find("ends inside its IDAT chunk (1828716644 bytes of data announced"), std::string::npos) << why;
    // A chunk cut short at the end of the file, and one whose length has the high bit set.
    std::string cut = rgb_png(16, 8, rows(16, 8));
    cut.resize(cut.size() - 12 - 4);  // the IDAT's CRC and the IEND gone
    EXPECT_NE(check_png(cut).find("ends inside its IDAT chunk"), std::string::npos);
    std::string high = rgb_png(16, 8, rows(16, 8));
    high[33] = char(0x80);  // the IDAT's length: 2^31 + its own
    EXPECT_NE(check_png(high).find("ends inside its IDAT chunk"), std::string::npos);
    // A file that ends inside IEND's CRC decodes: stb does not need it.
    std::string no_crc = rgb_png(16, 8, rows(16, 8));
    no_crc.resize(no_crc.size() - 4);
    EXPECT_EQ(decode_texture(no_crc, {}, img), "");
}

TEST(PngCheck, PixelDataThatInflatesFarBeyondTheImageIsRefused) {
    // A zip bomb: 16 MB of zeros (about 16 KB deflated) as the data of a 16 × 8 image that needs
    // 392 bytes. stb would grow its buffer to hold all of it.
    const std::string png = rgb_png(16, 8, std::string(16u << 20, '\0'));
    EXPECT_LT(png.size(), 64u * 1024);
    TextureImage img;
    const std::string why = decode_texture(png, {}, img);
    EXPECT_NE(why.find("inflates to more than twice the 392 bytes its pixels need"), std::string::npos) << why;
}

TEST(PngCheck, ABombStbWouldInflateWithoutZlibsChecksIsRefusedToo) {
    const std::string bomb = deflated(std::string(16u << 20, '\0'));
    // A window of 64 KB in the zlib header (CINFO 10; FCHECK made right): zlib refuses it, stb
    // does not look and would inflate all 16 MB.
    std::string wide = bomb;
    wide[0] = char(0xA8);
    wide[1] = char(31 - (0xA8 * 256) % 31);
    ASSERT_EQ((std::uint8_t(wide[0]) * 256 + std::uint8_t(wide[1])) % 31, 0);
    TextureImage img;
    std::string why = decode_texture(png_with_idat(16, 8, wide), {}, img);
    EXPECT_NE(why.find("not a valid zlib stream (zlib: invalid window size)"), std::string::npos) << why;
    // Apple's CgBI PNGs hold raw deflate streams, which stb reads too: counted the same way.
    why = check_png(png_with_idat(16, 8, deflated_raw(std::string(16u << 20, '\0')), true));
    EXPECT_NE(why.find("inflates to more than twice"), std::string::npos) << why;
    EXPECT_EQ(check_png(png_with_idat(16, 8, deflated_raw(rows(16, 8)), true)), "");
    // A wrong checksum at the end of the stream, which stb does not check: all the data was counted
    // before it, and the image decodes as it always did.
    std::string bad_sum = deflated(rows(16, 8));
    bad_sum.back() = char(bad_sum.back() ^ 1);
    EXPECT_EQ(decode_texture(png_with_idat(16, 8, bad_sum), {}, img), "");
    EXPECT_EQ(img.rgb[(3 * 16 + 5) * 3 + 2], 8);
    // Other corrupt data is refused with zlib's reason (stb refuses it too).
    std::string corrupt = deflated(rows(16, 8));
    corrupt[2] = char(0xFF);  // block type 3, which does not exist
    EXPECT_NE(check_png(png_with_idat(16, 8, corrupt)).find("zlib: invalid block type"), std::string::npos);
}

TEST(PngCheck, ImagesSplitOverManyIdatChunksAreCheckedAsOneStream) {
    // Writers split the zlib stream across IDAT chunks (libpng: 8 KB each); the check follows it.
    const std::string z = deflated(rows(64, 64));
    std::string png("\x89PNG\r\n\x1a\n", 8), ihdr;
    put32(ihdr, 64);
    put32(ihdr, 64);
    ihdr += std::string("\x08\x02\x00\x00\x00", 5);
    chunk(png, "IHDR", ihdr);
    for (std::size_t at = 0; at < z.size(); at += 7) chunk(png, "IDAT", z.substr(at, 7));
    chunk(png, "IEND", "");
    EXPECT_EQ(check_png(png), "");
    TextureImage img;
    ASSERT_EQ(decode_texture(png, {}, img), "");
    EXPECT_EQ(img.rgb[(10 * 64 + 20) * 3 + 2], 30);
    // The same bomb split likewise is still refused.
    const std::string bomb = deflated(std::string(8u << 20, '\0'));
    std::string split("\x89PNG\r\n\x1a\n", 8);
    chunk(split, "IHDR", ihdr);
    for (std::size_t at = 0; at < bomb.size(); at += 1000) chunk(split, "IDAT", bomb.substr(at, 1000));
    chunk(split, "IEND", "");
    EXPECT_NE(check_png(split).find("inflates to more than twice"), std::string::npos);
}

}  // namespace
}  // namespace whitted

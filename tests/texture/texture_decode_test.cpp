// Hostile texture files (docs/robustness.md): sizes are refused from the header before a
// texel is decoded, files shorter than their header says are refused, texels are stored as bytes.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "texture/texture_decode.h"

namespace whitted {
namespace {

// A PNG signature and an IHDR chunk claiming w × h, 8-bit RGB, and nothing else: all a header
// check needs (stb does not look at the CRC while reading the header).
std::string png_header(std::uint32_t w, std::uint32_t h) {
    std::string s("\x89PNG\r\n\x1a\n", 8);
    auto be32 = [&](std::uint32_t v) {
        for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xFF);
    };
    be32(13);
    s += "IHDR";
    be32(w);
    be32(h);
    s += std::string("\x08\x02\x00\x00\x00", 5);
    be32(0);  // CRC
    return s;
}

TEST(TextureDecode, RefusesDimensionBombsFromTheHeader) {
    TextureImage img;
    // The 783 KB PNG of 16384² took 3.9 GB: 268 M texels, over the 64 Mi limit. Refused from
    // its 33-byte header, before anything is allocated.
    std::string why = decode_texture(png_header(16384, 16384), {}, img);
    EXPECT_NE(why.find("16384x16384 texels: more than the limit of 67108864 texels"), std::string::npos) << why;
    // The 29-byte PPM header claiming 16000² (3.0 GB as floats).
    why = decode_texture("P6\n16000 16000\n255\n0123456789", {}, img);
    EXPECT_NE(why.find("16000x16000 texels"), std::string::npos) << why;
    // Too wide however few texels: 16385 × 1.
    why = decode_texture(png_header(16385, 1), {}, img);
    EXPECT_NE(why.find("more than 16384 across or down"), std::string::npos) << why;
    EXPECT_EQ(img.width, 0);
    EXPECT_TRUE(img.rgb.empty());
}

TEST(TextureDecode, RefusesWhatExceedsTheMemoryLeftForTextures) {
    // A 40 × 40 PPM is 4,800 bytes as stored: fits in 4,800, not in 4,799.
    std::string ppm = "P6 40 40 255\n" + std::string(40 * 40 * 3, '\x7f');
    TextureLimits limits;
    limits.max_total_bytes = 4800;
    TextureImage img;
    ASSERT_EQ(decode_texture(ppm, limits, img), "");
    EXPECT_EQ(img.rgb.size(), 4800u);  // three bytes a texel, not three floats
    EXPECT_EQ(img.texel(0), glm::vec3(127.0f / 255.0f));
    limits.max_total_bytes = 4799;
    TextureImage other;
    const std::string why = decode_texture(ppm, limits, other);
    EXPECT_NE(why.find("need 4800 bytes, more than the 4799 bytes left for textures"), std::string::npos) << why;
}

TEST(TextureDecode, RefusesAPpmShorterThanItsHeaderSays) {
    // a P6 header of 2048² then 9 bytes decoded "successfully" into
    // 12 MB of uninitialised memory. 2048·2048·3 = 12,582,912 bytes after the 17-byte header.
    const std::string header = "P6\n2048 2048\n255\n";
    ASSERT_EQ(header.size(), 17u);
    TextureImage img;
    std::string why = decode_texture(header + "123456789", {}, img);
    EXPECT_NE(why.find("truncated: 26 of 12582929 bytes"), std::string::npos) << why;
    // Comments between the fields count as header; 16-bit samples are two bytes.
    why = decode_texture("P6 # made by hand\n2 1 65535\n" + std::string(11, '\0'), {}, img);
    EXPECT_NE(why.find("truncated"), std::string::npos) << why;
    EXPECT_EQ(decode_texture("P6 # made by hand\n2 1 65535\n" + std::string(12, '\0'), {}, img), "");
    EXPECT_EQ(img.width, 2);
    // A grey P5: one byte a texel.
    EXPECT_NE(decode_texture("P5 3 3 255\n" + std::string(8, '\x10'), {}, img).find("truncated"), std::string::npos);
    EXPECT_EQ(decode_texture("P5 3 3 255\n" + std::string(9, '\x10'), {}, img), "");
}

TEST(TextureDecode, RefusesAnUncompressedTgaShorterThanItsHeaderSays) {
    // Type 2 (true colour), 100 × 100, 24 bits: 18 + 30,000 bytes; stb copied the rows without
    // checking, leaving what was missing uninitialised.
    std::string tga(18, '\0');
    tga[2] = 2;
    tga[12] = 100, tga[14] = 100, tga[16] = 24;
    TextureImage img;
    const std::string why = decode_texture(tga + std::string(29'999, '\x40'), {}, img);
    EXPECT_NE(why.find("truncated: 30017 of 30018 bytes"), std::string::npos) << why;
    EXPECT_EQ(decode_texture(tga + std::string(30'000, '\x40'), {}, img), "");
    EXPECT_EQ(img.texel(9999), glm::vec3(64.0f / 255.0f));
}

TEST(TextureDecode, RefusesFormatsWhittedDoesNotDocument) {
    TextureImage img;
    const std::string gif = "GIF89a\x01\x00\x01\x00\x00\x00\x00;";
    const std::string why = decode_texture(gif, {}, img);
    EXPECT_NE(why.find("unsupported format (GIF)"), std::string::npos) << why;
}

// Found by fuzz/texture_fuzzer's long run: a 312-byte JPEG whose Huffman table made
// Debian's stb_image abort on an assertion in stbi__jpeg_huff_decode, ending the whole process.
// JPEGs are decoded by libjpeg now: a located error, no abort.
TEST(TextureDecode, ACorruptJpegIsAnErrorNotAnAbort) {
    const std::string jpeg(
    "\xff\xd8\xff\xe0\x00\x10\x4a\x46\x49\x46\x00\x01\x01\xff\xd8\xff\xe0\x00\x10\x4a\x46\x49\xe8\xbc"
    "\x8d\x65\x61\x74\x65\x00\x32\x32\x32\x32\x32\x32\x32\x32\x32\x32\xff\xc0\x00\x11\x08\x01\x2c\x00"
    "\xff\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01\xff\xc4\x00\x1c\x00\x01\x00\x01\x05\x01\x01\x00\x00"
    "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x07\x03\x04\x05\x06\x08\x02\x01\xff\xc4\x00\x4b\x10\x00\x01"
    "\x03\x03\x01\x05\x04\x07\x05\x04\x06\x07\x09\x01\x00\x00\x01\x00\x02\x03\x04\x05\x11\x06\x07\x12"
    "\x21\x32\x41\x13\x51\xe1\xf0\x26\x35\x36\x53\x64\x65\x73\x74\x83\xe2\xff\xc4\x00\x1b\x01\x01\x00"
    "\x02\x03\x01\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x02\x04\x01\x03\x05\xe1\xa1\xff\xda"
    "\x00\x0c\x03\x01\x00\x02\x11\x03\x11\x00\x3f\x00\x99\x11\x11\x5d\x20\x11\x11\x00\xbc\xbb\xfe\xee"
    "\x46\xa1\xc6\xe6\xab\xbd\x09\xcd\x08\x88\x80\x22\x22\x03\xff\xd9\x01\x00\x01\x05\x01\x01\x00\x00"
    "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x07\x03\x04\x05\x06\x08\x02\x01\xff\xc4\x00\x4b\x10\x00\x01"
    "\x03\x03\x01\x05\x04\x07\x05\x04\x06\x07\x09\x01\x00\x00\x01\x00\x02\x03\x04\x05\x11\x06\x07\x12"
    "\x21\x31\x41\x13\x51\x61\x81\x22\x32\x42\x71\x91\xa1\xb1\x08\x14\x15\x23\xc1\x52\x62\x82\xd1\x43"
    "\x63\x72\x92\xa2\xb2\x24\x33\x34\xc2\xd2\xe1\xf0\x26\x35\xb4\x35\xa1\xad\x80\x22\x22\x03\xff\xd9",
        312);
    TextureImage img;
    const std::string why = decode_texture(jpeg, {}, img);
    EXPECT_NE(why.find("corrupt or truncated JPEG"), std::string::npos) << why;
}

}  // namespace
}  // namespace whitted

// Every format `whitted compare` reads, read back from files whitted's own writers made (and, for
// the formats whitted reads but does not write, files made here: TGA by stb, plain PPM, grey and
// big-endian PFM, and OpenEXR with half channels or luminance alone by OpenEXR itself).
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include "compare/compare_image.h"
#include "film/image_io.h"
#include "support/run_process.h"

namespace whitted {
namespace {

// 13 × 7 with every pixel different.
Image bytes_picture() {
    Image im(13, 7);
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 13; ++x) {
            std::uint8_t* p = &im.rgb[std::size_t(y * 13 + x) * 3];
            p[0] = std::uint8_t(x * 19), p[1] = std::uint8_t(y * 37), p[2] = std::uint8_t(255 - x * y * 3);
        }
    return im;
}

void expect_bytes(const CompareImage& got, const Image& want) {
    ASSERT_EQ(got.pixels.width, want.width);
    ASSERT_EQ(got.pixels.height, want.height);
    EXPECT_FALSE(got.linear);
    for (std::size_t i = 0; i < got.pixels.rgb.size(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(got.pixels.rgb[i][c], want.rgb[3 * i + std::size_t(c)] / 255.0f) << i << c;
}

struct CompareImageRead : ::testing::Test {
    std::string dir = test::make_temp_dir();
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string path(const std::string& name) const { return dir + "/" + name; }
};

TEST_F(CompareImageRead, LosslessEightBitFormatsAsWritten) {
    const Image picture = bytes_picture();
    for (auto [ext, format] : {std::pair{".png", "PNG"}, {".bmp", "BMP"}, {".ppm", "PPM"}}) {
        ASSERT_EQ(write_image(picture, path(std::string("a") + ext)), "");
        CompareImage got;
        ASSERT_EQ(read_compare_image(path(std::string("a") + ext), got), "") << ext;
        EXPECT_EQ(got.format, format);
        expect_bytes(got, picture);
    }
}

TEST_F(CompareImageRead, Jpeg) {
    Image smooth(16, 16);  // JPEG is lossy: a smooth picture comes back close
    for (int i = 0; i < 256; ++i) smooth.rgb[3 * i] = smooth.rgb[3 * i + 1] = std::uint8_t(64 + i / 4), smooth.rgb[3 * i + 2] = 90;
    ASSERT_EQ(write_image(smooth, path("a.jpg")), "");
    CompareImage got;
    ASSERT_EQ(read_compare_image(path("a.jpg"), got), "");
    EXPECT_EQ(got.format, "JPEG");
    ASSERT_EQ(got.pixels.width, 16);
    double worst = 0;
    for (std::size_t i = 0; i < 256; ++i)
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got.pixels.rgb[i][c] * 255.0 - smooth.rgb[3 * i + std::size_t(c)]));
    EXPECT_LE(worst, 4.0);
}

TEST_F(CompareImageRead, TgaAndPlainPpm) {
    const Image picture = bytes_picture();
    ASSERT_NE(stbi_write_tga(path("a.tga").c_str(), 13, 7, 3, picture.rgb.data()), 0);
    std::string p3 = "P3\n# plain\n13 7\n255\n";
    for (std::uint8_t v : picture.rgb) p3 += std::to_string(v) + " ";
    test::write_file(dir, "a.ppm", p3 + "\n");
    for (auto [name, format] : {std::pair{"a.tga", "TGA"}, {"a.ppm", "PPM"}}) {
        CompareImage got;
        ASSERT_EQ(read_compare_image(path(name), got), "") << name;
        EXPECT_EQ(got.format, format);
        expect_bytes(got, picture);
    }
}

LinearImage linear_picture() {
    LinearImage im{5, 3, std::vector<glm::vec3>(15), {}};
    for (std::size_t i = 0; i < 15; ++i) im.rgb[i] = {float(i) * 0.25f, -0.5f + float(i), 100.0f / float(i + 1)};
    return im;
}

TEST_F(CompareImageRead, ExrAndPfmKeepTheFloats) {
    const LinearImage picture = linear_picture();
    for (auto [name, format] : {std::pair{"a.exr", "OpenEXR"}, {"a.pfm", "PFM"}}) {
        ASSERT_EQ(write_linear_image(picture, path(name)), "");
        CompareImage got;
        ASSERT_EQ(read_compare_image(path(name), got), "") << name;
        EXPECT_EQ(got.format, format);
        EXPECT_TRUE(got.linear);
        ASSERT_EQ(got.pixels.width, 5);
        ASSERT_EQ(got.pixels.height, 3);
        EXPECT_EQ(got.pixels.rgb, picture.rgb) << name;
    }
}

// "Pf" (grey) with a positive scale: big-endian floats, rows bottom to top.
TEST_F(CompareImageRead, GreyBigEndianPfm) {
    std::string f = "Pf\n2 2\n1.0\n";
    for (float v : {0.25f, 0.5f, 3.0f, -1.0f}) {  // bottom row first
        std::uint32_t u;
        std::memcpy(&u, &v, 4);
        for (int shift = 24; shift >= 0; shift -= 8) f += char((u >> shift) & 0xff);
    }
    test::write_file(dir, "g.pfm", f);
    CompareImage got;
    ASSERT_EQ(read_compare_image(path("g.pfm"), got), "");
    ASSERT_EQ(got.pixels.width, 2);
    EXPECT_EQ(got.pixels.rgb[0], glm::vec3(3.0f));  // top-left: the file's second row
    EXPECT_EQ(got.pixels.rgb[3], glm::vec3(0.5f));  // bottom-right: the file's first row
}

// An OpenEXR file of the given half channels, every value `value`.
void write_half_exr(const std::string& file, std::initializer_list<const char*> names, float value) {
    Imf::Header header(3, 2);
    for (const char* n : names) header.channels().insert(n, Imf::Channel(Imf::HALF));
    Imf::OutputFile out(file.c_str(), header);
    std::vector<half> data(6, half(value));
    Imf::FrameBuffer fb;
    for (const char* n : names)
        fb.insert(n, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(data.data()), sizeof(half), 3 * sizeof(half)));
    out.setFrameBuffer(fb);
    out.writePixels(2);
}

TEST_F(CompareImageRead, ExrLuminanceAloneAndAlphaIgnored) {
    write_half_exr(path("y.exr"), {"Y"}, 0.75f);
    CompareImage got;
    ASSERT_EQ(read_compare_image(path("y.exr"), got), "");
    EXPECT_EQ(got.pixels.rgb[5], glm::vec3(0.75f));
    write_half_exr(path("rgba.exr"), {"R", "G", "B", "A"}, 2.0f);
    ASSERT_EQ(read_compare_image(path("rgba.exr"), got), "");
    EXPECT_EQ(got.pixels.rgb[0], glm::vec3(2.0f));
    write_half_exr(path("z.exr"), {"Z"}, 1.0f);
    EXPECT_NE(read_compare_image(path("z.exr"), got).find("no R, G, B or Y channel"), std::string::npos);
}

TEST_F(CompareImageRead, BadFilesAreErrorsNamingTheFile) {
    CompareImage got;
    auto error = [&](const std::string& name) { return read_compare_image(path(name), got); };
    EXPECT_NE(error("missing.png").find("missing.png"), std::string::npos);
    std::filesystem::create_directory(path("folder.png"));
    EXPECT_NE(error("folder.png").find("directory"), std::string::npos);
    test::write_file(dir, "text.png", "not an image at all\n");
    EXPECT_NE(error("text.png"), "");
    // Truncated: whitted's own files cut short.
    ASSERT_EQ(write_linear_image(linear_picture(), path("a.pfm")), "");
    ASSERT_EQ(write_linear_image(linear_picture(), path("a.exr")), "");
    for (const char* name : {"a.pfm", "a.exr"}) {
        std::filesystem::resize_file(path(name), std::filesystem::file_size(path(name)) - 10);
        EXPECT_NE(error(name), "") << name;
    }
    EXPECT_NE(error("a.pfm").find("truncated"), std::string::npos);
    // A header announcing more than the limits, refused before anything is allocated.
    test::write_file(dir, "huge.pfm", "PF\n100000 100000\n-1.0\n");
    EXPECT_NE(error("huge.pfm").find("more than 16384"), std::string::npos);
    test::write_file(dir, "empty.pfm", "PF\n0 5\n-1.0\n");
    EXPECT_NE(error("empty.pfm").find("empty"), std::string::npos);
    test::write_file(dir, "noscale.pfm", "PF\n1 1\nx\n");
    EXPECT_NE(error("noscale.pfm").find("scale"), std::string::npos);
    CompareLimits small;
    small.image.max_pixels = 10;
    ASSERT_EQ(write_image(bytes_picture(), path("b.png")), "");
    EXPECT_NE(read_compare_image(path("b.png"), got, small), "");
    ASSERT_EQ(write_linear_image(linear_picture(), path("c.exr")), "");
    EXPECT_NE(read_compare_image(path("c.exr"), got, small).find("more than the limit"), std::string::npos);
}

}  // namespace
}  // namespace whitted

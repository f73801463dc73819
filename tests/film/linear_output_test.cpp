// Linear output: .pfm and .exr keep the film's radiance unclamped, to the float; written atomically
// like the 8-bit formats.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>
#include <vector>

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <gtest/gtest.h>

#include "film/film.h"
#include "film/image_io.h"
#include "film/linear_decode.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

LinearImage sample_image() {
    Film film(3, 2);
    film.add(0, 0, {0.25f, 2.5f, 100.0f});  // above 1: an 8-bit file would clamp these
    film.add(1, 0, {1.0f, 0.0f, 0.5f});
    film.add(1, 0, {0.0f, 0.0f, 0.5f});     // two samples: the mean
    film.add(2, 1, {7.0f, 8.0f, 9.0f});
    return film.to_linear();
}

std::string temp_path(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("whitted-linear-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return (dir / name).string();
}

TEST(LinearOutput, PfmKeepsEveryFloatRowsBottomUp) {
    const LinearImage image = sample_image();
    EXPECT_EQ(image.rgb[1], glm::vec3(0.5f, 0.0f, 0.5f));
    const std::string path = temp_path("a.pfm");
    ASSERT_EQ(write_linear_image(image, path), "");
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int w = 0, h = 0;
    float scale = 0;
    in >> magic >> w >> h >> scale;
    in.get();
    EXPECT_EQ(magic, "PF");
    EXPECT_EQ(w, 3);
    EXPECT_EQ(h, 2);
    EXPECT_LT(scale, 0.0f);  // little-endian
    float px[2][3][3];
    in.read(reinterpret_cast<char*>(px), sizeof px);
    ASSERT_TRUE(in);
    // The file's first row is the image's bottom row.
    EXPECT_EQ(px[1][0][0], 0.25f);
    EXPECT_EQ(px[1][0][1], 2.5f);
    EXPECT_EQ(px[1][0][2], 100.0f);
    EXPECT_EQ(px[0][2][0], 7.0f);
    EXPECT_EQ(px[0][2][2], 9.0f);
    EXPECT_EQ(in.peek(), EOF);
}

TEST(LinearOutput, ExrReadsBackWithOpenExr) {
    const LinearImage image = sample_image();
    const std::string path = temp_path("a.exr");
    ASSERT_EQ(write_linear_image(image, path), "");
    Imf::RgbaInputFile in(path.c_str());
    const Imath::Box2i dw = in.dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    ASSERT_EQ(w, 3);
    ASSERT_EQ(h, 2);
    Imf::Array2D<Imf::Rgba> px(h, w);
    in.setFrameBuffer(&px[0][0], 1, std::size_t(w));
    in.readPixels(dw.min.y, dw.max.y);
    // Read back as half: equal to half precision (2.5, 100 and 0.25 are exact in half).
    EXPECT_EQ(float(px[0][0].r), 0.25f);
    EXPECT_EQ(float(px[0][0].g), 2.5f);
    EXPECT_EQ(float(px[0][0].b), 100.0f);
    EXPECT_EQ(float(px[1][2].g), 8.0f);
    EXPECT_EQ(float(px[0][1].b), 0.5f);
}

TEST(LinearOutput, EightBitFilesFromLinearValuesClamp) {
    const std::string path = temp_path("a.png");
    ASSERT_EQ(write_linear_image(sample_image(), path), "");
    Image back;
    ASSERT_EQ(read_image(path, back), "");
    EXPECT_EQ(back.at(0, 0), glm::u8vec3(64, 255, 255));  // ⌊255·0.25 + 0.5⌋, then clamped
}

TEST(LinearOutput, AFailedWriteLeavesNothingBehind) {
    const std::string dir = temp_path("missing-dir");
    EXPECT_NE(write_linear_image(sample_image(), dir + "/nope/a.exr"), "");
    EXPECT_FALSE(fs::exists(dir + "/nope"));
}

}  // namespace
// A header whose data window runs backwards (max.x < min.x) and is 65,498 lines tall: OpenEXR would
// size its line buffers from it (2 GB) before a pixel is read. The header is checked first: a located
// refusal, no allocation (the fuzzer's input, kept).
TEST(LinearOutput, AnExrHeaderThatWouldAskForGigabytesIsRefusedFirst) {
    const std::string bytes(
        "\x76\x2f\x31\x01\x02\x00\x00\x00\x63\x68\x61\x6e\x6e\x65\x6c\x73\x00\x63\x68\x6c\x69\x73\x74\x00"
        "\x37\x00\x00\x00\x42\x00\x02\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00\x00\x01\x00\x00\x00\x47\x00"
        "\x02\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00\x00\x01\x00\x00\x00\x00\x63\x6f\x69\x6f\x6e\x00\x63"
        "\x6f\x6d\x70\x72\x65\x73\x73\x69\x6f\x6e\x00\x01\x00\x00\x00\x03\x64\x61\x74\x61\x57\x69\x6e\x64"
        "\x6f\x77\x00\x62\x6f\x78\x32\x69\x00\x00\x10\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\xd9\xff"
        "\x00\x00\x05\x00\x00\x00\x64\x69\x73\x70\x6c\x61\x00\x00\x00\x00\x01\x06\x00\x00\x00\x00\x00\x00"
        "\x00\x00\x70\x0f\x00\x69\x78\x65\x6c\x41\x73\x70\x00\x00\x00\x00\x00\x00\xb2\xb2\xb2\xb2\xb2\xb2"
        "\x00\x00\x00\x85\x2d\x1f\x90",
        175);
    LinearImage out;
    const std::string problem = decode_linear_image(bytes, ImageLimits{}, out);
    EXPECT_EQ(problem, "16767233x1281 pixels: more than 16384 across or down");
}

// Thousands of channels: 256 lines of them would be more than the largest image the limits allow.
// Refused from the header (OpenEXR itself would read the file).
TEST(LinearOutput, AnExrOfTooManyChannelsIsRefusedFromItsHeader) {
    const std::string path = temp_path("channels.exr");
    {
        Imf::Header header(1000, 1);
        header.compression() = Imf::NO_COMPRESSION;
        for (int c = 0; c < 5000; ++c) {
            std::string name = c == 0 ? "R" : "c";
            if (c > 0) name += std::to_string(c);
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        }
        std::vector<float> zeros(1000, 0.0f);
        Imf::FrameBuffer fb;
        fb.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(zeros.data()), sizeof(float), 0));
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(1);
    }
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LinearImage out;
    EXPECT_EQ(decode_linear_image(bytes, ImageLimits{}, out), "too many channels (5000) for an image of this width");
    std::remove(path.c_str());
}

}  // namespace whitted

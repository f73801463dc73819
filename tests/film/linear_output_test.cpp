// Linear output: .pfm and .exr keep the film's radiance unclamped, to the float; written atomically
// like the 8-bit formats.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <gtest/gtest.h>

#include "film/film.h"
#include "film/image_io.h"

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
}  // namespace whitted

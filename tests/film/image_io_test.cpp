// Image files: what write_image refuses before it writes a byte, and what it writes.
#include <filesystem>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

TEST(ImageIo, RoundTripsEveryLosslessFormatRowZeroAtTheTop) {
    const std::string dir = test::make_temp_dir();
    Image img(3, 2);
    for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = std::uint8_t(40 * i);
    for (const char* ext : {".png", ".bmp", ".ppm"}) {
        SCOPED_TRACE(ext);
        const std::string path = dir + "/a" + ext;
        ASSERT_EQ(write_image(img, path), "");
        Image back;
        ASSERT_EQ(read_image(path, back), "");
        EXPECT_EQ(back.width, 3);
        EXPECT_EQ(back.height, 2);
        EXPECT_EQ(back.rgb, img.rgb);
    }
}

TEST(ImageIo, RefusesSizesItsEncodersCannotCount) {
    // 30000 × 30000 RGB is 2.7 GB, more than stb's PNG and BMP writers count in an int; JPEG
    // stores its sizes in 16 bits. Refused from the size alone, before any pixel is looked at (these
    // test images carry none), and nothing is written.
    const std::string dir = test::make_temp_dir();
    Image huge;
    huge.width = 30000;
    huge.height = 30000;
    for (const char* ext : {".png", ".bmp"}) {
        SCOPED_TRACE(ext);
        const std::string err = write_image(huge, dir + "/h" + ext);
        EXPECT_NE(err.find("30000x30000 is too large"), std::string::npos) << err;
        EXPECT_NE(err.find("use .ppm"), std::string::npos) << err;
    }
    Image wide;
    wide.width = 70000;
    wide.height = 2;
    EXPECT_NE(write_image(wide, dir + "/h.jpg").find("at most 65535"), std::string::npos);
    // Below the limits, an image whose pixels do not fill its size is refused too.
    Image wrong(4, 4);
    wrong.rgb.resize(3);
    EXPECT_NE(write_image(wrong, dir + "/w.png").find("do not match"), std::string::npos);
    // A long strip is fine as PNG.
    Image strip(70000, 1);
    EXPECT_EQ(write_image(strip, dir + "/s.png"), "");
    for (const char* name : {"/h.png", "/h.bmp", "/h.jpg", "/w.png"}) EXPECT_FALSE(fs::exists(dir + name)) << name;
}

TEST(ImageIo, RefusesExactlyThePngsStbCannotEncode) {
    // Issue 15, finding 1: 32768 × 21842 passed the old check and overflowed stb's zlib buffer.
    // stb's buffer holds at most 1,610,612,734 bytes of zlib stream, which for 9-bit literals
    // allows (3w + 1)·h ≤ 1,431,655,757 filtered bytes. At w = 32768 a row is 98,305 bytes:
    // 98,305 × 14,563 = 1,431,615,715 fits, 98,305 × 14,564 = 1,431,714,020 does not.
    EXPECT_NE(output_problem(32768, 21842, "a.png").find("too large"), std::string::npos);
    EXPECT_EQ(output_problem(32768, 14563, "a.png"), "");
    EXPECT_NE(output_problem(32768, 14564, "a.png").find("32768x14564 is too large for .png"), std::string::npos);
    // A square: 3w² + w ≤ 1,431,655,757 gives w = 21845 (3·21845² + 21845 = 1,431,633,920;
    // at 21846: 1,431,764,994).
    EXPECT_EQ(output_problem(21845, 21845, "a.png"), "");
    EXPECT_NE(output_problem(21846, 21846, "a.png"), "");
    // BMP: 54 + 4·⌈3w/4⌉·h ≤ INT_MAX. w = 32768: 98,304 bytes a row, h ≤ 21,845 (2,147,450,934 bytes).
    EXPECT_EQ(output_problem(32768, 21845, "a.bmp"), "");
    EXPECT_NE(output_problem(32768, 21846, "a.bmp"), "");
}

}  // namespace
}  // namespace whitted

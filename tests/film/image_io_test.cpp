// Image files: what write_image refuses before it writes a byte, and what it writes.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "film/png_encode.h"
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
    // 30000 × 30000 RGB is 2.7 GB, more than stb's BMP writer counts in an int; JPEG
    // stores its sizes in 16 bits. Refused from the size alone, before any pixel is looked at (these
    // test images carry none), and nothing is written.
    const std::string dir = test::make_temp_dir();
    Image huge;
    huge.width = 30000;
    huge.height = 30000;
    for (const char* ext : {".bmp"}) {
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

// 32768 × 21842 passed the old check and overflowed stb's zlib buffer (an int
// capacity doubling past INT_MAX). PNGs are now compressed by zlib in bands: no size limit of
// their own. BMP's is stb's sum 54 + 4·⌈3w/4⌉·h ≤ INT_MAX: at w = 32768 (98,304 bytes a row)
// h ≤ 21,845 (2,147,450,934 bytes).
TEST(ImageIo, PngHasNoEncoderLimitAndBmpStbsExactOne) {
    EXPECT_EQ(output_problem(32768, 21842, "a.png"), "");
    EXPECT_EQ(output_problem(32768, 32768, "a.png"), "");
    EXPECT_EQ(output_problem(32768, 21845, "a.bmp"), "");
    EXPECT_NE(output_problem(32768, 21846, "a.bmp").find("32768x21846 is too large for .bmp"), std::string::npos);
}

// Finding 10: the PNG encoder compresses bands of about 4 MB on several threads. An image of
// 1500 × 3000 (4,501 bytes a filtered row: 931 rows a band, 4 bands) decodes (by stb_image, an
// independent decoder) to the same pixels, and the file is the same for 1, 2 and 3 threads.
TEST(ImageIo, PngInBandsDecodesToThePixelsWhateverTheThreads) {
    Image img(1500, 3000);
    std::uint32_t state = 12345;
    for (std::size_t i = 0; i < img.rgb.size(); ++i) {
        state = state * 1664525u + 1013904223u;  // noise in some rows, smooth in others
        img.rgb[i] = (i / (1500 * 3)) % 7 == 0 ? std::uint8_t(state >> 24) : std::uint8_t(i / 3 % 1500 / 6);
    }
    std::vector<std::string> files;
    for (int threads : {1, 2, 3}) {
        std::string bytes;
        ASSERT_TRUE(encode_png(img, [&](const void* d, std::size_t n) { bytes.append(static_cast<const char*>(d), n); },
                               threads));
        files.push_back(bytes);
    }
    EXPECT_EQ(files[0], files[1]);
    EXPECT_EQ(files[0], files[2]);
    const std::string dir = test::make_temp_dir();
    ASSERT_EQ(write_image(img, dir + "/bands.png"), "");
    Image back;
    ASSERT_EQ(read_image(dir + "/bands.png", back), "");
    ASSERT_EQ(back.width, 1500);
    ASSERT_EQ(back.height, 3000);
    EXPECT_TRUE(back.rgb == img.rgb);
    EXPECT_EQ(fs::file_size(dir + "/bands.png"), files[0].size());
}

// Every chunk's CRC, computed here bit by bit as the PNG specification's sample code does (not
// with zlib, which the encoder uses), and the spec's own IEND chunk: strict decoders (libpng, so
// ImageMagick and GIMP) refuse a file with one bad CRC, where stb_image ignores them.
std::uint32_t png_crc(const std::string& bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

TEST(ImageIo, PngChunksCarryTheirCrcsAndTheFileEndsWithTheStandardIend) {
    Image img(7, 5);
    for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = std::uint8_t(37 * i);
    std::string png;
    ASSERT_TRUE(encode_png(img, [&](const void* d, std::size_t n) { png.append(static_cast<const char*>(d), n); }, 1));
    // Length 0, "IEND", CRC AE 42 60 82: the twelve bytes every PNG ends with.
    const std::string iend("\0\0\0\0IEND\xAE\x42\x60\x82", 12);
    ASSERT_GE(png.size(), 8u + 12u);
    EXPECT_EQ(png.substr(png.size() - 12), iend);
    int chunks = 0;
    for (std::size_t at = 8; at + 12 <= png.size(); ++chunks) {
        const auto byte = [&](std::size_t i) { return std::uint32_t(std::uint8_t(png[i])); };
        const auto be32 = [&](std::size_t i) { return byte(i) << 24 | byte(i + 1) << 16 | byte(i + 2) << 8 | byte(i + 3); };
        const std::size_t length = be32(at);
        ASSERT_LE(at + 12 + length, png.size());
        EXPECT_EQ(be32(at + 8 + length), png_crc(png.substr(at + 4, 4 + length)))
            << "chunk " << chunks << " (" << png.substr(at + 4, 4) << ")";
        at += 12 + length;
    }
    EXPECT_GE(chunks, 3);  // IHDR, IDAT, IEND at least
}

// Rewriting an image made a 0600 file 0644, and replaced a symbolic link to
// the image with a new file. The file a link leads to is rewritten (the link stays), with its
// permissions.
TEST(ImageIo, RewritingKeepsThePermissionsAndWritesThroughALink) {
    const std::string dir = test::make_temp_dir();
    fs::create_directories(dir + "/real");
    const std::string real = dir + "/real/out.png", via = dir + "/out.png";
    Image one(2, 2), two(3, 3);
    ASSERT_EQ(write_image(one, real), "");
    fs::permissions(real, fs::perms::owner_read | fs::perms::owner_write);
    fs::create_symlink("real/out.png", via);
    ASSERT_EQ(write_image(two, via), "");
    EXPECT_TRUE(fs::is_symlink(via));
    Image back;
    ASSERT_EQ(read_image(real, back), "");
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(fs::status(real).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
    ASSERT_EQ(write_linear_image(LinearImage{2, 1, {glm::vec3(0.5f), glm::vec3(2.0f)}, {}}, dir + "/real/l.exr"), "");
    fs::permissions(dir + "/real/l.exr", fs::perms::owner_read | fs::perms::owner_write);
    ASSERT_EQ(write_linear_image(LinearImage{1, 1, {glm::vec3(1.0f)}, {}}, dir + "/real/l.exr"), "");
    EXPECT_EQ(fs::status(dir + "/real/l.exr").permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir + "/real")) ++files;
    EXPECT_EQ(files, 2) << "no temporary file is left behind";
}

// An EXR that could not be written (a full disk) said "the image could not be
// encoded"; the system's reason is given. A file size limit stands in for the full disk here (in a
// child process: the limit is the process's), with SIGXFSZ ignored as the command-line tools do.
TEST(ImageIo, AnExrThatCannotBeWrittenSaysWhy) {
    const std::string dir = test::make_temp_dir();
    int pipe_fds[2];
    ASSERT_EQ(pipe(pipe_fds), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        setrlimit(RLIMIT_FSIZE, &limit);
        LinearImage big{256, 256, std::vector<glm::vec3>(256 * 256), {}};
        for (std::size_t i = 0; i < big.rgb.size(); ++i) big.rgb[i] = glm::vec3(float(i % 977), float(i % 13), 0.1f * float(i));
        const std::string err = write_linear_image(big, dir + "/big.exr");
        (void)!write(pipe_fds[1], err.data(), err.size());
        _exit(0);
    }
    close(pipe_fds[1]);
    std::string err;
    char buf[256];
    for (ssize_t n; (n = read(pipe_fds[0], buf, sizeof buf)) > 0;) err.append(buf, std::size_t(n));
    close(pipe_fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_NE(err.find("File too large"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(dir + "/big.exr"));
    for (const auto& e : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << e.path();
}

}  // namespace
}  // namespace whitted

// The one door files from others come through (base/read_file.h): regular files only, within a size
// limit, and for --untrusted only from inside the folders given, links followed only while they
// stay inside.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "base/read_file.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

TEST(ReadFile, AFileReadWholeTakesItsSizeNotTwice) {
    // Larger than the door's 1 MiB pieces: asking whether the file ended must not grow the string
    // (its capacity doubling, the text copied into the new block with the old one still held).
    const std::string dir = test::make_temp_dir();
    const std::string text(3 * 1024 * 1024 + 17, 'x');
    const std::string file = test::write_file(dir, "big.txt", text);
    const FileContents c = read_regular_file(file, std::size_t(64) << 20);
    ASSERT_TRUE(c.ok()) << c.error;
    EXPECT_EQ(c.bytes, text);
    EXPECT_LE(c.bytes.capacity(), text.size() + 4096);
    // Exactly at the limit still reads, one byte over still does not.
    EXPECT_TRUE(read_regular_file(file, text.size()).ok());
    EXPECT_FALSE(read_regular_file(file, text.size() - 1).ok());
}

TEST(ReadFile, OnlyRegularFilesWithinTheLimit) {
    const std::string dir = test::make_temp_dir();
    const std::string file = test::write_file(dir, "a.txt", "twelve bytes");
    FileContents r = read_regular_file(file, 100);
    EXPECT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.bytes, "twelve bytes");
    struct stat st {};
    ASSERT_EQ(stat(file.c_str(), &st), 0);
    EXPECT_EQ(r.inode, std::uint64_t(st.st_ino));  // what was opened is what was read
    EXPECT_NE(read_regular_file(file, 11).error.find("it is 12 bytes, more than the limit of 11 bytes"),
              std::string::npos);
    EXPECT_NE(read_regular_file("/dev/zero", 100).error.find("not a regular file"), std::string::npos);
    ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0600), 0);
    EXPECT_NE(read_regular_file(dir + "/fifo", 100).error.find("not a regular file"), std::string::npos);
    EXPECT_EQ(read_regular_file(dir, 100).error, "it is a directory");
    r = read_regular_file(dir + "/none", 100);
    EXPECT_TRUE(r.missing);
}

class Confined : public ::testing::TestWithParam<bool> {
protected:
    void SetUp() override {
        read_file_testing::force_part_by_part(GetParam());
        root_ = test::make_temp_dir();
        in_ = root_ + "/class/alice";
        fs::create_directories(in_ + "/sub");
        test::write_file(in_, "mine.txt", "mine");
        test::write_file(in_ + "/sub", "deep.txt", "deep");
        test::write_file(root_, "secret.txt", "SECRET");
    }
    void TearDown() override { read_file_testing::force_part_by_part(false); }
    FileContents read(const std::string& path) {
        const Confinement inside({in_});
        return read_regular_file(path, 1000, nullptr, &inside);
    }
    std::string root_, in_;
};

TEST_P(Confined, ReadsInsideTheFolder) {
    EXPECT_EQ(read(in_ + "/mine.txt").bytes, "mine");
    EXPECT_EQ(read(in_ + "/sub/deep.txt").bytes, "deep");
    EXPECT_EQ(read(in_ + "/sub/../mine.txt").bytes, "mine");  // `..` that stays inside
    // The folder reached by another spelling (a link to it): its files are still inside.
    fs::create_symlink(in_, root_ + "/alice-link");
    const Confinement by_link({root_ + "/alice-link"});
    EXPECT_EQ(read_regular_file(in_ + "/mine.txt", 1000, nullptr, &by_link).bytes, "mine");
    EXPECT_EQ(read_regular_file(root_ + "/alice-link/mine.txt", 1000, nullptr, &by_link).bytes, "mine");
}

TEST_P(Confined, OutsideIsMissingWhicheverWayItIsReached) {
    const FileContents missing = read(in_ + "/nothing.txt");
    EXPECT_TRUE(missing.missing);
    auto same_as_missing = [&](const std::string& path) {
        const FileContents r = read(path);
        EXPECT_TRUE(r.bytes.empty()) << path;
        EXPECT_TRUE(r.missing) << path;
        EXPECT_EQ(r.error, missing.error) << path;
    };
    same_as_missing(in_ + "/../../secret.txt");      // `..` out
    same_as_missing(root_ + "/secret.txt");          // named outright
    same_as_missing(root_ + "/nothing-either.txt");  // not there, outside: the same answer
    fs::create_symlink("../../secret.txt", in_ + "/up.txt");
    same_as_missing(in_ + "/up.txt");  // a relative link out
    fs::create_symlink(root_ + "/secret.txt", in_ + "/abs.txt");
    same_as_missing(in_ + "/abs.txt");  // an absolute link out
    fs::create_symlink(root_, in_ + "/updir");
    same_as_missing(in_ + "/updir/secret.txt");  // a linked folder out
    fs::create_symlink("/proc/self/root/" + root_ + "/secret.txt", in_ + "/magic.txt");
    same_as_missing(in_ + "/magic.txt");
}

TEST_P(Confined, LinksInsideAreFollowedWhereTheKernelCanKeepThemInside) {
    fs::create_symlink("sub/deep.txt", in_ + "/alias.txt");
    const FileContents r = read(in_ + "/alias.txt");
    if (GetParam()) {
        EXPECT_TRUE(r.missing) << "part by part, no link is followed";
    } else {
        EXPECT_EQ(r.bytes, "deep") << r.error;
    }
}

INSTANTIATE_TEST_SUITE_P(ReadFile, Confined, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "PartByPart" : "Openat2"; });

}  // namespace
}  // namespace whitted

// Frame ranges, frame times and the numbered names of an animation's files.
#include <gtest/gtest.h>

#include "session/frame_sequence.h"

namespace whitted {
namespace {

TEST(FrameSequence, RangesAreReadAsWritten) {
    const auto r = parse_frame_range("1..24");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->first, 1);
    EXPECT_EQ(r->last, 24);
    EXPECT_EQ(r->count(), 24);
    const auto one = parse_frame_range("7");
    ASSERT_TRUE(one);
    EXPECT_EQ(one->first, 7);
    EXPECT_EQ(one->last, 7);
    EXPECT_TRUE(parse_frame_range("0..999999"));
    for (const char* bad : {"", "..", "1..", "..2", "2..1", "-1..3", "1...3", "1..2..3", "a..b", "1.5..2", "0..1000000",
                            " 1..2", "1..2 "})
        EXPECT_FALSE(parse_frame_range(bad)) << bad;
}

TEST(FrameSequence, FrameNIsAtTimeNOverFps) {
    EXPECT_EQ(frame_time(0, 24.0f), 0.0f);
    EXPECT_EQ(frame_time(24, 24.0f), 1.0f);
    EXPECT_EQ(frame_time(3, 4.0f), 0.75f);
    // The float nearest n / fps (1/3 is not a float: the one rounded once, not twice).
    EXPECT_EQ(frame_time(1, 3.0f), float(1.0 / 3.0));
    EXPECT_EQ(frame_time(7, 0.5f), 14.0f);
}

TEST(FrameSequence, NumberedNamesSortInFrameOrder) {
    EXPECT_EQ(frame_path("out.png", 1), "out.0001.png");
    EXPECT_EQ(frame_path("out.png", 0), "out.0000.png");
    EXPECT_EQ(frame_path("dir/walk.exr", 123), "dir/walk.0123.exr");
    EXPECT_EQ(frame_path("dir/walk.exr", 12345), "dir/walk.12345.exr");
    EXPECT_EQ(frame_path("a.b/out", 5), "a.b/out.0005");  // the folder's dot is not an extension
}

}  // namespace
}  // namespace whitted

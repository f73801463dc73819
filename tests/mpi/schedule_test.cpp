// whitted-mpi's schedule: every tile handed out exactly once before the tail, guided share sizes
// (about remaining / (2 · ranks), at least what the rank renders at once), duplicates only at the
// tail and only to another rank, a resumed job skipping its finished tiles, and --verify's two
// copies of every tile on two different ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "schedule.h"

namespace whitted::mpi {
namespace {

TEST(Schedule, GuidedSharesCoverEveryTileOnceInScanOrder) {
    Schedule s(100, 2);
    // remaining / (2 · ranks), rounded up: 100/4 = 25, 75/4 → 19, 56/4 = 14, 42/4 → 11, ...
    std::vector<std::size_t> sizes;
    std::vector<int> seen;
    for (int r = 0;; r = 1 - r) {
        std::vector<int> share = s.next(r, 1);
        if (share.empty() || std::count(seen.begin(), seen.end(), share[0])) break;
        sizes.push_back(share.size());
        seen.insert(seen.end(), share.begin(), share.end());
        if (int(seen.size()) == 100) break;
    }
    ASSERT_GE(sizes.size(), 4u);
    EXPECT_EQ(sizes[0], 25u);
    EXPECT_EQ(sizes[1], 19u);
    EXPECT_EQ(sizes[2], 14u);
    EXPECT_EQ(sizes[3], 11u);
    std::vector<int> all(100);
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(seen, all);  // scan order, each once
}

TEST(Schedule, NeverLessThanTheRankRendersAtOnce) {
    Schedule s(10, 4);
    EXPECT_EQ(s.next(0, 8).size(), 8u);   // guided would say 2
    EXPECT_EQ(s.next(1, 8).size(), 2u);   // what is left
}

TEST(Schedule, ShuffledOrderIsAPermutation) {
    Schedule s(50, 1, 42);
    std::vector<int> got;
    for (std::vector<int> share; !(share = s.next(0, 1)).empty() && got.size() < 50;)
        got.insert(got.end(), share.begin(), share.end());
    ASSERT_EQ(got.size(), 50u);
    std::vector<int> sorted = got;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::set<int>(got.begin(), got.end()).size(), 50u);
    EXPECT_NE(got, sorted);
}

TEST(Schedule, TailDuplicatesGoToAnotherRankOnceAndTheFirstAnswerCounts) {
    Schedule s(4, 2);
    const std::vector<int> a = s.next(0, 4);  // rank 0 holds every tile
    ASSERT_EQ(a.size(), 4u);
    EXPECT_TRUE(s.next(0, 4).empty());  // never its own tiles again
    EXPECT_EQ(s.arrive(0), 1);
    const std::vector<int> dup = s.next(1, 2);  // the tail: two of the three still out
    EXPECT_EQ(dup, (std::vector<int>{1, 2}));
    EXPECT_EQ(s.next(1, 2), (std::vector<int>{3}));
    EXPECT_TRUE(s.next(1, 2).empty());  // each copied once
    EXPECT_EQ(s.duplicates_sent(), 3);
    EXPECT_EQ(s.arrive(1), 1);
    EXPECT_EQ(s.arrive(1), 2);  // the second copy is a duplicate, compared with the first
    EXPECT_EQ(s.done_count(), 2);
    EXPECT_FALSE(s.all_done());
    for (int t : {2, 3}) s.arrive(t);
    EXPECT_TRUE(s.all_done());
}

TEST(Schedule, ResumedTilesAreNotHandedOut) {
    std::vector<bool> done(6, false);
    done[1] = done[4] = true;
    Schedule s(6, 1, 0, done);
    EXPECT_EQ(s.done_count(), 2);
    std::vector<int> got;
    for (std::vector<int> share; got.size() < 4 && !(share = s.next(0, 1)).empty();)
        got.insert(got.end(), share.begin(), share.end());
    EXPECT_EQ(got, (std::vector<int>{0, 2, 3, 5}));
}

// Hands out every tile of `s` to ranks asking in turn (each `threads` at once) until none gets
// anything; returns per tile the ranks that got it.
std::vector<std::vector<int>> hand_out_all(Schedule& s, int ranks, int threads) {
    std::vector<std::vector<int>> got(std::size_t(s.tile_count()));
    for (int idle = 0, r = 0; idle < ranks; r = (r + 1) % ranks) {
        const std::vector<int> share = s.next(r, threads);
        idle = share.empty() ? idle + 1 : 0;
        for (int t : share) got[std::size_t(t)].push_back(r);
    }
    return got;
}

TEST(Schedule, VerifyHandsEveryTileToTwoDifferentRanksWithoutATail) {
    for (int ranks : {2, 3, 5})
        for (std::uint64_t seed : {0, 7}) {
            Schedule s(57, ranks, seed, {}, 2);
            const std::vector<std::vector<int>> got = hand_out_all(s, ranks, 3);
            for (int t = 0; t < 57; ++t) {
                ASSERT_EQ(got[std::size_t(t)].size(), 2u) << "tile " << t << ", " << ranks << " ranks";
                EXPECT_NE(got[std::size_t(t)][0], got[std::size_t(t)][1]) << "tile " << t;
            }
            EXPECT_EQ(s.duplicates_sent(), 0);
        }
}

TEST(Schedule, VerifyLeavesARanksOwnTilesToAnother) {
    Schedule s(4, 2, 0, {}, 2);
    EXPECT_EQ(s.next(0, 4), (std::vector<int>{0, 1, 2, 3}));  // rank 0: every first copy
    EXPECT_TRUE(s.next(0, 4).empty());                        // nothing it may render twice
    EXPECT_EQ(s.next(1, 4), (std::vector<int>{0, 1, 2, 3}));  // the second copies: rank 1
    EXPECT_TRUE(s.next(1, 4).empty());
}

TEST(Schedule, VerifiedTileIsDoneAtItsSecondCopy) {
    std::vector<bool> done(3, false);
    done[2] = true;  // resumed: done already, never handed out again
    Schedule s(3, 2, 0, done, 2);
    EXPECT_EQ(s.done_count(), 1);
    EXPECT_EQ(s.arrive(0), 1);
    EXPECT_FALSE(s.is_done(0));
    EXPECT_EQ(s.arrive(0), 2);
    EXPECT_TRUE(s.is_done(0));
    EXPECT_EQ(s.arrive(1), 1);
    EXPECT_FALSE(s.all_done());
    EXPECT_EQ(s.arrive(1), 2);
    EXPECT_TRUE(s.all_done());
    const std::vector<std::vector<int>> got = hand_out_all(s, 2, 1);
    EXPECT_TRUE(got[2].empty());
}

TEST(Schedule, VerifySharesStayGuided) {
    // 100 tiles twice over 2 ranks: the first share is a quarter of the 200 copies to render.
    Schedule s(100, 2, 0, {}, 2);
    EXPECT_EQ(s.next(0, 1).size(), 50u);
    EXPECT_EQ(s.next(1, 1).size(), 38u);  // 150 / 4, rounded up
}

TEST(Schedule, StoppedHandsOutNothing) {
    Schedule s(6, 1);
    s.stop();
    EXPECT_TRUE(s.next(0, 1).empty());
}

}  // namespace
}  // namespace whitted::mpi

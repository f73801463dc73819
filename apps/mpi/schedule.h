#pragma once
// Which tiles go to which rank, in what order: no MPI here, so it is tested on its own.
// Guided chunks (about remaining / (2 · ranks) tiles, never fewer than the asking rank renders at
// once) so that the image finishes evenly; at the tail, tiles still out are handed once more to
// ranks that would otherwise idle, and the first answer counts. With two copies (--verify) every
// tile is handed to two different ranks and is done when both have arrived; there is no tail.
#include <cstdint>
#include <vector>

namespace whitted::mpi {

class Schedule {
public:
    // `done` (optional, tile_count long): tiles already finished (a resumed render). seed 0:
    // tiles in scan order; otherwise a shuffled order (tests: the image must not depend on it).
    // copies 2: every tile rendered by two different ranks (needs at least two ranks).
    Schedule(int tile_count, int ranks, std::uint64_t seed = 0, const std::vector<bool>& done = {}, int copies = 1);

    // The next tiles for `rank`, which renders `min_tiles` at once; empty when there is nothing
    // (left) to hand it. At the tail these are duplicates of tiles another rank holds; with two
    // copies, the second pass hands each tile to a rank other than its first. Never more than
    // kMaxShare tiles (a share's pixels travel in one message).
    std::vector<int> next(int rank, int min_tiles);
    static constexpr int kMaxShare = 4096;

    // A copy of tile t has arrived: how many have, this one included. The tile is done when
    // `copies()` have; the first is kept, any other compared with it.
    int arrive(int t);

    // Interrupted: hand out nothing more.
    void stop() { stopped_ = true; }

    bool all_done() const { return done_count_ == int(done_.size()); }
    bool is_done(int t) const { return done_[std::size_t(t)]; }
    int done_count() const { return done_count_; }
    int tile_count() const { return int(done_.size()); }
    int duplicates_sent() const { return duplicates_; }
    int copies() const { return copies_; }

private:
    std::vector<int> next_first(int rank, int want);
    std::vector<int> next_second(int rank, int want);
    std::vector<int> next_tail(int rank, int want);
    std::size_t guided(std::size_t left, int want) const;

    int ranks_, copies_;
    std::vector<int> order_;  // tiles not yet handed out, in hand-out order, from cursor_ on
    std::size_t cursor_ = 0;
    std::vector<bool> done_;
    std::vector<int> holder_;  // the rank that first got tile t (-1: not handed out), -2: copied already
    std::vector<int> out_;     // tiles handed out and not done (the tail's candidates)
    std::vector<int> second_;  // two copies: the rank that got tile t's second copy (-1: not yet)
    std::size_t second_cursor_ = 0, second_left_ = 0;  // the second pass, over order_ again
    std::vector<int> arrived_;  // copies of tile t arrived
    int done_count_ = 0, duplicates_ = 0;
    bool stopped_ = false;
};

}  // namespace whitted::mpi

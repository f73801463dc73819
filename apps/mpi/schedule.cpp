#include "schedule.h"

#include <algorithm>
#include <numeric>
#include <random>

namespace whitted::mpi {

Schedule::Schedule(int tile_count, int ranks, std::uint64_t seed, const std::vector<bool>& done, int copies)
    : ranks_(std::max(1, ranks)), copies_(std::clamp(copies, 1, 2)), done_(std::size_t(tile_count), false),
      holder_(std::size_t(tile_count), -1), arrived_(std::size_t(tile_count), 0) {
    for (int t = 0; t < tile_count; ++t)
        if (std::size_t(t) < done.size() && done[std::size_t(t)]) {
            done_[std::size_t(t)] = true;
            arrived_[std::size_t(t)] = copies_;
            ++done_count_;
        } else {
            order_.push_back(t);
        }
    if (seed != 0) std::shuffle(order_.begin(), order_.end(), std::mt19937_64(seed));
    if (copies_ > 1) {
        second_.assign(std::size_t(tile_count), -1);
        second_left_ = order_.size();
    }
}

// Guided: big chunks first (few requests), small ones near the end (an even finish).
std::size_t Schedule::guided(std::size_t left, int want) const {
    const std::size_t g = (left + 2 * std::size_t(ranks_) - 1) / (2 * std::size_t(ranks_));
    return std::min({left, std::max(std::size_t(want), g), std::size_t(kMaxShare)});
}

std::vector<int> Schedule::next(int rank, int min_tiles) {
    if (stopped_) return {};
    const int want = std::clamp(min_tiles, 1, kMaxShare);
    if (cursor_ < order_.size()) return next_first(rank, want);
    if (copies_ > 1) return next_second(rank, want);
    return next_tail(rank, want);
}

std::vector<int> Schedule::next_first(int rank, int want) {
    // Sized by all the work left, the second copies included, so that the first pass does not end
    // in a few big shares.
    const std::size_t n = std::min(order_.size() - cursor_, guided(order_.size() - cursor_ + second_left_, want));
    std::vector<int> tiles;
    for (std::size_t i = 0; i < n; ++i) {
        const int t = order_[cursor_++];
        holder_[std::size_t(t)] = rank;
        out_.push_back(t);
        tiles.push_back(t);
    }
    return tiles;
}

std::vector<int> Schedule::next_second(int rank, int want) {
    std::vector<int> tiles;
    const std::size_t n = guided(second_left_, want);
    for (std::size_t i = second_cursor_; i < order_.size() && tiles.size() < n; ++i) {
        const int t = order_[i];
        if (second_[std::size_t(t)] >= 0 || holder_[std::size_t(t)] == rank) continue;
        second_[std::size_t(t)] = rank;
        tiles.push_back(t);
    }
    second_left_ -= tiles.size();
    while (second_cursor_ < order_.size() && second_[std::size_t(order_[second_cursor_])] >= 0) ++second_cursor_;
    return tiles;  // empty: what is left was this rank's first copy, for another rank
}

// The tail: tiles another rank still holds, each copied once, to whoever asks first.
std::vector<int> Schedule::next_tail(int rank, int want) {
    std::vector<int> tiles;
    out_.erase(std::remove_if(out_.begin(), out_.end(), [&](int t) { return done_[std::size_t(t)]; }), out_.end());
    for (int t : out_) {
        if (int(tiles.size()) >= want) break;
        int& h = holder_[std::size_t(t)];
        if (h == rank || h == -2) continue;
        h = -2;
        tiles.push_back(t);
        ++duplicates_;
    }
    return tiles;
}

int Schedule::arrive(int t) {
    int& n = arrived_[std::size_t(t)];
    ++n;
    if (n == copies_) {
        done_[std::size_t(t)] = true;
        ++done_count_;
    }
    return n;
}

}  // namespace whitted::mpi

#include "schedule.h"

#include <algorithm>
#include <numeric>
#include <random>

namespace whitted::mpi {

Schedule::Schedule(int tile_count, int ranks, std::uint64_t seed, const std::vector<bool>& done)
    : ranks_(std::max(1, ranks)), done_(std::size_t(tile_count), false), holder_(std::size_t(tile_count), -1) {
    for (int t = 0; t < tile_count; ++t)
        if (std::size_t(t) < done.size() && done[std::size_t(t)]) {
            done_[std::size_t(t)] = true;
            ++done_count_;
        } else {
            order_.push_back(t);
        }
    if (seed != 0) std::shuffle(order_.begin(), order_.end(), std::mt19937_64(seed));
}

std::vector<int> Schedule::next(int rank, int min_tiles) {
    std::vector<int> tiles;
    if (stopped_) return tiles;
    const int want = std::clamp(min_tiles, 1, kMaxShare);
    const std::size_t left = order_.size() - cursor_;
    if (left > 0) {
        // Guided: big chunks first (few requests), small ones near the end (an even finish).
        const std::size_t guided = (left + 2 * std::size_t(ranks_) - 1) / (2 * std::size_t(ranks_));
        const std::size_t n = std::min({left, std::max(std::size_t(want), guided), std::size_t(kMaxShare)});
        for (std::size_t i = 0; i < n; ++i) {
            const int t = order_[cursor_++];
            holder_[std::size_t(t)] = rank;
            out_.push_back(t);
            tiles.push_back(t);
        }
        return tiles;
    }
    // The tail: tiles another rank still holds, each copied once, to whoever asks first.
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

bool Schedule::finish(int t) {
    if (done_[std::size_t(t)]) return false;
    done_[std::size_t(t)] = true;
    ++done_count_;
    return true;
}

}  // namespace whitted::mpi

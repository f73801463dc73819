#pragma once
// The messages between rank 0 (the master, which also renders) and the workers.
//   worker → master  Request  {int32 threads}                 twice at the start: two requests in flight
//                    Result   ResultHeader, then per tile {int32 index, pixels}; want_more = a request
//                    Bye      WorkerStats                     nothing in flight, nothing queued: done
//   master → worker  Assign   AssignHeader, then per tile {int32 index, [pixels before], [active bytes]}:
//                             the answer to a request, once there is work of the pass under way (a
//                             request is kept while there is none); no tiles = the job is over
//                    Cancel   (empty)                         stop now and send what is finished
//                    Finish   {int32 exit code}               after the image is written
// A result names its pass: one that comes in after its pass ended (a tile handed out twice at the
// tail of a pass) is of no use.
#include <cstdint>
#include <cstring>
#include <vector>

#include "tiles.h"

namespace whitted::mpi {

enum Tag : int { kRequest = 1, kResult, kBye, kAssign, kCancel, kFinish };

struct ResultHeader {
    std::int32_t tiles = 0;
    std::int32_t want_more = 0;
    std::uint64_t rays = 0;
    std::int32_t pass = 0;
    std::int32_t unused = 0;
};

struct AssignHeader {
    std::int32_t tiles = 0;
    std::int32_t pass = 0;
    std::int32_t sample_begin = 0, sample_end = 0;
    std::int32_t with_pixels = 0, with_active = 0;  // each tile carries its pixels before, its active bytes
};

struct WorkerStats {
    double busy = 0, wall = 0;
    std::uint64_t bytes_sent = 0;
    std::int32_t tiles = 0, threads = 0;
    RayCounts rays;  // of every share the rank rendered (a tile handed out twice counted twice)
};

// The Result message of a rendered share.
inline std::vector<char> pack_result(const RenderedShare& share, const TileGrid& grid, bool want_more) {
    ResultHeader h{std::int32_t(share.tiles.size()), want_more ? 1 : 0, share.rays, share.pass, 0};
    std::vector<char> out(reinterpret_cast<const char*>(&h), reinterpret_cast<const char*>(&h) + sizeof h);
    for (int t : share.tiles) {
        const std::int32_t i = t;
        out.insert(out.end(), reinterpret_cast<const char*>(&i), reinterpret_cast<const char*>(&i) + sizeof i);
        append_tile_pixels(share.film, grid.tile(t), out);
    }
    return out;
}

// The Assign message of `share`: the header, the tile indices, then each tile's pixels before the
// pass (`before`, the whole image's; none in the first pass), then each tile's active bytes
// (`active`, the whole image's; none without adaptive sampling).
inline std::vector<char> pack_assign(const Share& share, const TileGrid& grid, const Film* before,
                                     const std::vector<std::uint8_t>* active) {
    const AssignHeader h{std::int32_t(share.tiles.size()), share.pass, share.sample_begin, share.sample_end,
                         before ? 1 : 0, active ? 1 : 0};
    std::vector<char> out(reinterpret_cast<const char*>(&h), reinterpret_cast<const char*>(&h) + sizeof h);
    for (int t : share.tiles) {
        const std::int32_t i = t;
        out.insert(out.end(), reinterpret_cast<const char*>(&i), reinterpret_cast<const char*>(&i) + sizeof i);
    }
    if (before)
        for (int t : share.tiles) append_tile_pixels(*before, grid.tile(t), out);
    if (active)
        for (int t : share.tiles) {
            const Tile r = grid.tile(t);
            for (int y = r.y0; y < r.y1; ++y) {
                const auto* row = active->data() + std::size_t(y) * std::size_t(grid.width);
                out.insert(out.end(), row + r.x0, row + r.x1);
            }
        }
    return out;
}

// The share an Assign message carries; false if it is cut short or names a tile not in the grid.
inline bool unpack_assign(const char* p, const char* end, const TileGrid& grid, Share& share) {
    AssignHeader h;
    if (end - p < std::ptrdiff_t(sizeof h)) return false;
    std::memcpy(&h, p, sizeof h);
    p += sizeof h;
    share.pass = h.pass;
    share.sample_begin = h.sample_begin;
    share.sample_end = h.sample_end;
    share.tiles.clear();
    if (h.tiles < 0 || end - p < std::ptrdiff_t(sizeof(std::int32_t)) * h.tiles) return false;
    for (int i = 0; i < h.tiles; ++i) {
        std::int32_t t = 0;
        std::memcpy(&t, p, sizeof t);
        p += sizeof t;
        if (t < 0 || t >= grid.count()) return false;
        share.tiles.push_back(t);
    }
    if (share.tiles.empty()) return true;
    if (h.with_pixels) {
        share.before = Film(grid.width, grid.height, box_of(grid, share.tiles));
        for (int t : share.tiles)
            if (!read_tile_pixels(p, end, grid.tile(t), share.before)) return false;
    }
    if (h.with_active) {
        share.active.assign(std::size_t(grid.width) * std::size_t(grid.height), 0);
        for (int t : share.tiles) {
            const Tile r = grid.tile(t);
            for (int y = r.y0; y < r.y1; ++y) {
                if (end - p < r.width()) return false;
                std::memcpy(share.active.data() + std::size_t(y) * std::size_t(grid.width) + std::size_t(r.x0), p,
                            std::size_t(r.width()));
                p += r.width();
            }
        }
    }
    return true;
}

}  // namespace whitted::mpi

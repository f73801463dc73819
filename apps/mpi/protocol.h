#pragma once
// The messages between rank 0 (the master, which also renders) and the workers.
//   worker → master  Request  {int32 threads}                 twice at the start: two requests in flight
//                    Result   ResultHeader, then per tile {int32 index, pixels}; want_more = a request
//                    Bye      WorkerStats                     nothing in flight, nothing queued: done
//   master → worker  Assign   int32 tile indices              the answer to every request (none = no work)
//                    Cancel   (empty)                         stop now and send what is finished
//                    Finish   {int32 exit code}               after the image is written
#include <cstdint>
#include <vector>

#include "tiles.h"

namespace whitted::mpi {

enum Tag : int { kRequest = 1, kResult, kBye, kAssign, kCancel, kFinish };

struct ResultHeader {
    std::int32_t tiles = 0;
    std::int32_t want_more = 0;
    std::uint64_t rays = 0;
};

struct WorkerStats {
    double busy = 0, wall = 0;
    std::uint64_t bytes_sent = 0;
    std::int32_t tiles = 0, threads = 0;
};

// The Result message of a rendered share.
inline std::vector<char> pack_result(const RenderedShare& share, const TileGrid& grid, bool want_more) {
    ResultHeader h{std::int32_t(share.tiles.size()), want_more ? 1 : 0, share.rays};
    std::vector<char> out(reinterpret_cast<const char*>(&h), reinterpret_cast<const char*>(&h) + sizeof h);
    for (int t : share.tiles) {
        const std::int32_t i = t;
        out.insert(out.end(), reinterpret_cast<const char*>(&i), reinterpret_cast<const char*>(&i) + sizeof i);
        append_tile_pixels(share.film, grid.tile(t), out);
    }
    return out;
}

}  // namespace whitted::mpi

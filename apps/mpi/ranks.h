#pragma once
// The two roles of a whitted-mpi job once every rank has the scene: rank 0 drives the render
// session, hands out each pass's tiles, renders too, merges, checkpoints and writes the image; the
// others render what they are given.
#include <atomic>
#include <cstdint>
#include <string>

#include "interrupt.h"
#include <memory>

#include "render/load_scene.h"
#include "render_options.h"
#include "session_run.h"
#include "tiles.h"

namespace whitted::mpi {

// Exit code when two ranks render the same tile to different bytes (the ranks are not alike); the
// same as a time limit's (cli::kExitTimeout): the message says which.
constexpr int kExitMismatch = 4;

struct RankSetup {
    const Integrator* integrator = nullptr;
    RenderJob job;  // the whole image, this rank's threads
    TileGrid grid;
    int rank = 0, ranks = 1, threads = 1;
    TestKnobs knobs;
    const std::atomic<bool>* interrupted = nullptr;
    // Rank 0 only:
    const cli::RenderOptions* options = nullptr;
    const cli::SessionLimits* limits = nullptr;  // --timeout, --time-limit
    std::shared_ptr<const Scene> scene;
    const LoadResult* loaded = nullptr;  // its texture and mesh files (what a checkpoint may not be)
    std::uint64_t inputs = 0;            // the hash of every input byte (a checkpoint's key)
    std::uint64_t schedule_seed = 0;
    bool verify = false;  // every tile rendered by two ranks and compared
    double grace_seconds = 0.5;
    int interrupt_after_tiles = 0;  // test-only: Ctrl-C as the Nth tile of the job is merged
    int frame = -1;                 // frame n of --frames: written only whole, no checkpoint
    double setup_seconds = 0, broadcast_seconds = 0;
    std::size_t broadcast_bytes = 0;
};

// Both return the exit code of the job (the same on every rank).
int run_master(const RankSetup& s);
int run_worker(const RankSetup& s);

}  // namespace whitted::mpi

#pragma once
// The two roles of a whitted-mpi job once every rank has the scene: rank 0 hands out tiles,
// renders too, merges, checkpoints and writes the image; the others render what they are given.
#include <atomic>
#include <cstdint>
#include <string>

#include "interrupt.h"
#include "render_options.h"
#include "session/checkpoint.h"
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
    const cli::Deadline* deadline = nullptr;  // --timeout
    CheckpointKey checkpoint_key;
    std::uint64_t schedule_seed = 0;
    bool verify = false;  // every tile rendered by two ranks and compared
    std::string checkpoint, resume;
    double checkpoint_seconds = 5, grace_seconds = 0.5;
    double setup_seconds = 0, broadcast_seconds = 0;
    std::size_t broadcast_bytes = 0;
};

// Both return the exit code of the job (the same on every rank).
int run_master(const RankSetup& s);
int run_worker(const RankSetup& s);

}  // namespace whitted::mpi

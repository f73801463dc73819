#pragma once
// One image of a whitted-mpi job, after the options: the scene shared with every rank, the render
// across them and, on rank 0, the image written. whitted-mpi renders one (the usual job) or one per
// frame of --frames.
#include <chrono>
#include <cstdint>

#include "ranks.h"
#include "render_options.h"
#include "scene_share.h"
#include "session_run.h"

namespace whitted::mpi {

// whitted-mpi's own options (and its hidden test knobs), beside whitted's.
struct MpiOptions {
    int tile_size = 32;
    double grace = 0.5;
    std::uint64_t schedule_seed = 0;
    bool verify = false;
    TestKnobs knobs;
    int interrupt_after_tiles = 0;
};

struct ImageJob {
    const cli::RenderOptions* options = nullptr;  // o.output is this image's file
    const MpiOptions* mpi = nullptr;
    int rank = 0, ranks = 1;
    const cli::SessionLimits* limits = nullptr;  // rank 0 only
    std::chrono::steady_clock::time_point start;
    int frame = -1;  // a frame of --frames: its file is written only whole
};

// Collective: renders `shared`'s scene across the ranks; rank 0 writes the image. The exit code, the
// same on every rank.
int render_image(const ImageJob& job, const SharedScene& shared);

// Collective: every frame of o.settings.frames whose file does not exist yet, in order; the scene is
// shared once when it does not move. The exit code, the same on every rank.
int render_frames(const ImageJob& job);

}  // namespace whitted::mpi

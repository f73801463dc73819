#pragma once
// The start of a job: every rank checks it runs the same binary with the same options; rank 0
// reads the scene and texture files and broadcasts their bytes; every rank builds the same scene.
#include <atomic>
#include <cstdint>
#include <string>

#include "render/load_scene.h"
#include "interrupt.h"
#include "render_options.h"
#include "session_run.h"

namespace whitted::mpi {

// Collective. True on every rank when all run the same executable (its bytes) with the same
// arguments; otherwise rank 0 has printed which rank differs.
bool same_binary_and_options(int argc, char** argv, int rank, int ranks);

struct SharedScene {
    LoadResult loaded;
    int code = 0;                 // the same on every rank: 0, or the exit code (rank 0 has reported why)
    std::uint64_t hash = 0;       // of the scene text and texture bytes
    std::size_t bytes = 0;        // broadcast
    double broadcast_seconds = 0, load_seconds = 0;
};

// Collective: rank 0 loads o.scene_path (reporting its diagnostics once, and that a limit of
// `limits` ran out if one did), the others build the scene from the broadcast bytes. `again`: the
// same file read at another time (--frames), whose warnings were said at the first read.
SharedScene share_scene(const cli::RenderOptions& o, int rank, const std::atomic<bool>* cancel,
                        const cli::SessionLimits* limits, bool again = false);

}  // namespace whitted::mpi

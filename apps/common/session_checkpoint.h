#pragma once
// --checkpoint FILE and --resume FILE of whitted and whitted-mpi (session/checkpoint.h) around the
// render session: the key of the job, the refusals, the state a
// resume goes on from, and the file kept up to date as tiles and passes finish.
#include <atomic>
#include <cstdint>
#include <string>

#include "render/load_scene.h"
#include "render_options.h"
#include "session/checkpoint.h"
#include "session/session.h"

namespace whitted::cli {

// True when the job keeps or resumes a checkpoint.
inline bool uses_checkpoint(const RenderSettings& s) { return !s.checkpoint.empty() || !s.resume.empty(); }

// The scene, loaded as load_scene does; with a checkpoint or a resume asked for, `inputs` is the
// hash of every input byte (the scene text, its textures and meshes, kept for it while loading).
LoadResult load_scene_and_inputs(const RenderOptions& o, const std::atomic<bool>* cancel, std::uint64_t& inputs);

class SessionCheckpoint {
public:
    // Refuses a --checkpoint that is a file the job reads or writes, puts the state of --resume
    // FILE into `session`, starts --checkpoint FILE with it. Returns kExitOk or the code to exit
    // with (the reason printed after `program`'s name).
    int start(const RenderOptions& o, const LoadResult& loaded, std::uint64_t inputs, Session& session,
              const char* program = "whitted");
    // The tiles resumed (whole passes count every tile), for the progress line.
    int tiles_resumed() const { return tiles_resumed_; }
    // From worker threads: a tile of the pass under way is finished, its pixels in `film`.
    void tile_done(const Tile& t, const Film& film);
    // After a whole pass: the file afresh with it (the tiles of the next pass follow it).
    void pass_done(const Session& session);
    void flush() { writer_.flush(true); }

private:
    CheckpointWriter writer_;
    CheckpointKey key_;
    std::string path_;
    double every_ = 5;
    int pass_samples_ = 0;  // the samples per pixel of the pass under way
    int tiles_resumed_ = 0;
    std::string program_ = "whitted";
};

}  // namespace whitted::cli

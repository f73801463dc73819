// --frames in whitted-mpi: the frames one after another, each rendered across every rank as one
// image is (its tiles handed out), so a sequence takes the whole cluster frame by frame and its
// bytes are whitted's --frames. Rank 0 decides which frames are still to do and says so to all.
#include <mpi.h>

#include <filesystem>
#include <iostream>

#include "image_job.h"
#include "session/frame_sequence.h"

namespace whitted::mpi {

int render_frames(const ImageJob& given) {
    cli::RenderOptions o = *given.options;
    ImageJob job = given;
    job.options = &o;
    const FrameRange range = *parse_frame_range(o.settings.frames);  // validated with the settings
    const std::string output = o.output;
    SharedScene shared;
    bool loaded = false;
    for (int n = range.first; n <= range.last; ++n) {
        o.output = frame_path(output, n);
        // 1: render it; 0: skip it (its file exists: an earlier run did it); -1: stop (Ctrl-C or
        // --timeout came between two frames).
        int next = 1;
        if (job.rank == 0) {
            std::error_code ec;
            if (cli::interrupt_flag().load() || (job.limits && job.limits->timed_out())) {
                const bool timed_out = job.limits && job.limits->timed_out();
                std::cerr << "whitted-mpi: "
                          << (timed_out ? "error: the time limit (--timeout) ran out" : "interrupted")
                          << " before frame " << n << ": " << o.output
                          << " not written (run the same command again to go on)\n";
                next = -1;
            } else if (std::filesystem::exists(o.output, ec)) {
                std::cerr << "whitted-mpi: frame " << n << ": " << o.output << " exists, skipped\n";
                next = 0;
            }
        }
        MPI_Bcast(&next, 1, MPI_INT, 0, MPI_COMM_WORLD);
        if (next < 0) return cli::kExitInterrupted;
        if (next == 0) continue;
        o.settings.time = frame_time(n, o.settings.fps);
        // A scene that does not move is the same scene at every frame: shared once.
        if (!loaded || shared.loaded.stats.moves) {
            shared = share_scene(o, job.rank, &cli::interrupt_flag(), job.limits, loaded);
            if (shared.code != 0) return shared.code;
            loaded = true;
        }
        job.frame = n;
        if (const int code = render_image(job, shared); code != cli::kExitOk) return code;
    }
    return cli::kExitOk;
}

}  // namespace whitted::mpi

#include "frames_command.h"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "accel/scene.h"
#include "film/image_io.h"
#include "interrupt.h"
#include "load_report.h"
#include "progress.h"
#include "render/load_scene.h"
#include "session/frame_sequence.h"
#include "session/session.h"
#include "session_run.h"

namespace whitted::cli {

int render_frames(const RenderOptions& given) {
    RenderOptions o = given;
    const FrameRange range = *parse_frame_range(o.settings.frames);  // validated with the settings
    if (std::string problem = output_unwritable(frame_path(o.output, range.first)); !problem.empty()) {
        std::cerr << "whitted: error: " << problem << "\n";
        return kExitIo;
    }
    install_interrupt_handler();
    const SessionLimits limits(o.settings, std::chrono::steady_clock::now());  // --timeout (frames take no budget)
    LoadResult loaded;
    bool hinted = false;
    for (int n = range.first; n <= range.last; ++n) {
        const std::string path = frame_path(o.output, n);
        std::error_code ec;
        if (std::filesystem::exists(path, ec)) {
            std::cerr << "whitted: frame " << n << ": " << path << " exists, skipped\n";
            continue;
        }
        o.settings.time = frame_time(n, o.settings.fps);
        if (!loaded.ok() || loaded.stats.moves) {
            const bool first = !loaded.ok();
            loaded = load_scene(o.scene_path, load_options(o, &interrupt_flag()));
            if (!first && loaded.cancelled) {  // the frames before this one are written
                std::cerr << "whitted: "
                          << (limits.timed_out() ? "error: the time limit (--timeout) ran out" : "interrupted")
                          << " before frame " << n << ": " << path
                          << " not written (run the same command again to go on)\n";
                return limits.timed_out() ? kExitTimeout : kExitInterrupted;
            }
            // The warnings once; a later load fails only as the first did not (a file changed meanwhile).
            if (first || !loaded.ok())
                if (int code = report_load(loaded, o, "whitted", limits.timed_out() ? "--timeout" : nullptr);
                    code != kExitOk)
                    return code;
        }
        const RenderJob job = render_job(o, &interrupt_flag());
        if (const std::string hint = sampled_effects_hint(loaded.stats.effects, job.sampling, job.integrator.mode);
            !hint.empty() && !hinted) {
            std::cerr << "whitted: note: " << hint << "\n";
            hinted = true;
        }
        Session session(loaded.scene, job);
        ProgressLine progress(job.tile_count() * int(session.pass_ends().size()), !o.quiet && isatty(STDERR_FILENO));
        SessionCheckpoint none;  // frames keep no checkpoint: a frame's file is its
        const SessionOutcome outcome =
            run_passes(session, limits, none, [&](const Tile&, const Film&) { progress.tile_done(); });
        progress.finish();
        if (o.stats && outcome.complete) {
            RenderStats total = outcome.last;
            total.rays = session.rays();
            total.seconds = session.seconds();
            print_stats(loaded.stats, total, session.samples_done(), session.passes_done());
        }
        RenderOptions frame = o;
        frame.output = path;
        if (const int code = write_frame(session, outcome, frame, limits, n, "whitted", kExitTimeout); code != kExitOk)
            return code;
    }
    return kExitOk;
}

}  // namespace whitted::cli

// whitted: the command-line renderer. Scene file in, image file out.
// Exit codes: 0 success, 1 bad usage, 2 bad scene, 3 I/O failure (the scene cannot be read, the
// image cannot be written, out of memory), 4 --timeout ran out, 130 interrupted.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <iostream>
#include <string>

#include "accel/scene.h"
#include "film/image_io.h"
#include "compare_command.h"
#include "explain_command.h"
#include "frames_command.h"
#include "grade_command.h"
#include "inspect_command.h"
#include "interrupt.h"
#include "load_report.h"
#include "progress.h"
#include "render/load_scene.h"
#include "render_options.h"
#include "session/run_limits.h"
#include "session/session.h"
#include "session_checkpoint.h"
#include "session_run.h"

namespace {

using namespace whitted;
using namespace whitted::cli;
using Clock = std::chrono::steady_clock;

int run(int argc, char** argv) {
    const auto start = Clock::now();
    CLI::App app{"whitted: a Whitted-style ray tracer for SceneView/Ray .sc scene files"};
    app.set_version_flag("--version", "whitted 0.1.0");
    app.footer("Exit codes: 0 done, 1 bad usage, 2 bad scene (FILE:LINE:COL: error: ...), 3 I/O failure, "
               "4 --timeout ran out, 130 interrupted (the last whole pass, or the tiles of the first, is written "
               "to NAME.partial.EXT).");
    RenderOptions o;
    add_render_options(app, o, Frontend::Cli);
    std::string inspect;  // whitted only (whitted-mpi has no use for it): not in the settings table
    app.add_option("--inspect", inspect,
                   "Print what made pixel X,Y (column, row; row 0 at the top) with these render settings: its "
                   "object and the scene lines above it, material, lights, shadows, reflected and refracted rays, "
                   "and its colour in parts. Renders nothing else, writes no image")
        ->type_name("X,Y");
    InspectOutputs inspect_outputs;
    app.add_option("--ray-tree", inspect_outputs.ray_tree_file,
                   "With --inspect: also write the pixel's ray tree (the camera, shadow, reflected and refracted "
                   "rays of its detailed sample, every bounce) to FILE: .obj (polylines, which Blender opens) or .json")
        ->type_name("FILE");
    app.add_flag("--json", inspect_outputs.json, "With --inspect: print the pixel's ray tree as JSON instead of the report");
    // Test-only (hidden): Ctrl-C as the Nth tile of the render finishes, at a known place.
    int interrupt_after_tiles = 0;
    app.add_option("--test-interrupt-after-tiles", interrupt_after_tiles)->group("");
    // Test-only (hidden): Ctrl-C as the load starts (a test timing a signal against the load raced it).
    bool interrupt_at_load = false;
    app.add_flag("--test-interrupt-at-load", interrupt_at_load)->group("");
    if (int code = parse_render_options(app, o, argc, argv, "whitted", Frontend::Cli); code != kExitOk)
        return code < 0 ? 0 : code;
    const RenderSettings& s = o.settings;
    std::optional<PixelArg> pixel;
    if (app.get_option("--inspect")->count() > 0) {
        std::string problem;
        pixel = parse_pixel_arg(inspect, s.width, s.height, problem);
        if (!pixel) {
            std::cerr << "whitted: error: " << problem << "\n";
            return kExitUsage;
        }
    }
    if (pixel && !s.frames.empty()) {
        std::cerr << "whitted: error: --inspect looks at one image: give it the frame's time with --time (frame n "
                     "is at n / --fps)\n";
        return kExitUsage;
    }
    if (!pixel && (!inspect_outputs.ray_tree_file.empty() || inspect_outputs.json)) {
        std::cerr << "whitted: error: --ray-tree and --json go with --inspect X,Y (the pixel whose rays they give)\n";
        return kExitUsage;
    }
    if (const std::string problem = inspect_outputs_problem(inspect_outputs); !problem.empty()) {
        std::cerr << "whitted: error: " << problem << "\n";
        return problem.rfind("--ray-tree", 0) == 0 ? kExitUsage : kExitIo;
    }
    // A missing folder or a read-only one is found now, not after a long render (as POV-Ray does).
    if (std::string problem = pixel || s.aov_file.empty() ? "" : output_unwritable(s.aov_file); !problem.empty()) {
        std::cerr << "whitted: error: " << problem << "\n";
        return kExitIo;
    }
    if (std::string problem = pixel ? "" : output_unwritable(o.output); !problem.empty()) {
        std::cerr << "whitted: error: " << problem << "\n";
        return kExitIo;
    }

    if (!s.frames.empty()) return render_frames(o);

    install_interrupt_handler();  // from here on Ctrl-C stops the load or the render
    const SessionLimits limits(s, start);
    std::uint64_t inputs = 0;
    if (interrupt_at_load) std::raise(SIGINT);
    LoadResult loaded = load_scene_and_inputs(o, &interrupt_flag(), inputs);
    if (int code = report_load(loaded, o, "whitted", limits.ran_out()); code != kExitOk) return code;

    RenderJob job = render_job(o, &interrupt_flag());
    const std::size_t left = memory_limit(s) - std::min(memory_limit(s), o.for_image);
    if (const std::string problem = pixel ? "" : aov_problem(*loaded.scene, job, left); !problem.empty()) {
        std::cerr << "whitted: error: --aov: " << problem << "\n";
        return kExitUsage;
    }
    if (pixel) {
        const int code = print_inspection(*loaded.scene, job, *pixel, o.scene_path, inspect_outputs);
        if (code != kExitInterrupted) return code;
        if (limits.timed_out())
            std::cerr << "whitted: error: the time limit of " << timeout_seconds(s)
                      << " s (--timeout) ran out while inspecting\n";
        else
            std::cerr << "whitted: interrupted while inspecting\n";
        return limits.timed_out() ? kExitTimeout : kExitInterrupted;
    }
    if (const std::string hint = sampled_effects_hint(loaded.stats.effects, job.sampling, job.integrator.mode);
        !hint.empty())
        std::cerr << "whitted: note: " << hint << "\n";

    Session session(loaded.scene, job);
    SessionCheckpoint checkpoint;
    if (uses_checkpoint(s))
        if (int code = checkpoint.start(o, loaded, inputs, session); code != kExitOk) return code;
    const int passes = int(session.pass_ends().size());
    ProgressLine progress(job.tile_count() * passes - checkpoint.tiles_resumed(), !o.quiet && isatty(STDERR_FILENO));
    std::atomic<int> tiles_finished{0};
    const SessionOutcome outcome = run_passes(session, limits, checkpoint, [&](const Tile&, const Film&) {
        progress.tile_done();
        if (++tiles_finished == interrupt_after_tiles) std::raise(SIGINT);
    });
    progress.finish();
    RenderStats total = outcome.last;
    total.rays = session.rays();
    total.seconds = session.seconds();
    if (o.stats) print_stats(loaded.stats, total, session.samples_done(), session.passes_done());
    return write_session(session, outcome, o, limits, "whitted", kExitTimeout);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]) == "compare") return whitted::cli::compare_main(argc - 1, argv + 1);
    if (argc > 1 && std::string(argv[1]) == "explain") return whitted::cli::explain_main(argc - 1, argv + 1);
    if (argc > 1 && std::string(argv[1]) == "grade") return whitted::cli::grade_main(argc - 1, argv + 1);
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "whitted: error: out of memory (a smaller image or scene may fit)\n";
    } catch (const std::exception& e) {
        std::cerr << "whitted: error: " << e.what() << "\n";
    }
    return kExitIo;
}

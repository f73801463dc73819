// whitted: the command-line renderer. Scene file in, image file out.
// Exit codes: 0 success, 1 bad usage, 2 bad scene, 3 I/O failure (the scene cannot be read, the
// image cannot be written, out of memory), 4 --timeout ran out, 130 interrupted.
#include <unistd.h>

#include <iostream>
#include <string>

#include "film/image_io.h"
#include "inspect_command.h"
#include "interrupt.h"
#include "load_report.h"
#include "progress.h"
#include "render/load_scene.h"
#include "render/renderer.h"
#include "render_options.h"
#include "run_limits.h"

namespace {

using namespace whitted;
using namespace whitted::cli;

int run(int argc, char** argv) {
    CLI::App app{"whitted: a Whitted-style ray tracer for SceneView/Ray .sc scene files"};
    app.set_version_flag("--version", "whitted 0.1.0");
    app.footer("Exit codes: 0 done, 1 bad usage, 2 bad scene (FILE:LINE:COL: error: ...), 3 I/O failure, "
               "4 --timeout ran out, 130 interrupted (the part rendered so far is written to NAME.partial.EXT).");
    RenderOptions o;
    add_render_options(app, o);
    add_timeout_option(app, o);
    std::string inspect;  // whitted only (whitted-mpi has no use for it): not in render_options
    app.add_option("--inspect", inspect,
                   "Print what made pixel X,Y (column, row; row 0 at the top) with these render settings: its "
                   "object and the scene lines above it, material, lights, shadows, reflected and refracted rays, "
                   "and its colour in parts. Renders nothing else, writes no image")
        ->type_name("X,Y");
    if (int code = parse_render_options(app, o, argc, argv, "whitted"); code != kExitOk) return code < 0 ? 0 : code;
    std::optional<PixelArg> pixel;
    if (app.get_option("--inspect")->count() > 0) {
        std::string problem;
        pixel = parse_pixel_arg(inspect, o.width, o.height, problem);
        if (!pixel) {
            std::cerr << "whitted: error: " << problem << "\n";
            return kExitUsage;
        }
    }
    // A missing folder or a read-only one is found now, not after a long render (as POV-Ray does).
    if (std::string problem = pixel ? "" : output_unwritable(o.output); !problem.empty()) {
        std::cerr << "whitted: error: " << problem << "\n";
        return kExitIo;
    }

    install_interrupt_handler();  // from here on Ctrl-C stops the load or the render
    const Deadline deadline(o.timeout);
    LoadResult loaded = load_scene(o.scene_path, load_options(o, &interrupt_flag()));
    if (int code = report_load(loaded, o, "whitted", deadline.timed_out()); code != kExitOk) return code;

    RenderJob job = render_job(o, &interrupt_flag());
    if (pixel) {
        const int code = print_inspection(*loaded.scene, job, *pixel, o.scene_path);
        if (code != kExitInterrupted) return code;
        if (deadline.timed_out())
            std::cerr << "whitted: error: the time limit of " << o.timeout << " s (--timeout) ran out while inspecting\n";
        else
            std::cerr << "whitted: interrupted while inspecting\n";
        return deadline.timed_out() ? kExitTimeout : kExitInterrupted;
    }
    ProgressLine progress(job.tile_count(), !o.quiet && isatty(STDERR_FILENO));
    job.on_tile = [&](const Tile&) { progress.tile_done(); };

    const auto integrator = make_integrator(*loaded.scene, job.camera_for(*loaded.scene), job.integrator);
    Film film(o.width, o.height);
    RenderStats rs = render(*integrator, job, film);
    progress.finish();

    // An interrupted render never replaces the output: a good image from an earlier run may be
    // there (a batch timeout's SIGTERM must not destroy it). Its part goes beside it, if there is
    // one and it can be written quickly.
    if (const std::string why = rs.cancelled ? why_no_partial_image(rs.tiles_done, o.width, o.height) : "";
        !why.empty()) {
        if (deadline.timed_out())
            std::cerr << "whitted: error: the time limit of " << o.timeout << " s (--timeout) ran out: " << why
                      << ": nothing written\n";
        else
            std::cerr << "whitted: interrupted: " << why << ": nothing written\n";
        return deadline.timed_out() ? kExitTimeout : kExitInterrupted;
    }
    const std::string written = rs.cancelled ? partial_image_path(o.output) : o.output;
    // .exr and .pfm keep the linear values; the 8-bit formats get them clamped (§7).
    const std::string err = is_linear_output(written) ? write_linear_image(film.to_linear(), written)
                                                      : write_image(film.to_image(), written);
    if (!err.empty()) {
        std::cerr << "whitted: error: " << err << "\n";
        return kExitIo;
    }
    if (o.stats) print_stats(loaded.stats, rs, job.sampling.samples_per_pixel());
    if (rs.cancelled && deadline.timed_out()) {
        std::cerr << "whitted: error: the time limit of " << o.timeout << " s (--timeout) ran out: wrote the "
                  << rs.tiles_done << " of " << rs.tiles_total << " tiles rendered so far to " << written << " ("
                  << o.output << " was not written)\n";
        return kExitTimeout;
    }
    if (rs.cancelled) {
        std::cerr << "whitted: interrupted: wrote the " << rs.tiles_done << " of " << rs.tiles_total
                  << " tiles rendered so far to " << written << " (" << o.output << " was not written)\n";
        return kExitInterrupted;
    }
    if (!o.quiet) std::cerr << "wrote " << o.output << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "whitted: error: out of memory (a smaller image or scene may fit)\n";
    } catch (const std::exception& e) {
        std::cerr << "whitted: error: " << e.what() << "\n";
    }
    return kExitIo;
}

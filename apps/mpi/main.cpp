// whitted-mpi: one image (or the frames of --frames, one by one) rendered across the ranks of an
// MPI job (Open MPI, Slurm).
//   mpirun -np N whitted-mpi SCENE -o OUT [every option of whitted] [--tile-size N]
//          [--checkpoint FILE [--checkpoint-every S]] [--resume FILE]
// The image is byte-identical to `whitted SCENE -o OUT` with the same options. Exit codes as
// whitted's (0, 1 usage, 2 scene, 3 I/O, 130 interrupted, also when --timeout ran out) and 4: two
// ranks rendered a tile to different bytes. Every rank exits with the same code.
#include <mpi.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <thread>

#include "image_job.h"
#include "interrupt.h"
#include "render_options.h"

namespace {

using namespace whitted;
using namespace whitted::cli;
using namespace whitted::mpi;

void add_mpi_options(CLI::App& app, MpiOptions& m) {
    app.add_option("--tile-size", m.tile_size, "Tile size in pixels: the unit handed to ranks and checkpointed")
        ->check(CLI::Range(4, 1024));
    app.add_option("--interrupt-grace", m.grace,
                   "Seconds rank 0 waits for tiles in flight after Ctrl-C/SIGTERM before writing the partial image")
        ->check(CLI::Range(0.0, 60.0));
    app.add_flag("--verify", m.verify,
                 "Render every tile on two different ranks and compare the bytes (twice the work): a check that "
                 "the machines of a cluster compute alike");
    // Test-only (hidden): the schedule in a shuffled order, a slowed rank, a rank off by a little.
    app.add_option("--test-schedule-seed", m.schedule_seed)->group("");
    app.add_option("--test-slow-rank", m.knobs.slow_rank)->group("");  // -1: every rank
    app.add_option("--test-slow-ms", m.knobs.slow_ms)->group("");
    app.add_option("--test-slow-others-ms", m.knobs.others_ms)->group("");
    app.add_option("--test-corrupt-rank", m.knobs.corrupt_rank)->group("");
    app.add_option("--test-interrupt-after-tiles", m.interrupt_after_tiles)->group("");
}

int run(int argc, char** argv, int rank, int ranks) {
    const auto start = std::chrono::steady_clock::now();
    CLI::App app{"whitted-mpi: whitted's image rendered across the ranks of an MPI job"};
    app.set_version_flag("--version", "whitted-mpi 0.1.0");
    app.footer("Run as: mpirun -np N whitted-mpi SCENE -o OUT [options]. Only rank 0 reads files. Exit codes: 0 done, "
               "1 bad usage or mismatched ranks, 2 bad scene, 3 I/O failure, 4 ranks disagree on a tile, 130 "
               "interrupted or --timeout ran out (the part rendered so far is written).");
    RenderOptions o;
    MpiOptions m;
    add_render_options(app, o, Frontend::Mpi);
    add_mpi_options(app, m);
    // whitted's own: taken, so that it is refused with a reason rather than a parser's complaint.
    std::string inspect;
    app.add_option("--inspect", inspect, "(whitted only)")->group("");
    // Every rank parses the same arguments; only rank 0 speaks.
    if (rank != 0) {
        std::cerr.setstate(std::ios::failbit);
        std::cout.setstate(std::ios::failbit);
    }
    if (int code = parse_render_options(app, o, argc, argv, "whitted-mpi", Frontend::Mpi); code != kExitOk)
        return code < 0 ? 0 : code;
    if (rank != 0) std::cerr.clear();
    if (app.get_option("--inspect")->count() > 0) {
        std::cerr << "whitted-mpi: error: --inspect is not for this program: it prints what made one pixel and "
                     "renders no image; run `whitted SCENE --inspect X,Y` with the same options\n";
        return kExitUsage;
    }
    if (!same_binary_and_options(argc, argv, rank, ranks)) return kExitUsage;
    if (m.verify && ranks < 2) {
        std::cerr << "whitted-mpi: error: --verify needs at least two ranks (mpirun -np 2 or more)\n";
        return kExitUsage;
    }

    install_interrupt_handler();
    // --timeout (and --untrusted's 60 s) and --time-limit: rank 0 stops the job as a first Ctrl-C would.
    std::optional<SessionLimits> limits;
    if (rank == 0) limits.emplace(o.settings, start);
    ImageJob job;
    job.options = &o;
    job.mpi = &m;
    job.rank = rank;
    job.ranks = ranks;
    job.limits = limits ? &*limits : nullptr;
    job.start = start;
    if (!o.settings.frames.empty()) return render_frames(job);
    const SharedScene shared = share_scene(o, rank, &interrupt_flag(), job.limits);
    if (shared.code != 0) return shared.code;
    return render_image(job, shared);
}

}  // namespace

int main(int argc, char** argv) {
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    int code = kExitIo;
    try {
        code = run(argc, argv, rank, ranks);
    } catch (const std::bad_alloc&) {
        std::cerr << "whitted-mpi: error: rank " << rank << " ran out of memory\n";
        MPI_Abort(MPI_COMM_WORLD, kExitIo);
    } catch (const std::exception& e) {
        std::cerr << "whitted-mpi: error: rank " << rank << ": " << e.what() << "\n";
        MPI_Abort(MPI_COMM_WORLD, kExitIo);
    }
    MPI_Finalize();
    return code;
}

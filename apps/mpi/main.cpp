// whitted-mpi: one image rendered across the ranks of an MPI job (Open MPI, Slurm).
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

#include "accel/scene.h"
#include "session/checkpoint.h"
#include "interrupt.h"
#include "load_report.h"
#include "ranks.h"
#include "render_options.h"
#include "scene_share.h"
#include "base/parallel_for.h"

namespace {

using namespace whitted;
using namespace whitted::cli;
using namespace whitted::mpi;

struct MpiOptions {
    int tile_size = 32;
    double grace = 0.5;
    std::uint64_t schedule_seed = 0;
    bool verify = false;
    TestKnobs knobs;
    int interrupt_after_tiles = 0;
};

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
    SharedScene shared = share_scene(o, rank, &interrupt_flag(), limits ? &*limits : nullptr);
    if (shared.code != 0) return shared.code;

    // A checkpoint is never written over what the job reads or writes (--checkpoint scene.sc
    // destroyed the scene): rank 0, which reads and writes them, decides for all.
    int refused = 0;
    const std::string& checkpoint = o.settings.checkpoint;
    if (rank == 0 && !checkpoint.empty()) {
        std::vector<std::string> inputs{o.scene_path};
        for (const auto* list : {&shared.loaded.texture_paths, &shared.loaded.mesh_paths})
            inputs.insert(inputs.end(), list->begin(), list->end());
        for (const std::string& t : o.settings.texture_dirs) inputs.push_back(t);
        if (std::string problem = checkpoint_conflict(checkpoint, o.output, inputs); !problem.empty()) {
            std::cerr << "whitted-mpi: error: " << problem << "\n";
            refused = 1;
        }
    }
    MPI_Bcast(&refused, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (refused) return kExitUsage;

    RankSetup s;
    s.job = render_job(o, nullptr);
    s.job.tile_size = m.tile_size;
    const auto integrator =
        make_integrator(*shared.loaded.scene, s.job.camera_for(*shared.loaded.scene), s.job.integrator);
    s.integrator = integrator.get();
    s.grid = {o.settings.width, o.settings.height, m.tile_size};
    s.rank = rank;
    s.ranks = ranks;
    s.threads = worker_count(o.settings.threads, std::size_t(1) << 20);
    s.job.threads = s.threads;
    s.knobs = m.knobs;
    s.interrupted = &interrupt_flag();
    if (rank != 0) return run_worker(s);
    s.options = &o;
    s.limits = &*limits;
    s.scene = shared.loaded.scene;
    s.loaded = &shared.loaded;
    s.inputs = shared.hash;  // with every setting that changes pixels and the tile grid, a checkpoint's key
    s.job.cancel = &interrupt_flag();
    s.schedule_seed = m.schedule_seed;
    s.verify = m.verify;
    s.grace_seconds = m.grace;
    s.interrupt_after_tiles = m.interrupt_after_tiles;
    s.broadcast_bytes = shared.bytes;
    s.broadcast_seconds = shared.broadcast_seconds;
    s.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (o.stats) {
        const auto& ls = shared.loaded.stats;
        std::fprintf(stderr, "objects %zu, lights %zu, textures %zu; rank 0: parse %.3fs, flatten %.3fs, textures "
                             "%.3fs, build %.3fs\n",
                     ls.objects, ls.lights, ls.textures, ls.parse_seconds, ls.flatten_seconds, ls.texture_seconds,
                     ls.build_seconds);
    }
    return run_master(s);
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

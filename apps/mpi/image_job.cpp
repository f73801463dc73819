#include "image_job.h"

#include <mpi.h>

#include <cstdio>
#include <iostream>

#include "accel/scene.h"
#include "base/parallel_for.h"
#include "session/checkpoint.h"

namespace whitted::mpi {

int render_image(const ImageJob& job, const SharedScene& shared) {
    const cli::RenderOptions& o = *job.options;
    const MpiOptions& m = *job.mpi;
    const int rank = job.rank;
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
    if (refused) return cli::kExitUsage;

    RankSetup s;
    s.job = render_job(o, nullptr);
    s.job.tile_size = m.tile_size;
    s.job.time_rays = o.stats;  // each rank times its traversals; rank 0 prints all ranks' rates
    const auto integrator =
        make_integrator(*shared.loaded.scene, s.job.camera_for(*shared.loaded.scene), s.job.integrator);
    s.integrator = integrator.get();
    s.grid = {o.settings.width, o.settings.height, m.tile_size};
    s.rank = rank;
    s.ranks = job.ranks;
    s.threads = worker_count(o.settings.threads, std::size_t(1) << 20);
    s.job.threads = s.threads;
    s.knobs = m.knobs;
    s.interrupted = &cli::interrupt_flag();
    if (rank != 0) return run_worker(s);
    s.options = &o;
    s.limits = job.limits;
    s.scene = shared.loaded.scene;
    s.loaded = &shared.loaded;
    s.inputs = shared.hash;  // with every setting that changes pixels and the tile grid, a checkpoint's key
    s.job.cancel = &cli::interrupt_flag();
    s.schedule_seed = m.schedule_seed;
    s.verify = m.verify;
    s.grace_seconds = m.grace;
    s.interrupt_after_tiles = m.interrupt_after_tiles;
    s.frame = job.frame;
    s.broadcast_bytes = shared.bytes;
    s.broadcast_seconds = shared.broadcast_seconds;
    s.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count();
    if (o.stats) {
        const auto& ls = shared.loaded.stats;
        std::fprintf(stderr, "objects %zu, lights %zu, textures %zu; rank 0: parse %.3fs, flatten %.3fs, textures "
                             "%.3fs, meshes %.3fs, build %.3fs\n",
                     ls.objects, ls.lights, ls.textures, ls.parse_seconds, ls.flatten_seconds, ls.texture_seconds,
                     ls.mesh_seconds, ls.build_seconds);
    }
    return run_master(s);
}

}  // namespace whitted::mpi

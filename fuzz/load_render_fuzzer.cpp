// libFuzzer target: any bytes as a scene file, loaded (parse, flatten, textures, BVH) and rendered
// to a small image in every mode (path tracing too). Limits are lowered so that one input stays within libFuzzer's
// time and memory budget: what is measured is that hostile input is refused, not how much fits.
#include <cstddef>
#include <cstdint>
#include <string>

#include "render/load_scene.h"
#include "render/renderer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace whitted;
    const std::string text(reinterpret_cast<const char*>(data), size);
    LoadOptions load;
    load.threads = 1;
    load.limits.max_instances = 20'000;
    load.limits.max_steps = 100'000;
    load.textures.missing = MissingTexturePolicy::Checker;
    // Textures are looked up next to a scene in a directory that does not exist: the lookup
    // runs, no file of the machine is read.
    LoadResult loaded = load_scene_text(text, "/nonexistent-whitted-fuzz/fuzz.sc", load);
    if (!loaded.ok()) return 0;
    RenderJob job;
    job.width = 12;
    job.height = 9;
    job.threads = 1;
    job.tile_size = 8;
    job.integrator.max_depth = int(size % 6);
    job.sampling.aa = 1 + int(size % 2);
    job.sampling.spp = 1 + int(size / 2 % 2);  // one sample (the lab model) or two (the §9.1 effects' sampling)
    for (RenderMode mode :
         {RenderMode::Whitted, RenderMode::Raycast, RenderMode::Normals, RenderMode::Depth, RenderMode::Path}) {
        job.integrator.mode = mode;
        Image image(job.width, job.height);
        render(*loaded.scene, job, image);
    }
    return 0;
}

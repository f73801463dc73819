// libFuzzer target: any bytes as a scene file, loaded (parse, flatten, textures, meshes, BVH) and rendered
// to a small image in every mode (path tracing too). Limits are lowered so that one input stays within libFuzzer's
// time and memory budget: what is measured is that hostile input is refused, not how much fits.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "render/load_scene.h"
#include "render/renderer.h"

// An input is a scene, optionally followed by this line and the bytes of the OBJ file `m.obj`, which
// every `object mesh [ file m.obj ]` of the scene reads (as the ranks of an MPI job get rank 0's).
constexpr std::string_view kMeshMark = "\n===m.obj===\n";

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace whitted;
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t mark = input.find(kMeshMark);
    const std::string text = input.substr(0, mark);
    TextureFiles meshes;
    if (mark != std::string::npos) meshes["m.obj"].assign(input.begin() + long(mark + kMeshMark.size()), input.end());
    LoadOptions load;
    load.preread_meshes = &meshes;
    load.max_memory = std::size_t(512) << 20;  // within libFuzzer's memory limit
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

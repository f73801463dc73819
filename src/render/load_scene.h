#pragma once
// The library's front door: scene file → renderable Scene, every problem returned as data.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "base/read_file.h"
#include "cs1230/stage.h"
#include "parse/parser.h"
#include "render/sampled_effects.h"
#include "texture/texture_loader.h"

namespace whitted {

struct Scene;  // accel/scene.h

// Three quarters of this machine's RAM: what a scene may take by default.
std::size_t default_max_memory();

struct LoadOptions {
    bool lenient = false;
    float time = 0;   // scene time t for `velocity` / `angularrate` (scene-format.md §9.4)
    // Motion blur: the shutter is open over [time + shutter_open, time + shutter_close], and the
    // moving objects are kept apart, met at each ray's time (accel/motion_set.h).
    bool shutter = false;
    float shutter_open = 0, shutter_close = 0;
    int threads = 0;  // for building the BVH; 0 = all hardware threads
    TextureOptions textures;
    std::size_t max_file_bytes = ParseOptions{}.max_file_bytes;  // the scene file's size limit
    std::size_t max_mesh_file_bytes = std::size_t(256) << 20;     // each OBJ file's (§9.3)
    // Mesh files another process already read (an MPI job's ranks get rank 0's), by name as
    // written; with textures.keep_files, the bytes of each mesh file read go to LoadResult::mesh_files.
    const TextureFiles* preread_meshes = nullptr;
    FlattenLimits limits;  // objects drawn and steps of the instancing walk (limits.cancel is set from `cancel`)
    // The memory the scene may need: its objects (estimated from the counts before any is made),
    // its textures and its meshes together. Sets limits.max_bytes and what is left for the files.
    std::size_t max_memory = default_max_memory();
    // A CSCI 1230 file drawn as the course's Intersect stage (§9.5) draws no texture: its
    // textures are not read (one that is missing is then no error).
    cs1230::Stage cs1230_stage = cs1230::Stage::Illuminate;
    // Set by another thread (or a signal handler) to give up: every stage but the parse looks at it
    // within a fraction of a second (the parse: between the file's pieces as it is read).
    const std::atomic<bool>* cancel = nullptr;
};

struct LoadStats {
    double parse_seconds = 0, flatten_seconds = 0, texture_seconds = 0, mesh_seconds = 0, build_seconds = 0;
    std::size_t objects = 0, lights = 0, textures = 0;
    Dialect dialect = Dialect::Labs;  // which family of files the scene is written in (§9.4)
    SampledEffects effects;           // §9.1 effects, which one sample per pixel does not show
    bool moves = false;               // velocity or angularrate (§9.4): another LoadOptions::time gives another scene
};

struct LoadResult {
    std::shared_ptr<const Scene> scene;     // null when the load failed
    std::vector<Diagnostic> diagnostics;     // warnings and errors, in order
    std::size_t unlisted_warnings = 0;       // the parser's warnings past kMaxWarningsListed, only counted
    std::vector<MissingTexture> missing_textures;  // also reported in diagnostics
    std::vector<Diagnostic> path_warnings;   // warnings that hold only in --mode path (§9.2)
    TextureFiles texture_files;  // with LoadOptions::textures.keep_files: the bytes of each texture file
    TextureFiles mesh_files;     // and of each mesh file
    LoadStats stats;
    std::vector<std::string> texture_paths;  // the files the textures were read from (a viewer watches them)
    std::vector<std::string> mesh_paths;     // and the meshes
    CameraDesc camera;  // the file's camera as written (eye, focus, up, angle): where the viewer's navigation starts
    bool cancelled = false;   // LoadOptions::cancel was set: no scene, no error
    bool unreadable = false;  // the scene file could not be read (an I/O failure, not a bad scene)
    bool ok() const { return scene != nullptr; }
};

LoadResult load_scene(const std::string& path, const LoadOptions& options = {});

// Reads the scene file as load_scene does (base/read_file.h: a regular file within
// max_file_bytes; with textures.confined, only from inside its folder: a link out of it is refused).
FileContents read_scene_file(const std::string& path, const LoadOptions& options);

// The same from text already in memory; `path` names it in messages and anchors texture lookup.
LoadResult load_scene_text(const std::string& text, const std::string& path, const LoadOptions& options = {});

}  // namespace whitted

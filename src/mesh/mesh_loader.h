#pragma once
// The mesh stage of loading (scene-format.md §9.3): reads the OBJ file of every `object mesh`,
// looked up like a texture (§8) and through the same door (base/read_file.h: regular files within
// a size limit, confined to the scene's folders under --untrusted), once per file however many
// objects and instances use it, and points the mesh instances at it.
#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include "flatten/flatten.h"
#include "texture/texture_loader.h"

namespace whitted {

struct MeshOptions {
    std::vector<std::string> search_dirs;  // the --texture-path folders, as textures have them
    // For files from others (--untrusted): only from inside the scene file's folder or a search
    // dir (links followed only while they stay inside); absolute names are refused.
    bool confined = false;
    std::size_t max_file_bytes = std::size_t(256) << 20;  // per OBJ file
    std::size_t max_bytes = std::size_t(-1);  // the memory all of the scene's meshes may need together
    const std::atomic<bool>* cancel = nullptr;
    // Files another process already found and read (the ranks of an MPI job get rank 0's): each
    // name is read from these bytes and no file is looked for; a name not here is missing.
    const TextureFiles* preread = nullptr;
    bool keep_files = false;  // keep the bytes of every file read (`kept`), to send on
};

struct MeshLoadResult {
    bool ok = true;          // false: an error diagnostic says why, or cancelled
    bool cancelled = false;  // options.cancel was set
    std::size_t bytes = 0;   // the memory the meshes need, with their BVHs
    std::vector<std::string> paths;  // the files read (none with options.preread)
};

// Fills flat.scene.meshes and each mesh instance's `mesh`. A file that cannot be found or read, or
// that holds no triangle, is an error at the `file` keyword naming the paths tried (and the OBJ
// line of a syntax error); degenerate and repeated triangles are skipped with one warning per file.
// With options.keep_files, `kept` (when given) gets the bytes of each file by its name as written.
MeshLoadResult load_meshes(FlattenResult& flat, const std::string& scene_path, const MeshOptions& options,
                           std::vector<Diagnostic>& diagnostics, TextureFiles* kept = nullptr);

}  // namespace whitted

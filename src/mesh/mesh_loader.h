#pragma once
// The mesh stage of loading (scene-format.md §9.3): reads the OBJ file of every `object mesh`,
// looked up like a texture (§8), once per file however many objects and instances use it, and
// points the mesh instances at it.
#include <string>
#include <vector>

#include "flatten/flatten.h"
#include "mesh/obj_reader.h"

namespace whitted {

// Fills flat.scene.meshes and each mesh instance's `mesh`. A file that cannot be found or read,
// or that holds no triangle, is an error at the `file` keyword naming the paths tried (and the
// OBJ line of a syntax error); degenerate triangles are skipped with one warning per file.
// Returns false if there was an error.
// `confined` (--untrusted): as for textures, only files inside the scene's folder or a search dir
// (links and `..` followed), and no absolute names. No file over `max_file_bytes` is read.
bool load_meshes(FlattenResult& flat, const std::string& scene_path, const std::vector<std::string>& search_dirs,
                 std::vector<Diagnostic>& diagnostics, bool confined = false,
                 std::size_t max_file_bytes = kMaxObjFileBytes);

}  // namespace whitted

#pragma once
// Reads a Wavefront OBJ file into a TriangleMesh (scene-format.md §9.3) with tinyobjloader:
// positions, normals and texture coordinates, polygons triangulated, OBJ materials ignored.
#include <cstddef>
#include <string>

#include "data/triangle_mesh.h"

namespace whitted {

struct ObjReadResult {
    bool ok = false;
    std::string error;        // when !ok: what was wrong, with the OBJ line where there is one
    int line = 0;             // the OBJ line of the error, 0 if none
    std::size_t degenerate = 0;  // triangles skipped: zero area (or non-finite corners)
};

// The largest OBJ file read unless told otherwise (about 4 million triangles).
constexpr std::size_t kMaxObjFileBytes = std::size_t(256) << 20;

// Reads `path` (a regular file of at most `max_bytes`). Fails on a file that cannot be read, a face that names a vertex, normal or
// texture coordinate the file has not defined (or index 0), a syntax error tinyobjloader reports,
// and a file with no (non-degenerate) triangle.
ObjReadResult read_obj(const std::string& path, TriangleMesh& mesh, std::size_t max_bytes = kMaxObjFileBytes);

// The same from text in memory (`name` stands for the file in messages).
ObjReadResult read_obj_text(const std::string& text, const std::string& name, TriangleMesh& mesh);

}  // namespace whitted

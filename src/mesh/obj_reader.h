#pragma once
// Reads a Wavefront OBJ file into a TriangleMesh (scene-format.md §9.3), a line at a time in
// tinyobjloader's grammar (mesh/obj_line.h): positions, normals and texture coordinates; polygons split into triangles
// (mesh/polygon_split.h); OBJ materials ignored. Every index a face gives is checked here before
// anything is looked up with it, and nothing of the file's words is quoted in a message (a file
// from others may be anything).
#include <atomic>
#include <cstddef>
#include <string>
#include <string_view>

#include "base/read_file.h"
#include "data/triangle_mesh.h"

namespace whitted {

struct ObjLimits {
    std::size_t max_file_bytes = std::size_t(256) << 20;  // read_obj: the file's size
    // The memory the mesh may need: the file's text held (all of it, or the piece being read),
    // what the parse keeps of it, and the mesh with its BVH (kMeshBvhBytesPerTriangle): refused
    // as soon as the count passes it.
    std::size_t max_bytes = std::size_t(-1);
    const std::atomic<bool>* cancel = nullptr;  // looked at every 64 KiB of text and every few faces
};

struct ObjReadResult {
    bool ok = false;
    bool cancelled = false;      // limits.cancel was set: no mesh, no error
    std::string error;           // when !ok: what was wrong, with the OBJ line where there is one
    int line = 0;                // the OBJ line of the error, 0 if none
    std::size_t degenerate = 0;  // triangles skipped: zero area (or non-finite corners)
    std::size_t duplicates = 0;  // triangles skipped: the same three corners, in the same order, as an earlier one
    std::size_t fans = 0;        // polygons of more than kEarClipCorners corners split as fans
    std::size_t bytes = 0;       // what the mesh needs once built, with its BVH (for the memory estimate)
};

// Reads `path` through base/read_file.h (a regular file, within limits.max_file_bytes), a piece at
// a time as read_obj_file does. Fails on a file that cannot be read, a face that names a vertex,
// normal or texture coordinate the file has not defined (or vertex 0, or no number), a mesh
// needing more memory than limits.max_bytes, and a file with no (non-degenerate) triangle.
ObjReadResult read_obj(const std::string& path, TriangleMesh& mesh, const ObjLimits& limits = {});

// The same from a file opened through base/read_file.h, read 64 KiB at a time and never held
// whole (`name` stands for the file in messages; a file that cannot be read to its end says why).
ObjReadResult read_obj_file(FileReader& file, const std::string& name, TriangleMesh& mesh,
                            const ObjLimits& limits = {});

// The same from text in memory (`name` stands for the file in messages).
ObjReadResult read_obj_text(std::string_view text, const std::string& name, TriangleMesh& mesh,
                            const ObjLimits& limits = {});

}  // namespace whitted

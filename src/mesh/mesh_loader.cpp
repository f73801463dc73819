#include "mesh/mesh_loader.h"

#include <filesystem>
#include <unordered_map>

#include "mesh/obj_reader.h"
#include "texture/texture_loader.h"

namespace whitted {

bool load_meshes(FlattenResult& flat, const std::string& scene_path, const std::vector<std::string>& search_dirs,
                 std::vector<Diagnostic>& diagnostics, bool confined, std::size_t max_file_bytes) {
    const ConfinedFolders folders(scene_path, search_dirs);
    SceneData& scene = flat.scene;
    constexpr std::uint32_t kNoMesh = 0xffffffffu;
    std::vector<std::uint32_t> mesh_of_material(scene.materials.size(), kNoMesh);
    std::unordered_map<std::string, std::uint32_t> mesh_of_path;      // found file → mesh
    std::unordered_map<std::string, bool> failed;                      // name as written → reported
    bool ok = true;
    for (std::size_t m = 0; m < flat.material_sources.size(); ++m) {
        const ObjectDesc& o = *flat.material_sources[m];
        if (o.kind != ShapeKind::Mesh) continue;
        if (failed.count(o.mesh_file)) {
            ok = false;
            continue;
        }
        if (confined && std::filesystem::path(o.mesh_file).is_absolute()) {
            diagnostics.push_back({Severity::Error, o.mesh_loc,
                                   "mesh file '" + o.mesh_file + "': an absolute path, refused for a file from others "
                                   "(--untrusted): name it relative to the scene's folder"});
            failed[o.mesh_file] = true;
            ok = false;
            continue;
        }
        const std::vector<std::string> tried = texture_candidates(o.mesh_file, scene_path, search_dirs);
        std::string found, outside;
        std::error_code ec;
        for (const std::string& path : tried) {
            if (!std::filesystem::is_regular_file(path, ec)) continue;
            if (confined && !folders.contains(path)) {
                if (outside.empty()) outside = path;
                continue;
            }
            found = path;
            break;
        }
        if (found.empty()) {
            std::string message = "mesh file '" + o.mesh_file + "' not found";
            if (!outside.empty())
                message = "mesh file '" + o.mesh_file + "': '" + outside +
                          "' is outside the scene's folder and the --texture-path folders (--untrusted)";
            for (const std::string& t : tried) message += "\n    tried: " + t;
            diagnostics.push_back({Severity::Error, o.mesh_loc, message});
            failed[o.mesh_file] = true;
            ok = false;
            continue;
        }
        if (auto it = mesh_of_path.find(found); it != mesh_of_path.end()) {
            mesh_of_material[m] = it->second;
            continue;
        }
        TriangleMesh mesh;
        const ObjReadResult r = read_obj(found, mesh, max_file_bytes);
        if (!r.ok) {
            const std::string where = r.line > 0 ? found + ":" + std::to_string(r.line) : found;
            diagnostics.push_back({Severity::Error, o.mesh_loc, "cannot use mesh '" + o.mesh_file + "': " + where + ": " + r.error});
            failed[o.mesh_file] = true;
            ok = false;
            continue;
        }
        if (r.degenerate > 0)
            diagnostics.push_back({Severity::Warning, o.mesh_loc,
                                   "mesh '" + found + "': skipped " + std::to_string(r.degenerate) +
                                       " degenerate triangle" + (r.degenerate == 1 ? "" : "s") + " (zero area)"});
        const std::uint32_t index = std::uint32_t(scene.meshes.size());
        scene.meshes.push_back(std::move(mesh));
        mesh_of_path.emplace(found, index);
        mesh_of_material[m] = index;
    }
    if (!ok) return false;
    for (Instance& inst : scene.instances)
        if (inst.kind == ShapeKind::Mesh) inst.mesh = mesh_of_material[inst.material];
    return true;
}

}  // namespace whitted

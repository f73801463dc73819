#include "mesh/mesh_loader.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <unordered_map>

#include "base/read_file.h"
#include "mesh/obj_reader.h"
#include "mesh/polygon_split.h"

namespace whitted {
namespace {

std::string plural(std::size_t n, const std::string& word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// The warnings a mesh that loaded may still deserve, one line each.
void warn_about(const ObjReadResult& r, const std::string& path, const SourceLoc& loc,
                std::vector<Diagnostic>& diagnostics) {
    const std::string head = "mesh '" + path + "': ";
    if (r.degenerate > 0)
        diagnostics.push_back(
            {Severity::Warning, loc, head + "skipped " + plural(r.degenerate, "degenerate triangle") + " (zero area)"});
    if (r.duplicates > 0)
        diagnostics.push_back({Severity::Warning, loc,
                               head + "skipped " + plural(r.duplicates, "triangle") +
                                   " repeating an earlier one (the same three corners in the same order)"});
    if (r.fans > 0)
        diagnostics.push_back({Severity::Warning, loc,
                               head + "split " + plural(r.fans, "polygon") + " of more than " +
                                   std::to_string(kEarClipCorners) +
                                   " corners as fans from their first corner (right only for convex ones)"});
}

}  // namespace

MeshLoadResult load_meshes(FlattenResult& flat, const std::string& scene_path, const MeshOptions& options,
                           std::vector<Diagnostic>& diagnostics, TextureFiles* kept) {
    MeshLoadResult result;
    SceneData& scene = flat.scene;
    constexpr std::uint32_t kNoMesh = 0xffffffffu;
    std::vector<std::uint32_t> mesh_of_material(scene.materials.size(), kNoMesh);
    std::unordered_map<std::string, std::uint32_t> mesh_of_name;  // name as written → mesh (kNoMesh: failed)
    std::unordered_map<std::string, std::uint32_t> mesh_of_file;  // device:inode → mesh
    std::unique_ptr<Confinement> inside;
    if (options.confined && !options.preread)
        inside = std::make_unique<Confinement>(confinement_folders(scene_path, options.search_dirs));
    ObjLimits limits;
    limits.max_file_bytes = options.max_file_bytes;
    limits.max_bytes = options.max_bytes;
    limits.cancel = options.cancel;
    auto fail = [&](const ObjectDesc& o, const std::string& message) {
        diagnostics.push_back({Severity::Error, o.mesh_loc, message});
        mesh_of_name[o.mesh_file] = kNoMesh;
        result.ok = false;
    };
    for (std::size_t m = 0; m < flat.material_sources.size(); ++m) {
        const ObjectDesc& o = *flat.material_sources[m];
        if (o.kind != ShapeKind::Mesh) continue;
        if (auto it = mesh_of_name.find(o.mesh_file); it != mesh_of_name.end()) {
            if (it->second == kNoMesh) result.ok = false;
            mesh_of_material[m] = it->second;
            continue;
        }
        // Where the bytes come from: the file found (through the door), or what another process
        // sent. A file whose bytes are not kept to send on is read a piece at a time as it is
        // parsed, never held whole (its text is as big as the mesh made of it).
        const bool whole = options.preread || (kept && options.keep_files);
        FileContents file;
        std::unique_ptr<FileReader> reader;
        std::string found;
        std::vector<std::string> tried;
        if (options.preread) {
            const auto f = options.preread->find(o.mesh_file);
            if (f == options.preread->end()) {
                fail(o, "mesh file '" + o.mesh_file + "': not among the files received");
                continue;
            }
            file.bytes.assign(f->second.begin(), f->second.end());
            found = o.mesh_file;
        } else {
            std::string portable = o.mesh_file;
            std::replace(portable.begin(), portable.end(), '\\', '/');
            if (options.confined && std::filesystem::path(portable).is_absolute()) {
                fail(o, "mesh file '" + o.mesh_file + "': an absolute path, refused for a file from others "
                           "(--untrusted): name it relative to the scene's folder");
                continue;
            }
            std::string reason;  // why a file that is there could not be read
            for (const std::string& c : texture_candidates(o.mesh_file, scene_path, options.search_dirs)) {
                tried.push_back(c);
                if (whole) {
                    file = read_regular_file(c, options.max_file_bytes, options.cancel, inside.get());
                } else {
                    reader = std::make_unique<FileReader>(c, options.max_file_bytes, options.cancel, inside.get());
                    file = reader->info();
                }
                if (file.cancelled) return result.cancelled = true, result.ok = false, result;
                if (file.ok()) {
                    found = c;
                    break;
                }
                if (!file.missing && reason.empty()) reason = "cannot read '" + c + "': " + file.error;
            }
            if (found.empty()) {
                std::string message = "mesh file '" + o.mesh_file + "' " +
                                      (!reason.empty()    ? "could not be read: " + reason
                                       : options.confined ? "not found inside the scene's folder and the "
                                                            "--texture-path folders (--untrusted)"
                                                          : std::string("not found"));
                for (const std::string& t : tried) message += "\n    tried: " + t;
                fail(o, message);
                continue;
            }
        }
        const std::string identity = std::to_string(file.device) + ":" + std::to_string(file.inode);
        if (!options.preread)
            if (auto it = mesh_of_file.find(identity); it != mesh_of_file.end()) {  // another spelling
                mesh_of_name[o.mesh_file] = mesh_of_material[m] = it->second;
                if (kept && options.keep_files) (*kept)[o.mesh_file].assign(file.bytes.begin(), file.bytes.end());
                continue;
            }
        TriangleMesh mesh;
        const ObjReadResult r = whole ? read_obj_text(file.bytes, found, mesh, limits)
                                      : read_obj_file(*reader, found, mesh, limits);
        if (r.cancelled) return result.cancelled = true, result.ok = false, result;
        if (!r.ok) {
            const std::string where = r.line > 0 ? found + ":" + std::to_string(r.line) : found;
            fail(o, "cannot use mesh '" + o.mesh_file + "': " + where + ": " + r.error);
            continue;
        }
        warn_about(r, found, o.mesh_loc, diagnostics);
        limits.max_bytes -= std::min(limits.max_bytes, r.bytes);
        result.bytes += r.bytes;
        if (kept && options.keep_files) (*kept)[o.mesh_file].assign(file.bytes.begin(), file.bytes.end());
        const std::uint32_t index = std::uint32_t(scene.meshes.size());
        scene.meshes.push_back(std::move(mesh));
        if (!options.preread) {
            mesh_of_file.emplace(identity, index);
            result.paths.push_back(found);
        }
        mesh_of_name[o.mesh_file] = mesh_of_material[m] = index;
    }
    if (!result.ok) return result;
    for (Instance& inst : scene.instances)
        if (inst.kind == ShapeKind::Mesh) inst.mesh = mesh_of_material[inst.material];
    return result;
}

}  // namespace whitted

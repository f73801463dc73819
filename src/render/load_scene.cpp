#include "render/load_scene.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "base/read_file.h"
#include "cs1230/detect.h"
#include "cs1230/scene_reader.h"
#include "flatten/flatten.h"
#include "integrator/path_integrator.h"
#include "mesh/mesh_loader.h"
#include "texture/texture_filter.h"

namespace whitted {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

LoadResult finish(ParseResult parsed, const LoadOptions& options, double parse_seconds) {
    LoadResult result;
    auto cancelled = [&] {
        return result.cancelled = options.cancel && options.cancel->load(std::memory_order_relaxed);
    };
    result.stats.parse_seconds = parse_seconds;
    result.unreadable = parsed.unreadable;
    result.diagnostics = std::move(parsed.diagnostics);
    result.unlisted_warnings = parsed.unlisted_warnings;
    result.stats.dialect = parsed.scene.dialect;
    result.stats.moves = parsed.scene.moves;
    result.camera = parsed.scene.camera;
    if (has_errors(result.diagnostics) || cancelled()) return result;

    auto t = Clock::now();
    FlattenLimits limits = options.limits;
    limits.cancel = options.cancel;
    limits.max_bytes = std::min(limits.max_bytes, options.max_memory);
    FlattenResult flat = flatten(parsed.scene, limits);
    result.stats.flatten_seconds = since(t);
    for (auto& d : flat.diagnostics) result.diagnostics.push_back(d);
    if (flat.cancelled) return result.cancelled = true, result;
    if (!flat.ok() || cancelled()) return result;

    t = Clock::now();
    TextureOptions textures = options.textures;
    textures.cancel = options.cancel;
    const std::size_t for_objects = flat.scene.instances.size() * kBytesPerInstance;
    std::size_t left = options.max_memory - std::min(options.max_memory, for_objects);
    textures.limits.max_total_bytes = std::min(textures.limits.max_total_bytes, left);
    // Next to the scene file, or for a CSCI 1230 file in the parent of its folder (§9.5).
    const std::string& assets = parsed.scene.assets_from();
    const bool drawn_without_textures =
        parsed.scene.lighting == LightingModel::Cs1230 && options.cs1230_stage == cs1230::Stage::Intersect;
    if (!drawn_without_textures)  // (every material's texture stays -1, none)
        result.missing_textures = load_textures(flat, assets, textures, result.diagnostics, &result.texture_files,
                                                 &result.texture_paths);
    if (has_errors(result.diagnostics) || cancelled()) return result.stats.texture_seconds = since(t), result;
    for (const TextureImage& image : flat.scene.textures)
        left -= std::min(left, stored_texture_bytes(image.width, image.height, textures.limits));
    if (textures.limits.mip_levels)  // once per texture, however many objects use it
        for (const TextureImage& image : flat.scene.textures)
            flat.scene.texture_levels.push_back(build_mip_levels(image));
    result.stats.texture_seconds = since(t);
    t = Clock::now();
    // Meshes (§9.3) are looked up where textures are, through the same door, in what memory is left.
    MeshOptions meshes;
    meshes.search_dirs = options.textures.search_dirs;
    meshes.confined = options.textures.confined;
    meshes.max_file_bytes = options.max_mesh_file_bytes;
    meshes.max_bytes = left;
    meshes.cancel = options.cancel;
    meshes.preread = options.preread_meshes;
    meshes.keep_files = options.textures.keep_files;
    const MeshLoadResult mesh_load = load_meshes(flat, assets, meshes, result.diagnostics, &result.mesh_files);
    result.stats.mesh_seconds = since(t);
    result.mesh_paths = mesh_load.paths;
    if (mesh_load.cancelled || cancelled()) return result.cancelled = true, result;
    if (!mesh_load.ok) return result;

    std::vector<SourceLoc> sources;
    for (const ObjectDesc* o : flat.material_sources) sources.push_back(o->loc);
    result.path_warnings = path_mode_warnings(flat.scene, sources);
    result.stats.effects = sampled_effects(flat.scene, parsed.scene.camera);

    t = Clock::now();
    result.stats.objects = flat.scene.instances.size();
    result.stats.lights = flat.scene.lights.size();
    result.stats.textures = flat.scene.textures.size();
    const Shutter shutter{double(options.time) + options.shutter_open, double(options.time) + options.shutter_close};
    auto scene = std::make_shared<const Scene>(
        accelerate(std::move(flat.scene), options.threads, options.cancel, options.shutter ? &shutter : nullptr));
    result.stats.build_seconds = since(t);
    if (!cancelled()) result.scene = std::move(scene);
    return result;
}

}  // namespace

std::size_t default_max_memory() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return std::size_t(4) << 30;
    return std::size_t(pages) / 4 * 3 * std::size_t(page);
}

LoadResult load_scene(const std::string& path, const LoadOptions& options) {
    auto t = Clock::now();
    ParseOptions parse_options;
    parse_options.lenient = options.lenient;
    parse_options.time = options.time;
    parse_options.max_file_bytes = options.max_file_bytes;
    parse_options.cancel = options.cancel;
    ParseResult parsed;
    // A CSCI 1230 JSON file (§9.5) goes to its own reader, everything else to the format's parser.
    const bool json = cs1230::is_json_scene_file(path);
    if (json || options.textures.confined) {
        // A file from others may be a link out of its folder (to a secret whose words the parser's
        // errors would print): it is opened as the textures are, beneath its folder.
        FileContents file = read_scene_file(path, options);
        if (!file.ok() && !file.cancelled) {
            LoadResult result;
            result.unreadable = true;
            result.diagnostics.push_back({Severity::Error, SourceLoc{path, 0, 0}, "cannot read scene file: " + file.error});
            return result;
        }
        parsed.cancelled = file.cancelled;
        if (!file.cancelled)
            parsed = json ? cs1230::read_scene(file.bytes, path, {.lenient = options.lenient})
                          : parse_scene_text(file.bytes, path, parse_options);
    } else {
        parsed = parse_scene_file(path, parse_options);
    }
    if (parsed.cancelled) {
        LoadResult result;
        result.cancelled = true;
        return result;
    }
    return finish(std::move(parsed), options, since(t));
}

FileContents read_scene_file(const std::string& path, const LoadOptions& options) {
    if (!options.textures.confined) return read_regular_file(path, options.max_file_bytes, options.cancel);
    std::error_code ec;
    const Confinement folder({std::filesystem::absolute(path, ec).parent_path().string()});
    FileContents file = read_regular_file(path, options.max_file_bytes, options.cancel, &folder);
    if (file.missing) file.error = "not found inside its folder (--untrusted follows no link out of it)";
    return file;
}

LoadResult load_scene_text(const std::string& text, const std::string& path, const LoadOptions& options) {
    auto t = Clock::now();
    ParseOptions parse_options;
    parse_options.lenient = options.lenient;
    parse_options.time = options.time;
    parse_options.max_file_bytes = options.max_file_bytes;
    parse_options.cancel = options.cancel;
    ParseResult parsed = cs1230::is_json_scene(path, text)
                             ? cs1230::read_scene(text, path, {.lenient = options.lenient})
                             : parse_scene_text(text, path, parse_options);
    if (parsed.cancelled) {
        LoadResult result;
        result.cancelled = true;
        return result;
    }
    return finish(std::move(parsed), options, since(t));
}

}  // namespace whitted

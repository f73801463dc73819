#include "render/load_scene.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>

#include "base/read_file.h"
#include "cs1230/detect.h"
#include "cs1230/scene_reader.h"
#include "flatten/flatten.h"
#include "integrator/path_integrator.h"
#include "mesh/mesh_loader.h"

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
    const std::size_t for_objects = flat.scene.instances.size() * kBytesPerInstance;
    textures.limits.max_total_bytes =
        std::min(textures.limits.max_total_bytes, options.max_memory - std::min(options.max_memory, for_objects));
    // Next to the scene file, or for a CSCI 1230 file in the parent of its folder (§9.5).
    const std::string& assets = parsed.scene.assets_from();
    const bool drawn_without_textures =
        parsed.scene.lighting == LightingModel::Cs1230 && options.cs1230_stage == cs1230::Stage::Intersect;
    if (!drawn_without_textures)  // (every material's texture stays -1, none)
        result.missing_textures = load_textures(flat, assets, textures, result.diagnostics, &result.texture_files,
                                                 &result.texture_paths);
    result.stats.texture_seconds = since(t);
    if (has_errors(result.diagnostics) || cancelled()) return result;
    // Meshes (§9.3) are looked up where textures are, and confined with them (--untrusted).
    if (!load_meshes(flat, assets, options.textures.search_dirs, result.diagnostics, options.textures.confined,
                     options.textures.limits.max_file_bytes) ||
        cancelled())
        return result;

    std::vector<SourceLoc> sources;
    for (const ObjectDesc* o : flat.material_sources) sources.push_back(o->loc);
    result.path_warnings = path_mode_warnings(flat.scene, sources);
    result.stats.effects = sampled_effects(flat.scene, parsed.scene.camera);

    t = Clock::now();
    result.stats.objects = flat.scene.instances.size();
    result.stats.lights = flat.scene.lights.size();
    result.stats.textures = flat.scene.textures.size();
    auto scene = std::make_shared<const Scene>(accelerate(std::move(flat.scene), options.threads));
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
    // A CSCI 1230 JSON file (§9.5) goes to its own reader, everything else to the format's parser.
    ParseResult parsed;
    if (cs1230::is_json_scene_file(path)) {
        FileContents file = read_regular_file(path, options.max_file_bytes, options.cancel);
        if (file.cancelled) parsed.cancelled = true;
        else if (!file.ok()) {
            parsed.diagnostics.push_back({Severity::Error, SourceLoc{path, 0, 0}, "cannot read scene file: " + file.error});
            parsed.unreadable = true;
        } else {
            parsed = cs1230::read_scene(file.bytes, path, {.lenient = options.lenient});
        }
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

LoadResult load_scene_text(const std::string& text, const std::string& path, const LoadOptions& options) {
    auto t = Clock::now();
    ParseOptions parse_options;
    parse_options.lenient = options.lenient;
    parse_options.time = options.time;
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

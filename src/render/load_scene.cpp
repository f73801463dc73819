#include "render/load_scene.h"

#include <chrono>

#include "flatten/flatten.h"
#include "integrator/path_integrator.h"

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
    result.stats.dialect = parsed.scene.dialect;
    result.camera = parsed.scene.camera;
    if (has_errors(result.diagnostics) || cancelled()) return result;

    auto t = Clock::now();
    FlattenResult flat = flatten(parsed.scene);
    result.stats.flatten_seconds = since(t);
    for (auto& d : flat.diagnostics) result.diagnostics.push_back(d);
    if (!flat.ok() || cancelled()) return result;

    t = Clock::now();
    result.missing_textures = load_textures(flat, parsed.scene.path, options.textures, result.diagnostics,
                                             &result.texture_files, &result.texture_paths);
    result.stats.texture_seconds = since(t);
    if (has_errors(result.diagnostics) || cancelled()) return result;

    std::vector<SourceLoc> sources;
    for (const ObjectDesc* o : flat.material_sources) sources.push_back(o->loc);
    result.path_warnings = path_mode_warnings(flat.scene, sources);

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

LoadResult load_scene(const std::string& path, const LoadOptions& options) {
    auto t = Clock::now();
    ParseResult parsed = parse_scene_file(path, {options.lenient, options.time});
    return finish(std::move(parsed), options, since(t));
}

LoadResult load_scene_text(const std::string& text, const std::string& path, const LoadOptions& options) {
    auto t = Clock::now();
    ParseResult parsed = parse_scene_text(text, path, {options.lenient, options.time});
    return finish(std::move(parsed), options, since(t));
}

}  // namespace whitted

#include "load_report.h"

#include <cstdio>
#include <iostream>
#include <vector>

namespace whitted::cli {
namespace {

// Warnings printed before the rest are only counted: a file with 100,000 stray brackets
// should not bury its one real message. (The parser keeps only as many of its own.)
constexpr std::size_t kMaxWarningsShown = 50;
static_assert(kMaxWarningsShown <= kMaxWarningsListed, "the parser keeps fewer warnings than are shown");

}  // namespace

int report_load(const LoadResult& loaded, const RenderOptions& o, const char* program, const char* limit) {
    std::size_t warnings = 0;
    std::vector<Diagnostic> diagnostics = loaded.diagnostics;
    if (o.settings.mode == "path")  // warnings that hold only there (§9.2)
        diagnostics.insert(diagnostics.end(), loaded.path_warnings.begin(), loaded.path_warnings.end());
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Severity::Error || ++warnings <= kMaxWarningsShown) std::cerr << d.str() << "\n";
    warnings += loaded.unlisted_warnings;  // the parser's own past those it listed, which are all shown
    if (warnings > kMaxWarningsShown)
        std::cerr << program << ": " << warnings - kMaxWarningsShown << " more warnings not shown\n";
    if (loaded.cancelled && limit) {
        const double seconds = std::string(limit) == "--time-limit" ? o.settings.time_limit : timeout_seconds(o.settings);
        std::cerr << program << ": error: the time limit of " << seconds << " s (" << limit
                  << ") ran out while loading the scene: nothing written\n";
        return kExitTimeout;
    }
    if (loaded.cancelled) {
        std::cerr << program << ": interrupted while loading the scene: nothing written\n";
        return kExitInterrupted;
    }
    if (!loaded.ok()) {
        if (!loaded.missing_textures.empty() && o.settings.missing_textures != "checker")
            std::cerr << program << ": use --texture-path DIR to add a place to look, or --missing-textures=checker "
                                    "to render without them\n";
        return loaded.unreadable ? kExitIo : kExitScene;
    }
    return kExitOk;
}

void print_stats(const LoadStats& ls, const RenderStats& rs, int samples_per_pixel, int passes) {
    std::fprintf(stderr,
                 "dialect %s\n"
                 "objects %zu, lights %zu, textures %zu; %d samples per pixel in %d passes\n"
                 "parse %.3fs, flatten %.3fs, textures %.3fs, meshes %.3fs, build %.3fs, render %.3fs (%d threads)\n",
                 dialect_name(ls.dialect), ls.objects, ls.lights, ls.textures, samples_per_pixel, passes, ls.parse_seconds,
                 ls.flatten_seconds, ls.texture_seconds, ls.mesh_seconds, ls.build_seconds, rs.seconds, rs.threads);
    print_rays(rs.rays, rs.seconds);
}

void print_rays(const RayCounts& rays, double seconds) {
    std::fprintf(stderr,
                 "rays: camera %llu, reflected %llu, refracted %llu, shadow %llu; %.2f Mrays/s\n"
                 "traversal Mrays/s per thread (1 in %llu timed): camera %.2f, reflected %.2f, refracted %.2f, shadow %.2f\n"
                 "samples rejected (not finite, counted as black): %llu\n",
                 (unsigned long long)rays.camera, (unsigned long long)rays.reflected,
                 (unsigned long long)rays.refracted, (unsigned long long)rays.shadow,
                 seconds > 0 ? double(rays.total()) / seconds * 1e-6 : 0.0, (unsigned long long)RayCounts::kTimeEvery,
                 rays.rays_per_second(RayKind::Camera) * 1e-6, rays.rays_per_second(RayKind::Reflected) * 1e-6,
                 rays.rays_per_second(RayKind::Refracted) * 1e-6, rays.rays_per_second(RayKind::Shadow) * 1e-6,
                 (unsigned long long)rays.rejected);
}

}  // namespace whitted::cli

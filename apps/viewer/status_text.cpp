#include "status_text.h"

#include <cstdio>

namespace whitted::viewer {

std::string load_summary(const RenderStatus& st) {
    if (!st.load_stats.objects && !st.load_stats.lights && st.state != RenderState::Rendering &&
        st.state != RenderState::Finished)
        return "";
    return ": " + std::to_string(st.load_stats.objects) + " objects, " + std::to_string(st.load_stats.lights) +
           (st.load_stats.lights == 1 ? " light" : " lights") + " (" + dialect_name(st.load_stats.dialect) + ")";
}

std::string progress_text(const RenderStatus& st) {
    char buf[200];
    const int pct = st.tiles_total ? int(100.0 * st.tiles_done / st.tiles_total) : 0;
    switch (st.state) {
        case RenderState::Idle: std::snprintf(buf, sizeof buf, "ready"); break;
        case RenderState::Loading: std::snprintf(buf, sizeof buf, "loading... %.1f s", st.elapsed_seconds); break;
        case RenderState::Rendering:
            if (st.passes_total > 1)
                std::snprintf(buf, sizeof buf, "rendering %d×%d: %d%%, %d of %d samples/pixel done, %.1f s",
                              st.settings.width, st.settings.height, pct, st.samples_done, st.samples_total,
                              st.elapsed_seconds);
            else
                std::snprintf(buf, sizeof buf, "rendering %d×%d: %d%% (%d/%d tiles), %.1f s", st.settings.width,
                              st.settings.height, pct, st.tiles_done, st.tiles_total, st.elapsed_seconds);
            break;
        case RenderState::Finished:
            if (st.samples_total > 1)
                std::snprintf(buf, sizeof buf, "done %d×%d, %d samples/pixel, in %.2f s", st.settings.width,
                              st.settings.height, st.samples_total, st.elapsed_seconds);
            else
                std::snprintf(buf, sizeof buf, "done %d×%d in %.2f s", st.settings.width, st.settings.height,
                              st.elapsed_seconds);
            break;
        case RenderState::Stopped:
            std::snprintf(buf, sizeof buf, "stopped at %d%% (%d/%d tiles, %d of %d samples/pixel complete), %.1f s",
                          pct, st.tiles_done, st.tiles_total, st.samples_done, st.samples_total, st.elapsed_seconds);
            break;
        case RenderState::Failed: std::snprintf(buf, sizeof buf, "the scene has errors"); break;
        case RenderState::MissingTextures: std::snprintf(buf, sizeof buf, "textures not found"); break;
    }
    return buf;
}

std::string render_hint(const RenderStatus& st) {
    const bool rendered = st.state == RenderState::Rendering || st.state == RenderState::Finished ||
                          st.state == RenderState::Stopped;
    if (!rendered) return "";
    return sampled_effects_hint(st.load_stats.effects, st.settings.sampling, st.settings.integrator.mode);
}

std::string pixel_readout(const Image& image, int x, int y, const std::optional<glm::vec3>& linear) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return "";
    const glm::u8vec3 p = image.at(x, y);
    char buf[160];
    int n = std::snprintf(buf, sizeof buf, "x %d  y %d   RGB %d %d %d", x, y, p.x, p.y, p.z);
    if (linear)
        std::snprintf(buf + n, sizeof buf - std::size_t(n), "   linear %.4g %.4g %.4g", double(linear->x),
                      double(linear->y), double(linear->z));
    return buf;
}

}  // namespace whitted::viewer

// The one place that maps a render mode to its integrator.
#include "integrator/caustic_integrator.h"
#include "integrator/cs1230_integrator.h"
#include "integrator/debug_views.h"
#include "integrator/integrator.h"
#include "integrator/path_integrator.h"
#include "integrator/whitted_integrator.h"

namespace whitted {

std::unique_ptr<Integrator> make_integrator(const Scene& scene, const Camera& camera,
                                            const IntegratorSettings& settings) {
    switch (settings.mode) {
        case RenderMode::Whitted:
            // A scene lit by the course's model (§9.5) is drawn by it; every other by §7's.
            if (scene.data.lighting == LightingModel::Cs1230)
                return std::make_unique<Cs1230Integrator>(scene, camera, settings.max_depth, settings.cs1230_stage);
            return std::make_unique<WhittedIntegrator>(scene, camera, settings.max_depth, settings.conventions,
                                                       settings.texture_filter, settings.texture_sample_rows);
        case RenderMode::Raycast: return std::make_unique<RaycastIntegrator>(scene, camera);
        case RenderMode::Normals: return std::make_unique<NormalsIntegrator>(scene, camera);
        case RenderMode::Depth: return std::make_unique<DepthIntegrator>(scene, camera);
        case RenderMode::Path:
            // Photons only where they carry light: every other scene gets the path tracer alone.
            if (settings.photons > 0 && scene_has_caustic_paths(scene.data)) {
                CausticSettings c;
                c.max_bounces = settings.max_depth;
                c.photons_per_sample = settings.photons;
                c.radius = settings.photon_radius;
                return std::make_unique<CausticIntegrator>(scene, camera, c);
            }
            return std::make_unique<PathIntegrator>(scene, camera, settings.max_depth);
    }
    return nullptr;
}

}  // namespace whitted

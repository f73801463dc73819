#pragma once
// The Whitted shadow factor S of scene-format.md §7 along a shadow ray: 0 once anything opaque is
// crossed, else the product of the `transparent` colours of every surface crossed (a closed glass
// object twice), 1 if nothing is in the way. Built on the scene's any-hit query with a filter.
#include <glm/glm.hpp>

#include "accel/scene.h"

namespace whitted {

inline glm::vec3 glass_transmittance(const Scene& scene, const Ray& ray, float t_max) {
    glm::vec3 through(1.0f);
    scene.visit_crossings(ray, t_max, [&](std::uint32_t instance, int crossings) {
        const Material& m = scene.material(instance);
        if (!m.is_transparent()) {
            through = glm::vec3(0.0f);
            return false;  // an opaque blocker: nothing else matters
        }
        through *= crossings == 2 ? m.transparent * m.transparent : m.transparent;
        return true;
    });
    return through;
}

}  // namespace whitted

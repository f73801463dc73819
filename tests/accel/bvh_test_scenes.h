#pragma once
// Random scenes and rays for the BVH tests (tests/accel/): every shape under random affine maps
// (rotation, shear, non-uniform and mirroring scale), and rays from anywhere, mostly aimed at
// an instance.
#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "accel/instance_geometry.h"
#include "flatten/flatten.h"

namespace whitted::test {

// Translation, rotation, shear and non-uniform scale with random signs (mirrored instances).
inline glm::mat4 random_affine(std::mt19937& rng, float spread) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    glm::mat4 m = glm::translate(glm::mat4(1.0f), spread * glm::vec3(u(rng), u(rng), u(rng)));
    m = glm::rotate(m, 3.14159f * u(rng), glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f));
    glm::mat4 shear(1.0f);
    shear[1][0] = 0.5f * u(rng);
    shear[2][1] = 0.5f * u(rng);
    m = m * shear;
    auto scale = [&] { float s = 0.2f + 1.8f * std::fabs(u(rng)); return u(rng) < -0.6f ? -s : s; };
    return glm::scale(m, glm::vec3(scale(), scale(), scale()));
}

// Every shape kind in turn (the ellipsoid included), so the BVH and packet tests cover them all.
struct RandomScene {
    std::vector<Instance> instances;
    std::vector<Material> materials;
};

inline RandomScene random_scene(std::uint32_t seed, int n, float spread) {
    std::mt19937 rng(seed);
    RandomScene s;
    Material opaque, glass, tinted;
    glass.transparent = glm::vec3(0.9f);
    tinted.transparent = glm::vec3(0.8f, 0.5f, 0.2f);
    s.materials = {opaque, glass, tinted};
    for (int i = 0; i < n; ++i)
        s.instances.push_back(make_instance(random_affine(rng, spread), ShapeKind(i % 5), std::uint32_t(rng() % 3)));
    return s;
}

// Rays from anywhere: half aimed at an instance (so that most hit something), some along axes.
inline std::vector<Ray> random_rays(std::uint32_t seed, int n, float spread, const std::vector<Instance>& instances) {
    std::mt19937 rng(seed * 7919u + 1);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
        Ray r;
        r.origin = 1.3f * spread * glm::vec3(u(rng), u(rng), u(rng));
        if (i % 2 == 0 && !instances.empty()) {
            const Instance& target = instances[rng() % instances.size()];
            glm::vec3 centre(object_to_world(target)[3]);
            r.direction = glm::normalize(centre + 0.5f * glm::vec3(u(rng), u(rng), u(rng)) - r.origin);
        } else {
            r.direction = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        }
        if (i % 16 == 1) r.direction = glm::vec3(0, 0, 0) + glm::vec3(0, 0, u(rng) < 0 ? -1 : 1);  // zero x, y
        if (i % 16 == 3) r.direction = glm::vec3(u(rng) < 0 ? -1 : 1, 0, 0);
        rays.push_back(r);
    }
    return rays;
}

}  // namespace whitted::test

#include "integrator/cube_light.h"

#include <algorithm>
#include <cmath>

#include "accel/instance_geometry.h"
#include "sampler/warp.h"  // kPi

namespace whitted {

CubeLight::CubeLight(const Instance& inst) {
    const glm::mat4 m = object_to_world(inst);
    for (int k = 0; k < 6; ++k) {
        const int axis = k / 2;
        const float side = k % 2 ? -0.5f : 0.5f;
        glm::vec3 c(0.0f), n(0.0f), a(0.0f), b(0.0f);
        c[axis] = side;
        n[axis] = side * 2.0f;
        a[(axis + 1) % 3] = 1.0f;
        b[(axis + 2) % 3] = 1.0f;
        centre_[k] = glm::vec3(m * glm::vec4(c, 1.0f));
        edge_a_[k] = glm::vec3(m * glm::vec4(a, 0.0f));
        edge_b_[k] = glm::vec3(m * glm::vec4(b, 0.0f));
        corner_[k] = centre_[k] - 0.5f * (edge_a_[k] + edge_b_[k]);
        normal_[k] = normal_to_world(inst, n);
        area_[k] = glm::length(glm::cross(edge_a_[k], edge_b_[k]));
    }
}

int CubeLight::face_of(const glm::vec3& n) {
    const glm::vec3 a = glm::abs(n);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return 2 * axis + (n[axis] < 0.0f ? 1 : 0);
}

void CubeLight::face_probabilities(const glm::vec3& x, float (&p)[6]) const {
    // In front of a face: x on its outer side. Each such face is weighed by half its share of an
    // estimate of the solid angle (area · cos / distance² from its centre, which underestimates
    // faces seen from close by at a grazing angle) and half its share of the area, so that no face
    // x can see gets less than half of what choosing by area would give it.
    float omega[6], area[6], omega_sum = 0.0f, area_sum = 0.0f;
    for (int k = 0; k < 6; ++k) {
        const glm::vec3 v = x - centre_[k];
        const float h = glm::dot(normal_[k], v);
        if (h > 0.0f) {
            const float d2 = glm::dot(v, v);
            omega[k] = std::min(2.0f * kPi, area_[k] * h / (d2 * std::sqrt(d2)));
            area[k] = area_[k];
        } else {
            omega[k] = area[k] = 0.0f;
        }
        omega_sum += omega[k];
        area_sum += area[k];
    }
    if (!(area_sum > 0.0f)) {  // inside (or on) the cube: every face's inner side, by area
        const float total = world_area();
        for (int k = 0; k < 6; ++k) p[k] = area_[k] / total;
        return;
    }
    for (int k = 0; k < 6; ++k)
        p[k] = 0.5f * (omega_sum > 0.0f ? omega[k] / omega_sum : area[k] / area_sum) + 0.5f * area[k] / area_sum;
}

CubeLight::Sample CubeLight::sample(const glm::vec3& x, glm::vec2 u) const {
    float p[6];
    face_probabilities(x, p);
    // u.x picks the face and is stretched back to [0, 1) within its share (stratification kept);
    // past the rounding of the sum, the last face that can be chosen.
    int k = 0;
    float below = 0.0f, start = 0.0f;
    for (int j = 0; j < 6; ++j) {
        if (!(p[j] > 0.0f)) continue;
        k = j;
        start = below;
        if (u.x < below + p[j]) break;
        below += p[j];
    }
    const float a = std::clamp((u.x - start) / p[k], 0.0f, 0x1.fffffep-1f);
    return {corner_[k] + a * edge_a_[k] + u.y * edge_b_[k], normal_[k], p[k] / area_[k]};
}

float CubeLight::pdf_area(const glm::vec3& x, int face) const {
    float p[6];
    face_probabilities(x, p);
    return p[face] / area_[face];
}

}  // namespace whitted

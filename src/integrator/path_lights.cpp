#include "integrator/path_lights.h"

#include <algorithm>
#include <cmath>

#include "accel/instance_geometry.h"
#include "sampler/warp.h"
#include "shapes/unit_shape_sampling.h"

namespace whitted {
namespace {

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// |det W| of the world→object rows: 1 / |det M|.
float det_world_to_object(const Instance& inst) {
    const glm::vec4* w = inst.world_to_object;
    return std::abs(glm::dot(glm::vec3(w[0]), glm::cross(glm::vec3(w[1]), glm::vec3(w[2]))));
}

// The world area of an object-space area element with normal n: |det M| · |M⁻ᵀ n| (M⁻ᵀ = Wᵀ).
float area_scale(const Instance& inst, const glm::vec3& n_object) {
    const glm::vec4* w = inst.world_to_object;
    const glm::vec3 t = n_object.x * glm::vec3(w[0]) + n_object.y * glm::vec3(w[1]) + n_object.z * glm::vec3(w[2]);
    return glm::length(t) / det_world_to_object(inst);
}

}  // namespace

float PathLights::world_area(const Instance& inst) {
    // Midpoint quadrature over the square of sample_unit_shape: the area element is constant on
    // flat parts and smooth on curved ones.
    constexpr int k = 48;
    double sum = 0;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            const ShapeSample s = sample_unit_shape(inst.kind, {(float(i) + 0.5f) / k, (float(j) + 0.5f) / k});
            sum += area_scale(inst, unit_shape_area_normal(inst.kind, unit_shape_normal(inst.kind, s.part, s.p)));
        }
    return float(sum / (k * k) * unit_shape_area(inst.kind));
}

PathLights::PathLights(const Scene& scene) : scene_(scene) {
    const SceneData& flat = scene.data;
    std::vector<float> power;
    mesh_sampler_of_.assign(flat.instances.size(), -1);
    cube_of_.assign(flat.instances.size(), -1);
    sphere_of_.assign(flat.instances.size(), -1);
    for (std::uint32_t i = 0; i < flat.instances.size(); ++i) {
        const glm::vec3& e = scene.material(i).emit;
        if (std::max(e.x, std::max(e.y, e.z)) <= 0.0f) continue;
        // A moving emitter (a shutter's motion blur) is not sampled where the load placed it: the
        // path tracer finds its light by the directions it samples, whole (no weighting).
        if (scene.motion.contains(i)) continue;
        const Instance& inst = flat.instances[i];
        if (inst.kind == ShapeKind::Mesh) {
            MeshAreaSampler sampler(flat.meshes[inst.mesh], object_to_world(inst));
            if (!(sampler.total_area() > 0.0f)) continue;
            mesh_sampler_of_[i] = std::int32_t(mesh_samplers_.size());
            lights_.push_back({std::int32_t(i), -1});
            power.push_back(std::max(1e-12f, luminance(e) * sampler.total_area() * kPi));
            mesh_samplers_.push_back(std::move(sampler));
            continue;
        }
        if (unit_shape_area(inst.kind) <= 0.0f) continue;  // no unit shape without a sampler
        if (inst.kind == ShapeKind::Cube) {
            cube_of_[i] = std::int32_t(cubes_.size());
            cubes_.emplace_back(inst);
        }
        if (inst.kind == ShapeKind::Sphere)
            if (const std::optional<SphereLight> sphere = SphereLight::of(inst)) {
                sphere_of_[i] = std::int32_t(spheres_.size());
                spheres_.push_back(*sphere);
            }
        lights_.push_back({std::int32_t(i), -1});
        power.push_back(std::max(1e-12f, luminance(e) * world_area(flat.instances[i]) * kPi));
    }
    const Bounds b = scene.bounds();
    const float radius = b.empty() ? 1.0f : 0.5f * glm::length(b.hi - b.lo);
    for (std::size_t l = 0; l < flat.lights.size(); ++l) {
        const Light& light = flat.lights[l];
        const float c = std::max(1e-12f, luminance(light.color));
        lights_.push_back({-1, std::int32_t(l)});
        power.push_back(light.type == LightType::Directional ? c * kPi * radius * radius : c * 4.0f * kPi);
    }
    double total = 0;
    for (float p : power) total += p;
    instance_choice_.assign(flat.instances.size(), 0.0f);
    double run = 0;
    for (std::size_t k = 0; k < lights_.size(); ++k) {
        const float prob = float(power[k] / total);
        run += power[k] / total;
        cdf_.push_back(float(run));
        if (lights_[k].instance >= 0) instance_choice_[std::size_t(lights_[k].instance)] = prob;
    }
    if (!cdf_.empty()) cdf_.back() = 1.0f;
}

const PathLight& PathLights::choose(float u, float& prob) const {
    const std::size_t k = std::min<std::size_t>(std::size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()),
                                                cdf_.size() - 1);
    prob = cdf_[k] - (k ? cdf_[k - 1] : 0.0f);
    return lights_[k];
}

float PathLights::choice_probability(std::uint32_t instance) const { return instance_choice_[instance]; }

AreaLightSample PathLights::sample_area(std::uint32_t instance, const glm::vec3& x, glm::vec2 u, float u_triangle) const {
    if (const std::int32_t m = mesh_sampler_of_[instance]; m >= 0) {
        const AreaSample s = mesh_samplers_[std::size_t(m)].sample({u_triangle, u.x, u.y});
        return {s.point, s.normal, s.pdf_area};
    }
    if (const std::int32_t c = cube_of_[instance]; c >= 0) {
        const CubeLight::Sample s = cubes_[std::size_t(c)].sample(x, u);
        return {s.point, s.normal, s.pdf_area};
    }
    if (const std::int32_t k = sphere_of_[instance]; k >= 0) {
        const SphereLight::Sample s = spheres_[std::size_t(k)].sample(x, u);
        return {s.point, s.normal, s.pdf_area};
    }
    const Instance& inst = scene_.data.instances[instance];
    const ShapeSample s = sample_unit_shape(inst.kind, u);
    const glm::vec3 n_object = unit_shape_normal(inst.kind, s.part, s.p);
    const glm::mat4 m = object_to_world(inst);
    const glm::vec3 p = glm::vec3(m * glm::vec4(s.p, 1.0f));
    return {p, normal_to_world(inst, n_object), pdf_area(instance, x, p, n_object)};
}

float PathLights::pdf_area(std::uint32_t instance, const glm::vec3& x, const glm::vec3& p, const glm::vec3& n_object) const {
    if (const std::int32_t m = mesh_sampler_of_[instance]; m >= 0)
        return 1.0f / mesh_samplers_[std::size_t(m)].total_area();
    if (const std::int32_t c = cube_of_[instance]; c >= 0)
        return cubes_[std::size_t(c)].pdf_area(x, p, CubeLight::face_of(n_object));
    const Instance& inst = scene_.data.instances[instance];
    if (const std::int32_t k = sphere_of_[instance]; k >= 0)
        return spheres_[std::size_t(k)].pdf_area(x, normal_to_world(inst, n_object));
    return 1.0f / (unit_shape_area(inst.kind) * area_scale(inst, unit_shape_area_normal(inst.kind, n_object)));
}

}  // namespace whitted

#include "integrator/photon_emitter.h"

#include <algorithm>
#include <cmath>

#include "accel/instance_geometry.h"
#include "accel/scene.h"
#include "integrator/path_lights.h"         // world_area
#include "integrator/whitted_integrator.h"  // surface_offset
#include "sampler/warp.h"
#include "shapes/unit_shape_sampling.h"

namespace whitted {
namespace {

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }
float max_component(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// The cone a spot's photons are drawn from: where its factor is not 0 (cos θ ≥ 0 unless exponent 0).
float spot_cone(const Light& light) {
    const float c = std::max(-1.0f, std::min(1.0f, light.cos_aperture));
    return light.exponent > 0.0f ? std::max(c, 0.0f) : c;
}

// The world area of an object-space area element with normal n: |det M| · |M⁻ᵀ n| (as the path
// tracer's lights convert it: the same density for the same point).
float area_scale(const Instance& inst, const glm::vec3& n_object) {
    const glm::vec4* w = inst.world_to_object;
    const float det = std::abs(glm::dot(glm::vec3(w[0]), glm::cross(glm::vec3(w[1]), glm::vec3(w[2]))));
    const glm::vec3 t = n_object.x * glm::vec3(w[0]) + n_object.y * glm::vec3(w[1]) + n_object.z * glm::vec3(w[2]);
    return glm::length(t) / det;
}

PhotonTarget sphere_of(const Bounds& b) { return {b.centre(), 0.5f * glm::length(b.extent())}; }

}  // namespace

bool has_delta_lobe(const Material& m) {
    return !(m.gloss > 0.0f) && max_component(m.reflect + m.transparent) > 0.0f;
}

float light_flux_scale(const Light& light, float radius) {
    switch (light.type) {
        case LightType::Point: return kPi * 4.0f * kPi;
        case LightType::Directional: return kPi * kPi * radius * radius;
        case LightType::Spot: {
            // ∫ cos^e θ dω over the cone: 2π (1 − c^(e+1)) / (e + 1) from c = cos of its edge.
            const float c = spot_cone(light), e = light.exponent;
            return kPi * 2.0f * kPi * (1.0f - (e > 0.0f ? std::pow(c, e + 1.0f) : c)) / (e + 1.0f);
        }
    }
    return 0.0f;
}

PhotonEmitter::PhotonEmitter(const Scene& scene, bool aim) : scene_(scene), aim_(aim) {
    const SceneData& data = scene.data;
    const Bounds bounds = scene.bounds();
    if (!bounds.empty()) {
        centre_ = bounds.centre();
        radius_ = std::max(1e-6f, 0.5f * glm::length(bounds.extent()));
    }
    // The objects a photon must meet first.
    Bounds all;
    for (std::uint32_t i = 0; i < data.instances.size(); ++i) {
        if (!has_delta_lobe(scene.material(i))) continue;
        const Instance& inst = data.instances[i];
        // A moving one (a shutter's motion blur) over the whole interval: photons have times of their own.
        const Bounds b = scene.motion.contains(i) ? scene.motion.swept[i - scene.motion.first]
                         : inst.kind == ShapeKind::Mesh ? mesh_world_bounds(data.meshes[inst.mesh], inst)
                                                        : world_bounds(inst);
        if (b.empty()) continue;
        all.grow(b);
        targets_.push_back(sphere_of(b));
    }
    if (targets_.size() > kMaxTargets) targets_.assign(1, sphere_of(all));

    std::vector<double> power;
    for (std::size_t l = 0; l < data.lights.size(); ++l) {
        const Light& light = data.lights[l];
        const float p = luminance(light.color) * light_flux_scale(light, radius_);
        if (!(p > 0.0f) || !std::isfinite(p)) continue;
        Source src;
        src.light = std::int32_t(l);
        if (aim_ && light.type != LightType::Directional) {
            const float limit = light.type == LightType::Point ? 4.0f * kPi : 2.0f * kPi * (1.0f - spot_cone(light));
            Cone cones[kMaxTargets];
            float total = 0.0f;
            const std::size_t n = cones_from(light.position, light.radius, limit, cones, total);
            if (n > 0) {
                src.aimed = true;
                src.cones_begin = std::uint32_t(cones_.size());
                cones_.insert(cones_.end(), cones, cones + n);
                src.cones_end = std::uint32_t(cones_.size());
                src.cone_solid_angle = total;
            }
        }
        sources_.push_back(src);
        power.push_back(p);
    }
    for (std::uint32_t i = 0; i < data.instances.size(); ++i) {
        const glm::vec3& e = scene.material(i).emit;
        if (!(max_component(e) > 0.0f)) continue;
        if (scene.motion.contains(i)) continue;  // the path tracer takes all of a moving emitter's light
        const Instance& inst = data.instances[i];
        Source src;
        src.instance = std::int32_t(i);
        float p = 0.0f;
        if (inst.kind == ShapeKind::Mesh) {
            MeshAreaSampler sampler(data.meshes[inst.mesh], object_to_world(inst));
            p = luminance(e) * sampler.total_area() * 2.0f * kPi;  // both sides
            if (!(p > 0.0f) || !std::isfinite(p)) continue;
            src.mesh = std::int32_t(meshes_.size());
            meshes_.push_back(std::move(sampler));
        } else {
            if (unit_shape_area(inst.kind) <= 0.0f) continue;
            p = luminance(e) * PathLights::world_area(inst) * kPi;
            if (!(p > 0.0f) || !std::isfinite(p)) continue;
        }
        sources_.push_back(src);
        power.push_back(p);
    }
    double total = 0;
    for (double p : power) total += p;
    power_.assign(power.begin(), power.end());
    double run = 0;
    for (double p : power) cdf_.push_back(float((run += p) / total));
    if (!cdf_.empty()) cdf_.back() = 1.0f;
}

std::size_t PhotonEmitter::cones_from(const glm::vec3& origin, float margin, float limit, Cone* out,
                                      float& total) const {
    std::size_t n = 0;
    total = 0.0f;
    for (const PhotonTarget& t : targets_) {
        const glm::vec3 to = t.centre - origin;
        const float d2 = glm::dot(to, to), r = t.radius + margin;
        if (!(d2 > r * r)) return 0;  // inside: every direction may meet it
        const float s2 = r * r / d2;
        // 1 − cos α as sin² α / (1 + cos α): no cancellation for a far, small target.
        const float one_minus_cos = s2 / (1.0f + std::sqrt(1.0f - s2));
        out[n++] = Cone{to / std::sqrt(d2), s2, 2.0f * kPi * one_minus_cos};
        total += out[n - 1].solid_angle;
    }
    return n > 0 && total < limit ? n : 0;
}

glm::vec3 PhotonEmitter::sample_cones(const Cone* cones, std::size_t count, float total, float pick, glm::vec2 u,
                                      float& pdf) {
    const float at = pick * total;
    float run = 0.0f;
    std::size_t j = 0;
    for (; j + 1 < count; ++j)
        if (at < (run += cones[j].solid_angle)) break;
    const Cone& c = cones[j];
    // Uniform in the cone: 1 − cos θ uniform on [0, 1 − cos α], the sine from it directly.
    const float v = u.x * c.solid_angle / (2.0f * kPi);
    const float sin_theta = std::sqrt(std::max(0.0f, v * (2.0f - v))), phi = 2.0f * kPi * u.y;
    glm::vec3 t, b;
    orthonormal_basis(c.axis, t, b);
    const glm::vec3 dir =
        glm::normalize(sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * b + (1.0f - v) * c.axis);
    // The mixture's density: the cones holding the direction over their total solid angle.
    int holding = 1;
    for (std::size_t i = 0; i < count; ++i) {
        if (i == j || glm::dot(dir, cones[i].axis) <= 0.0f) continue;
        const glm::vec3 x = glm::cross(dir, cones[i].axis);
        if (glm::dot(x, x) <= cones[i].sin2_max) ++holding;
    }
    pdf = float(holding) / total;
    return dir;
}

EmittedPhoton PhotonEmitter::emit(const EmissionNumbers& u) const {
    if (sources_.empty()) return {};
    const std::size_t k = std::min<std::size_t>(
        std::size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u.light) - cdf_.begin()), cdf_.size() - 1);
    const float prob = cdf_[k] - (k ? cdf_[k - 1] : 0.0f);
    return sources_[k].light >= 0 ? emit_light(sources_[k], prob, u) : emit_shape(sources_[k], prob, u);
}

EmittedPhoton PhotonEmitter::emit_light(const Source& src, float prob, const EmissionNumbers& u) const {
    EmittedPhoton out;
    const Light& light = scene_.data.lights[std::size_t(src.light)];
    glm::vec3 t, b;
    if (light.type == LightType::Directional) {
        // A disc of the bounding sphere facing the light, beyond the sphere on the light's side.
        const glm::vec3 dir = light.cos_half_angle < 1.0f ? uniform_cone(light.direction, light.cos_half_angle, u.dir)
                                                          : light.direction;
        orthonormal_basis(light.direction, t, b);
        const glm::vec2 d = radius_ * concentric_disc(u.point);
        const glm::vec3 on_disc = centre_ + d.x * t + d.y * b;
        // Rays of a tilted direction still start on the disc (§9.1's cone is a few degrees at most).
        out.ray = Ray{on_disc - 2.0f * radius_ * dir, dir};
        out.power = light.color * (light_flux_scale(light, radius_) / prob);
        return out;
    }
    glm::vec3 dir;
    float scale = 0.0f;  // the flux per unit of colour this photon carries
    if (src.aimed) {
        float pdf = 0.0f;
        dir = sample_cones(&cones_[src.cones_begin], src.cones_end - src.cones_begin, src.cone_solid_angle, u.cone,
                           u.dir, pdf);
        float profile = 1.0f;  // the spot's factor in that direction (§6)
        if (light.type == LightType::Spot) {
            const float cos_theta = glm::dot(dir, light.direction);
            if (cos_theta < spot_cone(light)) return out;  // outside the spot: no light that way
            if (light.exponent > 0.0f) profile = std::pow(std::max(0.0f, cos_theta), light.exponent);
        }
        scale = kPi * profile / (pdf * prob);  // intensity π · C · profile over the density
    } else {
        float factor = 1.0f;  // intensity profile / its mean over the sampled directions
        if (light.type == LightType::Spot) {
            const float c = spot_cone(light);
            dir = uniform_cone(light.direction, c, u.dir);
            const float e = light.exponent;
            const float cos_theta = std::max(0.0f, glm::dot(dir, light.direction));
            const float mean = e > 0.0f ? (1.0f - std::pow(c, e + 1.0f)) / ((e + 1.0f) * (1.0f - c)) : 1.0f;
            factor = (e > 0.0f ? std::pow(cos_theta, e) : 1.0f) / mean;
        } else {
            dir = uniform_cone(glm::vec3(0, 0, 1), -1.0f, u.dir);
        }
        scale = light_flux_scale(light, radius_) * factor / prob;
    }
    glm::vec3 origin = light.position;
    if (light.radius > 0.0f) {
        orthonormal_basis(dir, t, b);
        const glm::vec2 d = light.radius * concentric_disc(u.point);
        origin += d.x * t + d.y * b;
    }
    out.ray = Ray{origin, dir};
    out.power = light.color * scale;
    out.falloff = light.falloff;
    out.attenuated = true;
    return out;
}

EmittedPhoton PhotonEmitter::emit_shape(const Source& src, float prob, const EmissionNumbers& u) const {
    EmittedPhoton out;
    const std::uint32_t i = std::uint32_t(src.instance);
    const Instance& inst = scene_.data.instances[i];
    glm::vec3 p, n;
    float pdf_area;
    const bool two_sided = src.mesh >= 0;
    if (two_sided) {
        const AreaSample s = meshes_[std::size_t(src.mesh)].sample({u.triangle, u.point.x, u.point.y});
        p = s.point, n = s.normal, pdf_area = s.pdf_area;
    } else {
        const ShapeSample s = sample_unit_shape(inst.kind, u.point);
        const glm::vec3 n_object = unit_shape_normal(inst.kind, s.part, s.p);
        p = glm::vec3(object_to_world(inst) * glm::vec4(s.p, 1.0f));
        n = normal_to_world(inst, n_object);
        pdf_area = 1.0f / (unit_shape_area(inst.kind) * area_scale(inst, unit_shape_area_normal(inst.kind, n_object)));
    }
    if (!(pdf_area > 0.0f) || !std::isfinite(pdf_area)) return out;
    glm::vec3 dir;
    float scale;  // radiance · |cos| / the densities of the point, the direction and the source
    Cone cones[kMaxTargets];
    float total = 0.0f;
    const std::size_t count = aim_ ? cones_from(p, 0.0f, two_sided ? 4.0f * kPi : 2.0f * kPi, cones, total) : 0;
    if (count > 0) {
        float pdf = 0.0f;
        dir = sample_cones(cones, count, total, u.cone, u.dir, pdf);
        const float c = glm::dot(dir, n);
        if (!two_sided && !(c > 0.0f)) return out;  // behind a closed shape's surface
        scale = std::abs(c) / (pdf * pdf_area * prob);
    } else {
        const glm::vec3 side = two_sided && u.side < 0.5f ? -n : n;
        dir = cosine_hemisphere(side, u.dir);
        scale = kPi * (two_sided ? 2.0f : 1.0f) / (pdf_area * prob);
    }
    const float off = surface_offset(p);
    out.ray = Ray{p + (glm::dot(dir, n) > 0.0f ? off : -off) * n, dir};
    out.power = scene_.material(i).emit * scale;
    return out;
}

}  // namespace whitted

#include "integrator/cs1230_integrator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "accel/instance_geometry.h"
#include "cs1230/texture_lookup.h"

namespace whitted {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// How far secondary rays start along their direction (the TA renderer's 0.001, in world units).
constexpr float kRayOffset = 0.001f;

glm::vec3 clamp01(const glm::vec3& c) { return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f)); }

}  // namespace

Cs1230Integrator::Cs1230Integrator(const Scene& scene, const Camera& camera, int max_depth, cs1230::Stage stage)
    : Integrator(scene, camera), max_depth_(max_depth), stage_(stage) {}

glm::vec3 Cs1230Integrator::truncate_to_bytes(const glm::vec3& c) {
    const glm::vec3 v = clamp01(c);
    return glm::floor(255.0f * v) / 255.0f;
}

LightSample Cs1230Integrator::light_at(const Light& light, const glm::vec3& point) {
    LightSample ls;
    if (light.type == LightType::Directional) {
        ls.to_light = -light.direction;  // unit (flatten normalises it)
        ls.distance = kInfinity;
        ls.intensity = light.color;
        ls.position = point + ls.to_light;  // not a position: directional lights have none
        return ls;
    }
    const glm::vec3 towards = light.position - point;
    const float d = glm::length(towards);
    ls.to_light = towards / d;
    ls.distance = d;
    ls.position = light.position;
    const glm::vec3& c = light.falloff;
    const float att = std::min(1.0f, 1.0f / (c.x + d * c.y + d * d * c.z));
    float spot = 1.0f;
    if (light.type == LightType::Spot) {
        // The angle between the light's axis and the ray from the light to the point, in degrees.
        const float cosine = std::clamp(glm::dot(light.direction, -ls.to_light), -1.0f, 1.0f);
        const float angle = glm::degrees(std::acos(cosine));
        const float inner = light.spot_inner_deg, outer = light.spot_outer_deg;
        if (angle > outer) {
            spot = 0.0f;
        } else if (angle > inner && outer > inner) {
            const double r = double(angle - inner) / double(outer - inner);
            spot = float(1.0 - (-2.0 * r * r * r + 3.0 * r * r));
        }
    }
    ls.intensity = light.color * (att * spot);
    return ls;
}

void Cs1230Integrator::radiance(const CameraBatch& batch, const Sampler&, glm::vec3 (&out)[kPacketSize],
                                RayCounts& counts) const {
    Hit hits[kPacketSize];
    const unsigned found = timed_trace(counts, RayKind::Camera, std::popcount(batch.active),
                                       [&] { return scene_.intersect(batch.rays, batch.active, hits); }) &
                           batch.active;
    NoShadingRecorder none;
    for (int l = 0; l < kPacketSize; ++l) {
        if (!((batch.active >> l) & 1)) continue;
        ++counts.camera;
        const glm::vec3 c = (found >> l) & 1 ? shade(batch.rays[l], hits[l], 0, counts, none) : scene_.data.background;
        out[l] = truncate_to_bytes(c);
    }
}

glm::vec3 Cs1230Integrator::radiance(const Ray& ray, const SampleKey&, const Sampler&, RayCounts& counts,
                                     ShadingRecorder& recorder) const {
    ++counts.camera;
    return truncate_to_bytes(trace(RayKind::Camera, ray, 0, counts, recorder));
}

template <class Recorder>
glm::vec3 Cs1230Integrator::trace(RayKind kind, const Ray& ray, int depth, RayCounts& counts, Recorder& rec) const {
    Hit hit;
    if (!timed_trace(counts, kind, 1, [&] { return scene_.intersect(ray, hit); })) {
        rec.miss(scene_.data.background);
        return scene_.data.background;
    }
    return shade(ray, hit, depth, counts, rec);
}

Surface Cs1230Integrator::surface(const Ray& ray, const Hit& hit) const {
    const SceneData& data = scene_.data;
    const Instance& inst = data.instances[hit.instance];
    Surface s;
    s.point = ray.at(hit.t);
    const glm::vec3 p = to_object_space(inst, ray).at(hit.t);
    if (inst.kind == ShapeKind::Mesh) {
        const TriangleMesh& mesh = data.meshes[inst.mesh];
        s.object_normal = glm::normalize(triangle_geometric_normal(mesh, hit.triangle));
        s.normal = normal_to_world(inst, mesh_shading_normal(mesh, hit.triangle, hit.u, hit.v));
        s.uv = mesh_uv(mesh, hit.triangle, hit.u, hit.v);  // the file's vt: v up, as the course's
    } else {
        s.object_normal = unit_shape_normal(inst.kind, hit.part, p);
        s.normal = normal_to_world(inst, s.object_normal);
        s.uv = cs1230::shape_uv(inst.kind, hit.part, p);
    }
    s.material = &data.materials[inst.material];
    s.ambient = s.material->ambient;
    s.diffuse = s.material->diffuse;
    if (s.material->texture >= 0 && stage_ == cs1230::Stage::Illuminate) {
        const Material& m = *s.material;
        const glm::vec3 texel = cs1230::nearest_texel(data.textures[std::size_t(m.texture)], s.uv, m.repeat_u, m.repeat_v);
        const float b = std::max(m.blend, 0.0f);
        s.diffuse = (1.0f - b) * s.diffuse + texel * b;  // the texel is not multiplied by kd
    }
    return s;
}

bool Cs1230Integrator::intersect_instance(std::uint32_t instance, const Ray& ray, Hit& hit) const {
    const Instance& inst = scene_.data.instances[instance];
    const Ray o = to_object_space(inst, ray);
    if (inst.kind == ShapeKind::Mesh) {
        MeshHit h;
        if (!mesh_intersect_nearest(scene_.mesh_bvhs[inst.mesh], o, 0.0f, kInfinity, h)) return false;
        hit = Hit{h.t, instance, kPartSide, h.triangle, h.u, h.v};
        return true;
    }
    float t;
    ShapePart part;
    if (!nearest_hit(intersect_unit_shape(inst.kind, o), 0.0f, kInfinity, t, part)) return false;
    hit = Hit{t, instance, part};
    return true;
}

template <class Recorder>
glm::vec3 Cs1230Integrator::shade(const Ray& ray, const Hit& hit, int depth, RayCounts& counts, Recorder& rec) const {
    const SceneData& data = scene_.data;
    const Surface s = surface(ray, hit);
    const Material& m = *s.material;
    const glm::vec3 dir = glm::normalize(ray.direction);
    const glm::vec3 to_eye = -dir;
    const bool outside = glm::dot(s.normal, to_eye) >= 0.0f;
    // Lit with the outward normal as the course does; a mesh's triangles are two-sided.
    const bool mesh = data.instances[hit.instance].kind == ShapeKind::Mesh;
    const glm::vec3 n = mesh && !outside ? -s.normal : s.normal;
    rec.hit(ray, hit, s, n, outside, depth);

    glm::vec3 color = m.emit + s.ambient;  // ambient once: the course's lights have none
    rec.base(m.emit, s.ambient);
    const bool illuminate = stage_ == cs1230::Stage::Illuminate;
    glm::vec3 diffuse(0.0f), specular(0.0f);
    for (std::size_t li = 0; li < data.lights.size(); ++li) {
        const Light& light = data.lights[li];
        if (!illuminate && light.type != LightType::Directional) {
            if constexpr (Recorder::kRecords) rec.light(LightTerm{li, light_at(light, s.point), false, 0.0f, {}, {}, {}});
            continue;  // the Intersect stage knows only directional lights
        }
        const LightSample ls = light_at(light, s.point);
        const glm::vec3& l = ls.to_light;
        if (illuminate) {
            ++counts.shadow;
            const Ray shadow{s.point + kRayOffset * l, l};
            const float reach = std::isinf(ls.distance) ? kInfinity : glm::length(ls.position - shadow.origin);
            if (timed_trace(counts, RayKind::Shadow, 1, [&] { return scene_.occluded(shadow, reach); })) {
                if constexpr (Recorder::kRecords)
                    rec.light(LightTerm{li, ls, true, glm::dot(n, l), glm::vec3(0.0f), {}, {}});
                continue;
            }
        }
        const glm::vec3 mirrored = glm::reflect(-l, n);
        const float cos_ln = std::max(0.0f, glm::dot(n, l));
        const float cos_rv = std::max(0.0f, glm::dot(mirrored, to_eye));
        const glm::vec3 d = ls.intensity * s.diffuse * cos_ln;
        const glm::vec3 sp = ls.intensity * m.specular * std::pow(cos_rv, m.shine);
        diffuse += d;
        specular += sp;
        if constexpr (Recorder::kRecords) rec.light(LightTerm{li, ls, true, glm::dot(n, l), glm::vec3(1.0f), d, sp});
    }
    color += diffuse + specular;

    if (depth >= max_depth_) {
        rec.depth_limit();
    } else if (illuminate) {
        if (m.is_transparent()) color += refraction(s, dir, hit.instance, depth, counts, rec);
        if (m.reflect != glm::vec3(0.0f) && glm::dot(to_eye, n) >= 0.0f) {
            const glm::vec3 r = glm::reflect(dir, n);
            const Ray reflected{s.point + kRayOffset * r, r};
            ++counts.reflected;
            rec.secondary(SecondaryKind::Reflect, SecondaryRecord::Outcome::Traced, reflected, m.reflect);
            const glm::vec3 c = trace(RayKind::Reflected, reflected, depth + 1, counts, rec);
            color += m.reflect * c;
            rec.secondary_color(c, m.reflect * c);
        }
    }
    color = clamp01(color);
    rec.done(color);
    return color;
}

// Through the shape, as the course's renderer refracts: into it with η = 1/ior about the outward
// normal, to where the refracted ray leaves this same shape (nothing else inside counts), out
// with η = ior; the ray outside is traced on, weighted by kt·Ot. Where it cannot leave (total
// internal reflection) nothing comes through. A ray already inside only leaves.
template <class Recorder>
glm::vec3 Cs1230Integrator::refraction(const Surface& s, const glm::vec3& dir, std::uint32_t instance, int depth,
                                       RayCounts& counts, Recorder& rec) const {
    const Material& m = *s.material;
    glm::vec3 leave_from = s.point, leave_dir(0.0f);
    if (glm::dot(dir, s.normal) < 0.0f) {
        const glm::vec3 in = glm::refract(dir, s.normal, 1.0f / m.ior);
        if (in == glm::vec3(0.0f)) return glm::vec3(0.0f);
        const Ray inner{s.point + kRayOffset * in, in};
        Hit exit;
        if (!intersect_instance(instance, inner, exit)) return glm::vec3(0.0f);
        const Surface e = surface(inner, exit);
        leave_from = e.point;
        leave_dir = glm::refract(in, -e.normal, m.ior);
    } else {
        leave_dir = glm::refract(dir, -s.normal, m.ior);
    }
    if (leave_dir == glm::vec3(0.0f)) return glm::vec3(0.0f);
    const Ray out{leave_from + kRayOffset * leave_dir, leave_dir};
    ++counts.refracted;
    rec.secondary(SecondaryKind::Refract, SecondaryRecord::Outcome::Traced, out, m.transparent);
    const glm::vec3 c = trace(RayKind::Refracted, out, depth + 1, counts, rec);
    rec.secondary_color(c, m.transparent * c);
    return m.transparent * c;
}

}  // namespace whitted

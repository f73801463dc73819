#include "integrator/surface.h"

#include "accel/instance_geometry.h"
#include "texture/texture_sample.h"

namespace whitted {

namespace {

// Inlined into both callers: a call here costs every static hit (0.5% of a one-sample render).
[[gnu::always_inline]] inline Surface surface_of(const Scene& scene, const Instance& inst, const Ray& ray,
                                                 const Hit& hit) {
    const Ray object_ray = to_object_space(inst, ray);
    const glm::vec3 p = object_ray.at(hit.t);
    Surface s;
    s.point = ray.at(hit.t);
    s.material = &scene.data.materials[inst.material];
    // The texture coordinates only where a texture reads them (an atan2 and an asin on a sphere):
    // the others keep (0, 0), and the pixel inspector asks surface_uv for its report.
    const bool textured = s.material->texture >= 0;
    s.uv = glm::vec2(0.0f);
    if (inst.kind == ShapeKind::Mesh) {
        const TriangleMesh& mesh = scene.data.meshes[inst.mesh];
        s.object_normal = glm::normalize(triangle_geometric_normal(mesh, hit.triangle));
        s.normal = normal_to_world(inst, mesh_shading_normal(mesh, hit.triangle, hit.u, hit.v));
        if (textured) s.uv = mesh_uv(mesh, hit.triangle, hit.u, hit.v);
    } else {
        s.object_normal = unit_shape_normal(inst.kind, hit.part, p);
        s.normal = normal_to_world(inst, s.object_normal);
        if (textured) s.uv = unit_shape_uv(inst.kind, hit.part, p);
    }
    s.diffuse = s.material->diffuse;
    s.ambient = s.material->ambient;
    if (s.material->texture >= 0)
        mix_texel(s, sample_texture(scene.data.textures[s.material->texture], s.uv, s.material->repeat_u,
                                    s.material->repeat_v));
    return s;
}

// A moving instance where the ray met it (out of line: renders without a shutter never come here).
[[gnu::noinline]] Surface moving_surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
    return surface_of(scene, scene.instance_at(hit.instance, ray.time), ray, hit);
}

}  // namespace

Surface surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
    if (scene.motion.contains(hit.instance)) return moving_surface_at(scene, ray, hit);
    return surface_of(scene, scene.data.instances[hit.instance], ray, hit);  // read in place
}

glm::vec2 surface_uv(const Scene& scene, const Ray& ray, const Hit& hit) {
    const Instance inst = scene.instance_at(hit.instance, ray.time);
    if (inst.kind == ShapeKind::Mesh) return mesh_uv(scene.data.meshes[inst.mesh], hit.triangle, hit.u, hit.v);
    return unit_shape_uv(inst.kind, hit.part, to_object_space(inst, ray).at(hit.t));
}

void mix_texel(Surface& s, const glm::vec3& texel) {
    if (s.material->blend >= 0) {  // Brown/Tufts `blend` (spec §9.4): a mix, the ambient left as is
        s.diffuse = (1.0f - s.material->blend) * s.diffuse + s.material->blend * texel;
    } else {  // the texel multiplies diffuse and ambient (spec §8)
        s.diffuse *= texel;
        s.ambient *= texel;
    }
}

}  // namespace whitted

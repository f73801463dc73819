#include "integrator/surface.h"

#include "accel/instance_geometry.h"
#include "texture/texture_sample.h"

namespace whitted {

Surface surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
    const Instance& inst = scene.flat.instances[hit.instance];
    const Ray object_ray = to_object_space(inst, ray);
    const glm::vec3 p = object_ray.at(hit.t);
    Surface s;
    s.point = ray.at(hit.t);
    if (inst.kind == ShapeKind::Mesh) {
        const TriangleMesh& mesh = scene.flat.meshes[inst.mesh];
        s.normal = normal_to_world(inst, mesh_shading_normal(mesh, hit.triangle, hit.u, hit.v));
        s.uv = mesh_uv(mesh, hit.triangle, hit.u, hit.v);
    } else {
        s.normal = normal_to_world(inst, unit_shape_normal(inst.kind, hit.part, p));
        s.uv = unit_shape_uv(inst.kind, hit.part, p);
    }
    s.material = &scene.flat.materials[inst.material];
    s.diffuse = s.material->diffuse;
    s.ambient = s.material->ambient;
    if (s.material->texture >= 0) {
        // The texel multiplies diffuse and ambient (spec §8).
        glm::vec3 texel = sample_texture(scene.flat.textures[s.material->texture], s.uv, s.material->repeat_u,
                                         s.material->repeat_v);
        s.diffuse *= texel;
        s.ambient *= texel;
    }
    return s;
}

}  // namespace whitted

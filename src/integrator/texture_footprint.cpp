#include "integrator/texture_footprint.h"

#include <cmath>

#include "accel/instance_geometry.h"
#include "texture/texture_sample.h"

namespace whitted {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Where ray r meets the plane through `point` with normal `ng`.
bool meet_plane(const Ray& r, const glm::vec3& point, const glm::vec3& ng, glm::vec3& at) {
    const float along = glm::dot(ng, r.direction);
    if (!(std::abs(along) > 1e-12f)) return false;
    at = r.at(glm::dot(ng, point - r.origin) / along);
    return finite(at);
}

// The texture coordinates and world shading normal the hit's surface, continued, has at world
// point q of its tangent plane: the shape's own formulas at q (a triangle's barycentrics extended
// past its edges).
void continued_surface(const Scene& scene, const Instance& inst, const Hit& hit, const glm::vec3& q, glm::vec2& uv,
                       glm::vec3& n) {
    const glm::vec3 po = to_object_space(inst, Ray{q, glm::vec3(0.0f)}).origin;
    if (inst.kind == ShapeKind::Mesh) {
        const TriangleMesh& mesh = scene.data.meshes[inst.mesh];
        const TriangleIndices& c = mesh.triangles[hit.triangle];
        const glm::vec3 a = mesh.positions[c[0]], e1 = mesh.positions[c[1]] - a, e2 = mesh.positions[c[2]] - a;
        const glm::vec3 w = po - a;
        const float d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
        const float d20 = glm::dot(w, e1), d21 = glm::dot(w, e2);
        const float inv = 1.0f / (d00 * d11 - d01 * d01);
        const float u = (d11 * d20 - d01 * d21) * inv, v = (d00 * d21 - d01 * d20) * inv;
        uv = mesh_uv(mesh, hit.triangle, u, v);
        n = normal_to_world(inst, mesh_shading_normal(mesh, hit.triangle, u, v));
    } else {
        uv = unit_shape_uv(inst.kind, hit.part, po);
        n = normal_to_world(inst, unit_shape_normal(inst.kind, hit.part, po));
    }
}

// Whether u goes around the shape (and wraps from 1 to 0 at a seam).
bool u_goes_around(const Instance& inst, const Hit& hit) {
    return inst.kind != ShapeKind::Mesh && hit.part == kPartSide;
}

glm::vec3 mirrored(const glm::vec3& d, const glm::vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

// Snell's law as the Whitted integrator's (unit d, n facing d's origin side, eta = n_from / n_to).
bool refract(const glm::vec3& d, const glm::vec3& n, float eta, glm::vec3& out) {
    const float cos_i = -glm::dot(n, d);
    const float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
    if (k < 0.0f) return false;
    out = glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * n);
    return true;
}

}  // namespace

bool surface_differentials(const Scene& scene, const Hit& hit, const Surface& s, const RayDifferential& rd,
                           SurfaceDifferentials& out, float time) {
    const Instance inst = scene.instance_at(hit.instance, time);  // where a moving one is at that time
    // The tangent plane of the true surface (a triangle's own plane, not its shading normal's).
    const glm::vec3 ng = normal_to_world(inst, s.object_normal);
    glm::vec3 px, py;
    if (!meet_plane(rd.x, s.point, ng, px) || !meet_plane(rd.y, s.point, ng, py)) return false;
    out.dpdx = px - s.point;
    out.dpdy = py - s.point;
    glm::vec2 uvx, uvy;
    glm::vec3 nx, ny;
    continued_surface(scene, inst, hit, px, uvx, nx);
    continued_surface(scene, inst, hit, py, uvy, ny);
    out.uv.dx = uvx - s.uv;
    out.uv.dy = uvy - s.uv;
    if (u_goes_around(inst, hit)) {  // the short way round the seam
        out.uv.dx.x -= std::round(out.uv.dx.x);
        out.uv.dy.x -= std::round(out.uv.dy.x);
    }
    out.dndx = nx - s.normal;
    out.dndy = ny - s.normal;
    return finite(out.dndx) && finite(out.dndy) && std::isfinite(out.uv.dx.x + out.uv.dx.y + out.uv.dy.x + out.uv.dy.y);
}

void refilter_texture(const Scene& scene, Surface& s, TextureFilter filter, const TextureFootprint* footprint) {
    const Material& m = *s.material;
    if (m.texture < 0) return;
    const TextureImage& image = scene.data.textures[std::size_t(m.texture)];
    glm::vec3 texel;
    if (filter == TextureFilter::Nearest) {
        texel = sample_texture_nearest(image, s.uv, m.repeat_u, m.repeat_v);
    } else if (!footprint || !uses_footprint(filter)) {
        texel = sample_texture(image, s.uv, m.repeat_u, m.repeat_v);
    } else {
        static const std::vector<TextureImage> kNoLevels;  // mip-maps not built: the image alone
        const auto& all = scene.data.texture_levels;
        const auto& levels = std::size_t(m.texture) < all.size() ? all[std::size_t(m.texture)] : kNoLevels;
        texel = sample_texture_filtered(image, levels, filter, s.uv, m.repeat_u, m.repeat_v, *footprint);
    }
    s.diffuse = m.diffuse;
    s.ambient = m.ambient;
    mix_texel(s, texel);
}

RayDifferential reflected_differential(const glm::vec3& p, const glm::vec3& n, float side, const RayDifferential& in,
                                       const SurfaceDifferentials& d) {
    const glm::vec3 nx = glm::normalize(n + side * d.dndx), ny = glm::normalize(n + side * d.dndy);
    return RayDifferential{Ray{p + d.dpdx, mirrored(glm::normalize(in.x.direction), nx)},
                           Ray{p + d.dpdy, mirrored(glm::normalize(in.y.direction), ny)}};
}

bool refracted_differential(const glm::vec3& p, const glm::vec3& n, float side, float eta, const RayDifferential& in,
                            const SurfaceDifferentials& d, RayDifferential& out) {
    const glm::vec3 nx = glm::normalize(n + side * d.dndx), ny = glm::normalize(n + side * d.dndy);
    out.x.origin = p + d.dpdx;
    out.y.origin = p + d.dpdy;
    return refract(glm::normalize(in.x.direction), nx, eta, out.x.direction) &&
           refract(glm::normalize(in.y.direction), ny, eta, out.y.direction);
}

}  // namespace whitted

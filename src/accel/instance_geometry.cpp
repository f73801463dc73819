#include "accel/instance_geometry.h"

namespace whitted {

glm::mat4 object_to_world(const Instance& inst) {
    // world_to_object = [A | t] (affine), so object_to_world = [A⁻¹ | −A⁻¹·t]; A⁻¹ by cofactors
    // in double (the build calls this once per instance: a general 4×4 inverse is much slower).
    const glm::vec4* w = inst.world_to_object;
    const double a00 = w[0].x, a01 = w[0].y, a02 = w[0].z;
    const double a10 = w[1].x, a11 = w[1].y, a12 = w[1].z;
    const double a20 = w[2].x, a21 = w[2].y, a22 = w[2].z;
    const double c00 = a11 * a22 - a12 * a21, c01 = a12 * a20 - a10 * a22, c02 = a10 * a21 - a11 * a20;
    const double inv_det = 1.0 / (a00 * c00 + a01 * c01 + a02 * c02);
    // inv[r][c] (row r, column c) = cofactor(c, r) / det.
    const double inv[3][3] = {
        {c00 * inv_det, (a02 * a21 - a01 * a22) * inv_det, (a01 * a12 - a02 * a11) * inv_det},
        {c01 * inv_det, (a00 * a22 - a02 * a20) * inv_det, (a02 * a10 - a00 * a12) * inv_det},
        {c02 * inv_det, (a01 * a20 - a00 * a21) * inv_det, (a00 * a11 - a01 * a10) * inv_det},
    };
    const double t[3] = {w[0].w, w[1].w, w[2].w};
    glm::mat4 m(1.0f);  // column-major: m[col][row]
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[c][r] = float(inv[r][c]);
        m[3][r] = float(-(inv[r][0] * t[0] + inv[r][1] * t[1] + inv[r][2] * t[2]));
    }
    return m;
}

Bounds world_bounds(const Instance& inst) { return unit_shape_world_bounds(inst.kind, object_to_world(inst)); }

Bounds mesh_world_bounds(const TriangleMesh& mesh, const Instance& inst) {
    Bounds b;
    if (mesh.box.empty()) return b;
    const glm::mat4 m = object_to_world(inst);
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner((k & 1) ? mesh.box.hi.x : mesh.box.lo.x, (k & 2) ? mesh.box.hi.y : mesh.box.lo.y,
                               (k & 4) ? mesh.box.hi.z : mesh.box.lo.z);
        b.grow(glm::vec3(m * glm::vec4(corner, 1.0f)));
    }
    return b;
}

}  // namespace whitted

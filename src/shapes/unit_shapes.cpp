#include "shapes/unit_shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shapes/unit_shape_math.h"

namespace whitted {

ShapeSpan intersect_unit_shape(ShapeKind kind, const Ray& object_ray) {
    const auto s = shape_math::intersect_rescaled<float>(kind, object_ray.origin, object_ray.direction);
    ShapeSpan out;
    out.count = s.count;
    out.t[0] = s.t[0]; out.t[1] = s.t[1];
    out.part[0] = s.part[0]; out.part[1] = s.part[1];
    return out;
}

glm::vec3 unit_shape_normal(ShapeKind kind, ShapePart part, const glm::vec3& p) {
    return shape_math::normal<float>(kind, part, p);
}

namespace {

// Callers index texels with u·W: keep u, v in [0, 1) even for points a hair off the shape.
float clamp01(float x) {
    static const float kMax = std::nextafter(1.0f, 0.0f);
    return std::clamp(x, 0.0f, kMax);  // NaN cannot arise: every input is finite
}

// u = 0.5 − φ/(2π), φ = atan2(z, x): the sphere and the sides share it.
float around_u(const glm::vec3& p) {
    return 0.5f - std::atan2(p.z, p.x) * (0.5f * std::numbers::inv_pi_v<float>);
}

}  // namespace

glm::vec2 unit_shape_uv(ShapeKind kind, ShapePart part, const glm::vec3& p) {
    float u = 0, v = 0;
    switch (part) {
        case kPartSide:
            u = around_u(p);
            if (kind == ShapeKind::Sphere || kind == ShapeKind::Ellipsoid) {
                // The ellipsoid as the sphere it maps onto (x/2, y, z/2): the same formula in y.
                const float s = std::clamp(2.0f * p.y, -1.0f, 1.0f);
                v = 0.5f - std::asin(s) * std::numbers::inv_pi_v<float>;
            } else {
                v = 0.5f - p.y;
            }
            break;
        case kPartTopCap: case kPartPosY: u = p.x + 0.5f; v = p.z + 0.5f; break;
        case kPartBottomCap: case kPartNegY: u = p.x + 0.5f; v = 0.5f - p.z; break;
        case kPartPosZ: u = p.x + 0.5f; v = 0.5f - p.y; break;
        case kPartNegZ: u = 0.5f - p.x; v = 0.5f - p.y; break;
        case kPartPosX: u = 0.5f - p.z; v = 0.5f - p.y; break;
        case kPartNegX: u = p.z + 0.5f; v = 0.5f - p.y; break;
    }
    return {clamp01(u), clamp01(v)};
}

Bounds unit_shape_world_bounds(ShapeKind kind, const glm::mat4& m) {
    // glm is column-major: m[col][row]. Row i of the linear part is (m[0][i], m[1][i], m[2][i]).
    if (kind == ShapeKind::Ellipsoid)  // the sphere of radius 0.5 stretched by (2, 1, 2)
        return unit_shape_world_bounds(ShapeKind::Sphere, m * glm::mat4(glm::vec4(2, 0, 0, 0), glm::vec4(0, 1, 0, 0),
                                                                        glm::vec4(0, 0, 2, 0), glm::vec4(0, 0, 0, 1)));
    const glm::vec3 centre(m[3]);
    Bounds b;
    if (kind == ShapeKind::Sphere || kind == ShapeKind::Cylinder) {
        glm::vec3 half;
        for (int i = 0; i < 3; ++i) {
            const float x = m[0][i], y = m[1][i], z = m[2][i];
            half[i] = kind == ShapeKind::Sphere
                          // support of a ball: r·||row i||
                          ? 0.5f * std::sqrt(x * x + y * y + z * z)
                          // segment along the y column plus a disc spanned by the x, z columns
                          : 0.5f * std::abs(y) + 0.5f * std::sqrt(x * x + z * z);
        }
        b.grow(centre - half);
        b.grow(centre + half);
        return b;
    }
    if (kind == ShapeKind::Cone) {
        // The convex hull of the base disc (centre M·(0,-0.5,0), spanned by the x and z columns)
        // and the apex M·(0,0.5,0): the disc's box grown by the apex point is exact.
        const glm::vec3 base(m * glm::vec4(0.0f, -0.5f, 0.0f, 1.0f));
        glm::vec3 half;
        for (int i = 0; i < 3; ++i) half[i] = 0.5f * std::sqrt(m[0][i] * m[0][i] + m[2][i] * m[2][i]);
        b.grow(base - half);
        b.grow(base + half);
        b.grow(glm::vec3(m * glm::vec4(0.0f, 0.5f, 0.0f, 1.0f)));
        return b;
    }
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 corner((c & 1) ? 0.5f : -0.5f, (c & 2) ? 0.5f : -0.5f,
                               (c & 4) ? 0.5f : -0.5f, 1.0f);
        b.grow(glm::vec3(m * corner));
    }
    return b;
}

}  // namespace whitted

#include "integrator/cube_light.h"

#include <algorithm>
#include <cmath>

#include "accel/instance_geometry.h"
#include "base/atan2.h"

namespace whitted {

namespace {

// The solid angle of the parallelogram (a, b, c, d) seen from the origin, as the triangles
// (a, b, c) and (a, c, d), whose triple products have the same absolute value `triple`. Each
// triangle's half-angle θ has tan θ = triple / x (Van Oosterom and Strackee 1983), θ in (0, π);
// the parallelogram's is less than 2π, so θ1 + θ2 < π is one atan2 by the tangent's addition rule
// (base/atan2.h's: glibc's took 6% of the Cornell box's instructions).
// (Float points are less than 1e39 apart and more than 1e-45: x1·x2, of the sixth power of their
// distances, neither overflows nor underflows a double.)
double parallelogram_solid_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                 const glm::dvec3& d, double triple) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c), ld = glm::length(d);
    const double ac = glm::dot(a, c);
    const double x1 = la * lb * lc + glm::dot(a, b) * lc + ac * lb + glm::dot(b, c) * la;
    const double x2 = la * lc * ld + ac * ld + glm::dot(a, d) * lc + glm::dot(c, d) * la;
    return 2.0 * fast_atan2(triple * (x1 + x2), x1 * x2 - triple * triple);
}

}  // namespace

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
        // Perpendicular up to the rounding of the matrix (a rotation's entries are rounded to float).
        const float la = glm::length(edge_a_[k]), lb = glm::length(edge_b_[k]);
        rectangle_[k] = std::abs(glm::dot(edge_a_[k], edge_b_[k])) <= 1e-5f * la * lb && area_[k] > 0.0f;
        if (rectangle_[k]) frame_[k] = SphericalRectangle::Frame(edge_a_[k], edge_b_[k]);
        const glm::dvec3 diagonal = glm::dvec3(edge_a_[k]) + glm::dvec3(edge_b_[k]);
        reach2_[k] = kReach * kReach * glm::dot(diagonal, diagonal) / 4.0;
        corner_d_[k] = corner_[k];
        edge_a_d_[k] = edge_a_[k];
        edge_b_d_[k] = edge_b_[k];
        centre_d_[k] = centre_[k];
        normal_d_[k] = normal_[k];
    }
}

int CubeLight::face_of(const glm::vec3& n) {
    const glm::vec3 a = glm::abs(n);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return 2 * axis + (n[axis] < 0.0f ? 1 : 0);
}

void CubeLight::face_probabilities(const glm::vec3& x, double (&p)[6]) const {
    // In front of a face: x on its outer side. Its share: the face's solid angle as a point at its
    // centre would subtend it, area · cos / d² (the exact one, found for the face chosen alone,
    // cost two to three times as much for the two or three faces x sees: any shares give the
    // same expectation, as long as sample() and pdf_area() use the same).
    double share_sum = 0.0, area_sum = 0.0;
    bool seen[6];
    const glm::dvec3 xd(x);
    for (int k = 0; k < 6; ++k) {
        p[k] = 0.0;
        const glm::dvec3 to = xd - centre_d_[k];
        const double h = glm::dot(normal_d_[k], to);
        seen[k] = h > 0.0;
        if (!seen[k]) continue;
        const double d2 = glm::dot(to, to);
        p[k] = double(area_[k]) * h / (d2 * std::sqrt(d2));
        share_sum += p[k];
        area_sum += area_[k];
    }
    if (!(area_sum > 0.0)) {  // inside (or on) the cube: every face's inner side, by area
        const double total = world_area();
        for (int k = 0; k < 6; ++k) p[k] = area_[k] / total;
        return;
    }
    // Shares too small (or large) for a double (faces 1e100 off): the faces seen by area.
    const bool finite = share_sum > 0.0 && share_sum < 1e300;
    for (int k = 0; k < 6; ++k) p[k] = finite ? p[k] / share_sum : seen[k] ? area_[k] / area_sum : 0.0;
}

double CubeLight::solid_angle(const glm::vec3& x, int k) const {
    const glm::dvec3 xd(x);
    const double h = glm::dot(normal_d_[k], xd - centre_d_[k]);
    if (!(h > 0.0)) return 0.0;
    // The parallelogram as two triangles, whose triple products are both
    // (corner − x) · (edge_a × edge_b) = distance · area, free of the cancellation of the triple
    // product of three long vectors seen from far off.
    const glm::dvec3 a = corner_d_[k] - xd, &ea = edge_a_d_[k], &eb = edge_b_d_[k];
    const glm::dvec3 b = a + ea, c = b + eb, d = a + eb;
    return parallelogram_solid_angle(a, b, c, d, h * double(area_[k]));
}

double CubeLight::sampled_solid_angle(const glm::vec3& x, int k) const {
    if (!rectangle_[k]) return 0.0;
    const glm::dvec3 to = glm::dvec3(x) - centre_d_[k];
    return glm::dot(to, to) < reach2_[k] ? solid_angle(x, k) : 0.0;
}

float CubeLight::density(const glm::vec3& x, const glm::vec3& p, int k, double prob, double omega) const {
    if (!(prob > 0.0)) return 0.0f;
    if (!by_solid_angle(k, omega)) return float(prob / area_[k]);
    // 1 / omega per unit solid angle (the two triangles' solid angle is the spherical rectangle's
    // to double's rounding, and cheaper); a unit of area at p is cos_light / d² of it.
    const glm::dvec3 to = glm::dvec3(p) - glm::dvec3(x);
    const double d2 = glm::dot(to, to);
    const double cos_light = std::abs(glm::dot(normal_d_[k], to)) / std::sqrt(d2);
    return float(prob / omega * cos_light / d2);
}

CubeLight::Sample CubeLight::sample(const glm::vec3& x, glm::vec2 u) const {
    double p[6];
    face_probabilities(x, p);
    // u.x picks the face and is stretched back to [0, 1) within its share (stratification kept);
    // past the rounding of the sum, the last face that can be chosen.
    int k = 0;
    double below = 0.0, start = 0.0;
    for (int j = 0; j < 6; ++j) {
        if (!(p[j] > 0.0)) continue;
        k = j;
        start = below;
        if (double(u.x) < below + p[j]) break;
        below += p[j];
    }
    glm::vec2 st(std::clamp(float((double(u.x) - start) / p[k]), 0.0f, 0x1.fffffep-1f), u.y);
    const double omega = sampled_solid_angle(x, k);
    if (by_solid_angle(k, omega))
        st = SphericalRectangle(x, corner_[k], frame_[k], omega).sample(st);
    const glm::vec3 point = corner_[k] + st.x * edge_a_[k] + st.y * edge_b_[k];
    return {point, normal_[k], density(x, point, k, p[k], omega)};
}

float CubeLight::pdf_area(const glm::vec3& x, const glm::vec3& point, int face) const {
    double p[6];
    face_probabilities(x, p);
    if (!(p[face] > 0.0)) return 0.0f;
    return density(x, point, face, p[face], sampled_solid_angle(x, face));
}

}  // namespace whitted

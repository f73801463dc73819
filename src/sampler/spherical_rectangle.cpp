#include "sampler/spherical_rectangle.h"

#include <algorithm>
#include <cmath>

namespace whitted {

namespace {
constexpr double kTwoPi = 6.283185307179586476925;
}

SphericalRectangle::SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const glm::vec3& ex,
                                       const glm::vec3& ey) {
    set_up(x, corner, ex, ey, true);
}

SphericalRectangle::SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const glm::vec3& ex,
                                       const glm::vec3& ey, double solid_angle) {
    set_up(x, corner, ex, ey, false);
    solid_angle_ = solid_angle;
}

void SphericalRectangle::set_up(const glm::vec3& x, const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey,
                                bool solid_angle) {
    const glm::dvec3 a(ex), b(ey);
    const double la = glm::length(a), lb = glm::length(b);
    const glm::dvec3 fx = a / la, fy = b / lb, fz = glm::cross(fx, fy);
    const glm::dvec3 d = glm::dvec3(corner) - glm::dvec3(x);
    x0_ = glm::dot(d, fx);
    y0_ = glm::dot(d, fy);
    z0_ = -std::abs(glm::dot(d, fz));  // the frame's z turned to point away from the rectangle
    x1_ = x0_ + la;
    y1_ = y0_ + lb;
    // The unit normals of the four planes through x and an edge (v00 × v10, v10 × v11, v11 × v01,
    // v01 × v00 for the corners vij = (xi, yj, z0), each in closed form), and the spherical
    // rectangle's inner angles between them; its area is their sum less 2π (Girard).
    const double z2 = z0_ * z0_;
    const glm::dvec3 n0 = glm::dvec3(0, z0_, -y0_) / std::sqrt(z2 + y0_ * y0_);
    const glm::dvec3 n1 = glm::dvec3(-z0_, 0, x1_) / std::sqrt(z2 + x1_ * x1_);
    const glm::dvec3 n2 = glm::dvec3(0, -z0_, y1_) / std::sqrt(z2 + y1_ * y1_);
    const glm::dvec3 n3 = glm::dvec3(z0_, 0, -x0_) / std::sqrt(z2 + x0_ * x0_);
    const auto angle = [](const glm::dvec3& p, const glm::dvec3& q) {
        return std::acos(std::clamp(-glm::dot(p, q), -1.0, 1.0));
    };
    b0_ = n0.z;
    b1_ = n2.z;
    k_ = kTwoPi - angle(n2, n3) - angle(n3, n0);
    if (solid_angle) solid_angle_ = angle(n0, n1) + angle(n1, n2) - k_;
}

glm::vec2 SphericalRectangle::sample(glm::vec2 u) const {
    // The first coordinate cuts off the part of the solid angle left of x = xu: the angle au of the
    // plane through x and the line x = xu, from which its cosine cu and xu itself.
    const double au = double(u.x) * solid_angle_ + k_;
    const double fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
    const double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + b0_ * b0_), -1.0, 1.0);
    const double xu = std::clamp(-(cu * z0_) / std::sqrt(std::max(0.0, 1.0 - cu * cu)), x0_, x1_);
    // The second, uniform in the height h = sin(elevation) along that line, which is uniform in
    // its solid angle.
    const double dd = std::sqrt(xu * xu + z0_ * z0_);
    const double h0 = y0_ / std::sqrt(dd * dd + y0_ * y0_), h1 = y1_ / std::sqrt(dd * dd + y1_ * y1_);
    const double hv = h0 + double(u.y) * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1.0 - 1e-12 ? std::clamp(hv * dd / std::sqrt(1.0 - hv2), y0_, y1_) : y1_;
    return {float((xu - x0_) / (x1_ - x0_)), float((yv - y0_) / (y1_ - y0_))};
}

}  // namespace whitted

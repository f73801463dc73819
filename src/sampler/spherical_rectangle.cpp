#include "sampler/spherical_rectangle.h"

#include <algorithm>
#include <cmath>

#include "base/atan2.h"

namespace whitted {

namespace {
constexpr double kTwoPi = 6.283185307179586476925;
}

SphericalRectangle::Frame::Frame(const glm::vec3& ex, const glm::vec3& ey) {
    const glm::dvec3 a(ex), b(ey);
    la = glm::length(a);
    lb = glm::length(b);
    fx = a / la;
    fy = b / lb;
    fz = glm::cross(fx, fy);
}

SphericalRectangle::SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const glm::vec3& ex,
                                       const glm::vec3& ey) {
    set_up(x, corner, Frame(ex, ey), true);
}

SphericalRectangle::SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const glm::vec3& ex,
                                       const glm::vec3& ey, double solid_angle) {
    set_up(x, corner, Frame(ex, ey), false);
    solid_angle_ = solid_angle;
}

SphericalRectangle::SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const Frame& frame,
                                       double solid_angle) {
    set_up(x, corner, frame, false);
    solid_angle_ = solid_angle;
}

void SphericalRectangle::set_up(const glm::vec3& x, const glm::vec3& corner, const Frame& f, bool solid_angle) {
    const glm::dvec3 d = glm::dvec3(corner) - glm::dvec3(x);
    x0_ = glm::dot(d, f.fx);
    y0_ = glm::dot(d, f.fy);
    z0_ = -std::abs(glm::dot(d, f.fz));  // the frame's z turned to point away from the rectangle
    x1_ = x0_ + f.la;
    y1_ = y0_ + f.lb;
    // The planes through x and an edge have the normals v00 × v10, v10 × v11, v11 × v01 and
    // v01 × v00 for the corners vij = (xi, yj, z0); the spherical rectangle's inner angle between
    // two of them is atan2(|m × n|, −m · n), each in closed form (no normalising), and its area is
    // their sum less 2π (Girard). b0 and b1 are the z of the first and the third, normalised.
    const double z2 = z0_ * z0_, az = -z0_;
    b0_ = -y0_ / std::sqrt(z2 + y0_ * y0_);
    b1_ = y1_ / std::sqrt(z2 + y1_ * y1_);
    one_minus_b0_squared_ = z2 / (z2 + y0_ * y0_);  // 1 − b0², without its cancellation
    inv_width_ = 1.0 / f.la;
    inv_height_ = 1.0 / f.lb;
    const auto angle = [&](double xi, double yj, double minus_dot) {  // at the corner (xi, yj)
        return fast_atan2(az * std::sqrt(xi * xi + yj * yj + z2), minus_dot);
    };
    k_ = kTwoPi - angle(x0_, y1_, x0_ * y1_) - angle(x0_, y0_, -x0_ * y0_);
    if (solid_angle) solid_angle_ = angle(x1_, y0_, x1_ * y0_) + angle(x1_, y1_, -x1_ * y1_) - k_;
}

glm::vec2 SphericalRectangle::sample(glm::vec2 u) const {
    // The first coordinate cuts off the part of the solid angle left of x = xu: the angle au of the
    // plane through x and the line x = xu. The paper finds its cosine cu from
    // fu = (cos au · b0 − b1) / sin au as cu = sign(fu) / √(fu² + b0²), then xu = −cu·z0 / √(1 − cu²);
    // with n = cos au · b0 − b1 and s = sin au that is xu = −sign(n)·s·z0 / √(n² − (1 − b0²)·s²), the
    // same number with one root and one division in the chain instead of two roots and three
    // divisions (each waits for the one before: they were most of this function's time).
    const double au = double(u.x) * solid_angle_ + k_;
    const double s = std::sin(au), n = std::cos(au) * b0_ - b1_;
    const double den2 = n * n - one_minus_b0_squared_ * s * s;
    const double num = -(std::copysign(1.0, n) * s) * z0_;  // z0 < 0: xu has the sign of fu = n / s
    // As the plane's cosine tends to ±1, xu tends to ±∞ (beyond the rectangle's edge).
    const double xu = std::clamp(den2 > 0.0 ? num / std::sqrt(den2) : num >= 0.0 ? x1_ : x0_, x0_, x1_);
    // The second, uniform in the height h = sin(elevation) along that line, which is uniform in
    // its solid angle (the three roots at once).
    const double r2 = xu * xu + z0_ * z0_, dd = std::sqrt(r2);
    const double h0 = y0_ / std::sqrt(r2 + y0_ * y0_), h1 = y1_ / std::sqrt(r2 + y1_ * y1_);
    const double hv = h0 + double(u.y) * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1.0 - 1e-12 ? std::clamp(hv * dd / std::sqrt(1.0 - hv2), y0_, y1_) : y1_;
    return {float((xu - x0_) * inv_width_), float((yv - y0_) * inv_height_)};
}

}  // namespace whitted

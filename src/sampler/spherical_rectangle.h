#pragma once
// Uniform sampling of the solid angle a rectangle subtends from a point (Ureña, Fajardo and King
// 2013, "An Area-Preserving Parametrization for Spherical Rectangles"). The square [0, 1)² maps
// onto the rectangle so that equal areas of the square become equal solid angles seen from the
// point: a light sampled this way from a point close to it is not crowded with samples far off at
// grazing angles, as sampling by area is. The map is continuous, so stratification is kept.
// Computed in double: the solid angle is the sum of four angles minus 2π, which loses the digits
// of a small one to cancellation.
#include <glm/glm.hpp>

namespace whitted {

class SphericalRectangle {
public:
    // The rectangle's own frame, which does not depend on x: a light seen from many points makes it
    // once (its two lengths, two divisions and a cross product fewer per point).
    struct Frame {
        Frame() = default;
        Frame(const glm::vec3& ex, const glm::vec3& ey);
        glm::dvec3 fx{0.0}, fy{0.0}, fz{0.0};  // unit: along ex, along ey, their cross product
        double la = 0.0, lb = 0.0;             // |ex|, |ey|
    };

    // The rectangle corner + [0, 1]·ex + [0, 1]·ey (ex ⟂ ey, neither zero) seen from x, which is
    // not in its plane.
    SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey);
    // The same with its solid angle from x known (computed otherwise, equal to rounding): two
    // angles fewer.
    SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey,
                       double solid_angle);
    // The same with the frame made from ex and ey.
    SphericalRectangle(const glm::vec3& x, const glm::vec3& corner, const Frame& frame, double solid_angle);

    // The solid angle the rectangle subtends from x (steradians, in (0, 2π)).
    double solid_angle() const { return solid_angle_; }
    // The rectangle's coordinates (s, t) in [0, 1]² (point = corner + s·ex + t·ey) of the point
    // seen in the direction u maps to; density 1 / solid_angle() per unit solid angle from x.
    glm::vec2 sample(glm::vec2 u) const;

private:
    // The frame, b0_, b1_ and k_; the inner angles at the edges x = x0 and y = y0 (for the solid
    // angle) when asked.
    void set_up(const glm::vec3& x, const glm::vec3& corner, const Frame& f, bool solid_angle);
    // The rectangle in a frame at x: x along ex, y along ey, z away from the rectangle, which lies
    // at z = z0 < 0 over [x0, x1] × [y0, y1].
    double x0_, x1_, y0_, y1_, z0_;
    double b0_, b1_, k_;  // the z of the normals of the planes through x and the edges y = y0, y = y1
    double one_minus_b0_squared_, inv_width_, inv_height_;
    double solid_angle_;
};

}  // namespace whitted

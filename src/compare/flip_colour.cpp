#include "compare/flip_colour.h"

#include <cmath>

namespace whitted::flip {
namespace {

// The sRGB → XYZ matrix FLIP's reference implementation uses (rows: X, Y, Z), as its fractions:
// within 2e-4 of the one derived from the sRGB primaries and D65 (IEC 61966-2-1 to four decimals
// but for Z of blue, 0.9504 for 0.9505). Its own, so that FLIP's numbers are the paper's.
// glm matrices are column-major: M[column][row].
const glm::dmat3& rgb_to_xyz() {
    static const glm::dmat3 m(10135552.0 / 24577794.0, 2613072.0 / 12288897.0, 1425312.0 / 73733382.0,
                              8788810.0 / 24577794.0, 8788810.0 / 12288897.0, 8788810.0 / 73733382.0,
                              4435075.0 / 24577794.0, 887015.0 / 12288897.0, 70074185.0 / 73733382.0);
    return m;
}

const glm::dmat3& xyz_to_rgb() {
    static const glm::dmat3 m = glm::inverse(rgb_to_xyz());
    return m;
}

constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95;

}  // namespace

double srgb_to_linear(double c) { return c > 0.04045 ? std::pow((c + 0.055) / 1.055, 2.4) : c / 12.92; }

glm::dvec3 linear_rgb_to_xyz(const glm::dvec3& rgb) { return rgb_to_xyz() * rgb; }
glm::dvec3 xyz_to_linear_rgb(const glm::dvec3& xyz) { return xyz_to_rgb() * xyz; }

glm::dvec3 white_xyz() { return linear_rgb_to_xyz(glm::dvec3(1.0)); }

glm::dvec3 xyz_to_ycxcz(const glm::dvec3& xyz) {
    const glm::dvec3 n = xyz / white_xyz();
    return {116.0 * n.y - 16.0, 500.0 * (n.x - n.y), 200.0 * (n.y - n.z)};
}

glm::dvec3 ycxcz_to_xyz(const glm::dvec3& v) {
    const double y = (v.x + 16.0) / 116.0;
    return glm::dvec3(y + v.y / 500.0, y, y - v.z / 200.0) * white_xyz();
}

glm::dvec3 xyz_to_lab(const glm::dvec3& xyz) {
    constexpr double d = 6.0 / 29.0;
    auto f = [&](double t) { return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0; };
    const glm::dvec3 n = xyz / white_xyz();
    const double fx = f(n.x), fy = f(n.y), fz = f(n.z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::dvec3 hunt_adjust(const glm::dvec3& lab) { return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z}; }

double hyab(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = a - b;
    return std::abs(d.x) + std::sqrt(d.y * d.y + d.z * d.z);
}

glm::dvec3 linear_rgb_to_hunt_lab(const glm::dvec3& rgb) { return hunt_adjust(xyz_to_lab(linear_rgb_to_xyz(rgb))); }

double flip_cmax() {
    static const double cmax =
        std::pow(hyab(linear_rgb_to_hunt_lab({0.0, 1.0, 0.0}), linear_rgb_to_hunt_lab({0.0, 0.0, 1.0})), kQc);
    return cmax;
}

double flip_colour_error(double hyab_distance) {
    const double e = std::pow(hyab_distance, kQc), cmax = flip_cmax(), knee = kPc * cmax;
    return e < knee ? kPt / knee * e : kPt + (e - knee) / (cmax - knee) * (1.0 - kPt);
}

}  // namespace whitted::flip

#pragma once
// FLIP's colour spaces (Andersson et al. 2020, §3 and §4.1): sRGB, linear RGB, CIE XYZ, the
// opponent space YCxCz in which the contrast sensitivity filters work, and CIELAB with the Hunt
// adjustment, where the HyAB distance is taken. All with the D65 white of sRGB.
#include <glm/glm.hpp>

namespace whitted::flip {

// The sRGB transfer function, decoding: an encoded value in [0, 1] → linear.
double srgb_to_linear(double c);

// Linear sRGB ↔ XYZ with FLIP's matrix for the sRGB primaries and D65 white.
glm::dvec3 linear_rgb_to_xyz(const glm::dvec3& rgb);
glm::dvec3 xyz_to_linear_rgb(const glm::dvec3& xyz);

// XYZ of the white (linear RGB (1, 1, 1)): the reference white of YCxCz and CIELAB here.
glm::dvec3 white_xyz();

// YCxCz (Zhang and Wandell 1997): Y = 116·Y/Yn − 16, Cx = 500·(X/Xn − Y/Yn), Cz = 200·(Y/Yn − Z/Zn).
glm::dvec3 xyz_to_ycxcz(const glm::dvec3& xyz);
glm::dvec3 ycxcz_to_xyz(const glm::dvec3& ycxcz);

// CIELAB (L*, a*, b*).
glm::dvec3 xyz_to_lab(const glm::dvec3& xyz);

// The Hunt adjustment: a* and b* scaled by 0.01·L* (colours look less colourful when darker).
glm::dvec3 hunt_adjust(const glm::dvec3& lab);

// HyAB: |ΔL| + ‖(Δa, Δb)‖ (Abasi et al. 2020), FLIP's colour distance.
double hyab(const glm::dvec3& a, const glm::dvec3& b);

// Linear RGB → Hunt-adjusted CIELAB, the space the colour pipeline compares in.
glm::dvec3 linear_rgb_to_hunt_lab(const glm::dvec3& rgb);

// The largest colour difference FLIP expects, HyAB(green, blue) in Hunt-adjusted CIELAB, raised to
// the colour exponent qc = 0.7: the scale its errors are mapped to [0, 1] against.
double flip_cmax();

// FLIP's map of a colour difference ΔE (HyAB) to [0, 1]: ΔE^0.7, then linear up to pc·cmax
// (pc = 0.4) where it reaches pt = 0.95, and linear from there to 1 at cmax.
double flip_colour_error(double hyab_distance);

}  // namespace whitted::flip

#pragma once
// An emissive cube seen from a shading point (path tracing, scene-format.md §9.2). Emission is
// two-sided, but the cube is convex and closed: from outside, a face's points can be seen only if
// the point is in front of that face's plane (at most three faces); the others are hidden behind
// them. So only those faces are sampled, each chosen in proportion to the solid angle it would
// subtend as a point at its centre (area · cos / d²), and on it uniform in the solid angle it
// subtends (sampler/spherical_rectangle.h; the exact angle: Van Oosterom and Strackee 1983) when
// it is a rectangle in the world (a matrix that shears the
// cube makes parallelograms of its faces), x is near it (kReach) and its solid angle is neither
// tiny nor close to a hemisphere (kMinSolidAngle, kMaxSolidAngle); else uniform by world area on it. From inside, all
// six by world area. The density depends on the shading point and, per unit area, on the point
// of the face: next-event estimation and a BSDF ray that hits the cube ask for it with both, so
// multiple importance sampling weighs with the density the point was drawn with.
#include <glm/glm.hpp>

#include "data/scene_data.h"
#include "sampler/spherical_rectangle.h"

namespace whitted {

class CubeLight {
public:
    explicit CubeLight(const Instance& inst);

    struct Sample {
        glm::vec3 point;   // world space, on the face
        glm::vec3 normal;  // the face's unit outward normal
        float pdf_area;    // per unit of world area, given x
    };
    // A point of the cube for the shading point x, from u in [0, 1)² (u.x also picks the face).
    Sample sample(const glm::vec3& x, glm::vec2 u) const;
    // The density sample() draws the point p of face `face` with, per unit world area, from x.
    float pdf_area(const glm::vec3& x, const glm::vec3& p, int face) const;
    // The face (0..5: +x, −x, +y, −y, +z, −z) whose object-space outward normal is n.
    static int face_of(const glm::vec3& n_object);
    float world_area() const { return area_[0] + area_[1] + area_[2] + area_[3] + area_[4] + area_[5]; }

    // Below this solid angle (pbrt-v4's bound) a face is sampled by area: a face that small as
    // seen from x is far off or seen edge-on, its ratio of the two densities (cos_light /
    // distance²) varies little over it or its light is slight, so the construction's trigonometry
    // buys little; and its solid angle, four near-right angles less 2π, keeps fewer digits.
    static constexpr double kMinSolidAngle = 3e-4;
    // Above this one (2π less 0.06: x nearly in the face's plane, inside its outline) too: the
    // construction degenerates as x's distance to the plane goes to 0 (the planes through x and
    // the edges all tend to the face's, and it divides by that distance), and its directions
    // graze the face, where a small error in a direction is a large one in the point.
    static constexpr double kMaxSolidAngle = 6.22;
    // Farther from a face's centre than this many half-diagonals (one diagonal: its bounding
    // sphere seen within 30° of its centre), a face is sampled by area too, as Cycles samples a
    // triangle by area beyond its longest edge from its plane: there the solid angle and the
    // spherical rectangle cost more than the variance they save (the Cornell box: time -30%,
    // variance +2%; bench/RESULTS.md). Closer, cos_light / d² varies over the face without bound.
    static constexpr double kReach = 2.0;

private:
    // The probability of choosing each face from x (0 for faces that cannot be seen from there).
    void face_probabilities(const glm::vec3& x, double (&p)[6]) const;
    // The solid angle of face k from x (0 if x is not in front of it).
    double solid_angle(const glm::vec3& x, int k) const;
    // Whether face k, of solid angle omega from x, is sampled in solid angle (else by area).
    bool by_solid_angle(int k, double omega) const {
        return rectangle_[k] && omega >= kMinSolidAngle && omega <= kMaxSolidAngle;
    }
    float density(const glm::vec3& x, const glm::vec3& p, int k, double prob, double omega) const;
    // Face k's solid angle from x where it is sampled in it (a rectangle x is near), else 0.
    double sampled_solid_angle(const glm::vec3& x, int k) const;

    glm::vec3 corner_[6], edge_a_[6], edge_b_[6];  // face k = corner + [0,1]·edge_a + [0,1]·edge_b
    glm::vec3 centre_[6], normal_[6];
    float area_[6];
    double reach2_[6];  // the square of kReach half-diagonals
    bool rectangle_[6];  // edge_a ⟂ edge_b in the world (a face the matrix does not shear)
    SphericalRectangle::Frame frame_[6];  // of the rectangles
    // The same in double, converted once (the solid angles are found in double).
    glm::dvec3 corner_d_[6], edge_a_d_[6], edge_b_d_[6], centre_d_[6], normal_d_[6];
};

}  // namespace whitted

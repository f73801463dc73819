#pragma once
// An emissive cube seen from a shading point (path tracing, scene-format.md §9.2). Emission is
// two-sided, but the cube is convex and closed: from outside, a face's points can be seen only if
// the point is in front of that face's plane (at most three faces); the others are hidden behind
// them. So only those faces are sampled, each chosen with a probability that estimates its share
// of the solid angle, and uniform by world area on it; from inside, all six by world area. The
// density depends on the shading point: next-event estimation and a BSDF ray that hits the cube
// ask for it at the same point, so multiple importance sampling stays consistent.
#include <glm/glm.hpp>

#include "data/scene_data.h"

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
    // The density sample() draws the point of face `face` with, per unit world area, from x.
    float pdf_area(const glm::vec3& x, int face) const;
    // The face (0..5: +x, −x, +y, −y, +z, −z) whose object-space outward normal is n.
    static int face_of(const glm::vec3& n_object);
    float world_area() const { return area_[0] + area_[1] + area_[2] + area_[3] + area_[4] + area_[5]; }

private:
    // The probability of choosing each face from x (0 for faces that cannot be seen from there).
    void face_probabilities(const glm::vec3& x, float (&p)[6]) const;

    glm::vec3 corner_[6], edge_a_[6], edge_b_[6];  // face k = corner + [0,1]·edge_a + [0,1]·edge_b
    glm::vec3 centre_[6], normal_[6];
    float area_[6];
};

}  // namespace whitted

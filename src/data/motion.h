#pragma once
// A transform that changes with scene time: the `velocity` and `angularrate` keywords of a trans
// block (scene-format.md §9.4) kept as data instead of evaluated at one instant, so that each ray
// of a motion-blurred render can place a moving object where it is at the ray's own time.
#include <vector>

#include <glm/glm.hpp>

namespace whitted {

// One factor of the product, in the order written (the last one applies to the object first).
struct MotionStep {
    enum class Kind : unsigned char { Matrix, Velocity, Spin };
    Kind kind = Kind::Matrix;
    glm::dmat4 matrix{1.0};   // Matrix: the static factor
    glm::dmat4 inverse{1.0};  // Matrix: its inverse, kept so that the world→object map needs no inversion per ray
    glm::dvec3 vector{0.0};   // Velocity: the velocity; Spin: the unit axis
    double rate = 0;          // Spin: degrees per unit of time
};

// M(t) = S1 · S2 · … · Sn: static matrices, translations by t·v and rotations by rate·t degrees.
class Motion {
public:
    // Appends a factor on the right (applied to the object before those already there). Adjacent
    // static factors are merged into one.
    void then_matrix(const glm::dmat4& m);
    void then_velocity(const glm::dvec3& v);
    void then_spin(const glm::dvec3& axis, double degrees_per_time);  // a non-zero axis
    void then(const Motion& inner);  // every factor of `inner`, on the right

    bool moves() const;  // any factor that depends on t
    bool empty() const { return steps_.empty(); }
    const std::vector<MotionStep>& steps() const { return steps_; }

    glm::dmat4 object_to_world(double t) const;
    glm::dmat4 world_to_object(double t) const;  // the inverse, factor by factor

    // A bound on how fast any point within `radius` of the object-space origin moves in world
    // space while t stays within [-t_abs, t_abs]: a Lipschitz constant of t ↦ M(t)·p, so that boxes
    // taken at sampled times, grown by speed × half the spacing, bound the whole sweep.
    double speed_bound(double radius, double t_abs) const;

private:
    std::vector<MotionStep> steps_;
};

}  // namespace whitted

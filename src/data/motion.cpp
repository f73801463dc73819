#include "data/motion.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace whitted {
namespace {

// An upper bound on the largest singular value of the linear part (its Frobenius norm).
double stretch(const glm::dmat4& m) {
    double s = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) s += m[c][r] * m[c][r];
    return std::sqrt(s);
}

glm::dmat4 spin_matrix(const MotionStep& s, double t) {
    return glm::rotate(glm::dmat4(1.0), glm::radians(s.rate * t), s.vector);
}

}  // namespace

void Motion::then_matrix(const glm::dmat4& m) {
    if (!steps_.empty() && steps_.back().kind == MotionStep::Kind::Matrix) {
        steps_.back().matrix = steps_.back().matrix * m;
        steps_.back().inverse = glm::inverse(steps_.back().matrix);
        return;
    }
    MotionStep s;
    s.matrix = m;
    s.inverse = glm::inverse(m);
    steps_.push_back(s);
}

void Motion::then_velocity(const glm::dvec3& v) {
    MotionStep s;
    s.kind = MotionStep::Kind::Velocity;
    s.vector = v;
    steps_.push_back(s);
}

void Motion::then_spin(const glm::dvec3& axis, double degrees_per_time) {
    MotionStep s;
    s.kind = MotionStep::Kind::Spin;
    s.vector = glm::normalize(axis);
    s.rate = degrees_per_time;
    steps_.push_back(s);
}

void Motion::then(const Motion& inner) {
    for (const MotionStep& s : inner.steps_) {
        if (s.kind == MotionStep::Kind::Matrix) then_matrix(s.matrix);
        else steps_.push_back(s);
    }
}

bool Motion::moves() const {
    return std::any_of(steps_.begin(), steps_.end(), [](const MotionStep& s) {
        return s.kind == MotionStep::Kind::Velocity ? s.vector != glm::dvec3(0.0)
               : s.kind == MotionStep::Kind::Spin   ? s.rate != 0
                                                    : false;
    });
}

glm::dmat4 Motion::object_to_world(double t) const {
    glm::dmat4 m(1.0);
    for (const MotionStep& s : steps_) {
        switch (s.kind) {
            case MotionStep::Kind::Matrix: m = m * s.matrix; break;
            case MotionStep::Kind::Velocity: m = glm::translate(m, t * s.vector); break;
            case MotionStep::Kind::Spin: m = m * spin_matrix(s, t); break;
        }
    }
    return m;
}

glm::dmat4 Motion::world_to_object(double t) const {
    glm::dmat4 m(1.0);
    for (auto it = steps_.rbegin(); it != steps_.rend(); ++it) {
        const MotionStep& s = *it;
        switch (s.kind) {
            case MotionStep::Kind::Matrix: m = m * s.inverse; break;
            case MotionStep::Kind::Velocity: m = glm::translate(m, -t * s.vector); break;
            case MotionStep::Kind::Spin: m = m * glm::transpose(spin_matrix(s, t)); break;
        }
    }
    return m;
}

double Motion::speed_bound(double radius, double t_abs) const {
    // From the object outwards: q_i = S_i · q_{i+1}, with |q_i| ≤ reach and |dq_i/dt| ≤ speed.
    double reach = radius, speed = 0;
    for (auto it = steps_.rbegin(); it != steps_.rend(); ++it) {
        const MotionStep& s = *it;
        switch (s.kind) {
            case MotionStep::Kind::Matrix: {
                const double k = stretch(s.matrix);
                speed *= k;
                reach = k * reach + glm::length(glm::dvec3(s.matrix[3]));
                break;
            }
            case MotionStep::Kind::Velocity:
                speed += glm::length(s.vector);
                reach += t_abs * glm::length(s.vector);
                break;
            case MotionStep::Kind::Spin:  // a rotation keeps lengths; it moves a point at |ω|·|q|
                speed += std::abs(glm::radians(s.rate)) * reach;
                break;
        }
    }
    return speed;
}

}  // namespace whitted

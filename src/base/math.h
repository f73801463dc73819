#pragma once
// Constants every stage uses.

namespace whitted {

constexpr float kPi = 3.14159265358979323846f;

}  // namespace whitted

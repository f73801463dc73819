#pragma once
// The matrices of a trans block (scene-format.md §3). Column vectors: p' = M p.
#include <array>
#include <glm/glm.hpp>
#include <optional>

namespace whitted {

glm::mat4 translation_matrix(const glm::vec3& t);
glm::mat4 scale_matrix(const glm::vec3& s);
// Right-handed rotation by `degrees` about `axis` (normalised here); nullopt for a zero axis.
std::optional<glm::mat4> rotation_matrix(const glm::vec3& axis, float degrees);
// 16 numbers as written after matrixRC (row by row) / matrixCR (column by column).
glm::mat4 matrix_from_rows(const std::array<float, 16>& v);
glm::mat4 matrix_from_columns(const std::array<float, 16>& v);

// True when M cannot be safely inverted: a non-finite entry, a (nearly) zero axis, or axes that
// are (nearly) linearly dependent. Scale-invariant, so tiny but regular objects are fine.
bool is_singular(const glm::mat4& m);

}  // namespace whitted

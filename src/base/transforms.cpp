#include "base/transforms.h"

#include <cmath>

namespace whitted {

glm::mat4 translation_matrix(const glm::vec3& t) {
    glm::mat4 m(1.0f);
    m[3] = glm::vec4(t, 1.0f);  // glm is column-major: m[3] is the last column
    return m;
}

glm::mat4 scale_matrix(const glm::vec3& s) {
    glm::mat4 m(1.0f);
    m[0][0] = s.x;
    m[1][1] = s.y;
    m[2][2] = s.z;
    return m;
}

std::optional<glm::mat4> rotation_matrix(const glm::vec3& axis, float degrees) {
    // In double: the axis may be tiny but non-zero, and sin/cos of 90° should be clean.
    const glm::dvec3 a(axis);
    const double len = std::sqrt(glm::dot(a, a));
    if (!(len > 0) || !std::isfinite(len)) return std::nullopt;
    const glm::dvec3 u = a / len;
    const double rad = static_cast<double>(degrees) * (3.14159265358979323846 / 180.0);
    const double c = std::cos(rad), s = std::sin(rad), t = 1 - c;
    // Rodrigues' formula, row r / column k of the usual (column-vector) rotation matrix.
    const double r[3][3] = {
        {t * u.x * u.x + c, t * u.x * u.y - s * u.z, t * u.x * u.z + s * u.y},
        {t * u.x * u.y + s * u.z, t * u.y * u.y + c, t * u.y * u.z - s * u.x},
        {t * u.x * u.z - s * u.y, t * u.y * u.z + s * u.x, t * u.z * u.z + c},
    };
    glm::mat4 m(1.0f);
    for (int row = 0; row < 3; ++row)
        for (int k = 0; k < 3; ++k) m[k][row] = static_cast<float>(r[row][k]);
    return m;
}

glm::mat4 matrix_from_rows(const std::array<float, 16>& v) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) m[i % 4][i / 4] = v[i];  // value i is row i/4, column i%4
    return m;
}

glm::mat4 matrix_from_columns(const std::array<float, 16>& v) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = v[i];  // value i is column i/4, row i%4
    return m;
}

bool is_singular(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return true;
    // Affine matrices (bottom row 0 0 0 1): only the 3×3 part matters, and a large translation
    // must not make a regular matrix look degenerate. Otherwise judge the whole 4×4.
    const bool affine = m[0][3] == 0 && m[1][3] == 0 && m[2][3] == 0 && m[3][3] == 1;
    const glm::dmat4 d(m);
    double det = 0, column_norms = 1;
    if (affine) {
        const glm::dmat3 a(d);
        det = glm::determinant(a);
        for (int c = 0; c < 3; ++c) {
            const double n = glm::length(a[c]);
            if (n < 1e-12)
                return true;  // a zero scale; below 1e-12 the inverse is useless in float
            column_norms *= n;
        }
    } else {
        det = glm::determinant(d);
        for (int c = 0; c < 4; ++c) {
            const double n = glm::length(d[c]);
            if (n < 1e-12) return true;
            column_norms *= n;
        }
    }
    // Hadamard: |det| <= product of the column lengths, with equality for orthogonal axes.
    // The ratio measures how close the axes are to being dependent, whatever the scale.
    return !(std::fabs(det) / column_norms > 1e-6);
}

}  // namespace whitted

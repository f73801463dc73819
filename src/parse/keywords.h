#pragma once
// The format's words (every block's keywords, the shapes, the light types), found by a perfect
// hash: one table look-up and one comparison per word instead of a chain of string compares.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace whitted {

enum class Keyword : std::uint8_t {
    None,  // not one of the words below
    Background, Camera, Light, Mastersubgraph, Trans,                      // top level
    Color,                                                                  // background, light
    Eye, Look, Focus, Up, Angle, NearFar, Aperture, Focaldistance,          // camera
    Type, Position, Direction, Function, Exponent, Radius, Number, Ambient,  // light
    Translate, Scale, Rotate, MatrixRC, MatrixCR, Velocity, Angularrate, Object, Subgraph,  // trans
    File, Diffuse, Specular, Reflect, Transparent, Emit, Shine, Ior, Gloss, Texture, Alpha, Blend,  // object
    Cube, Cylinder, Cone, Sphere, Ellipsoid, Cactus, Cow, Mesh,             // shapes
    Point, Directional, Spotlight,                                          // light types
    Count
};

namespace keyword_detail {

// Spelled as in the files, in the order of the enum.
inline constexpr std::array<std::string_view, std::size_t(Keyword::Count)> kSpelling = {
    "",         "background", "camera",    "light",       "mastersubgraph", "trans",     "color",     "eye",
    "look",     "focus",      "up",        "angle",       "near-far",       "aperture",  "focaldistance",
    "type",     "position",   "direction", "function",    "exponent",       "radius",    "number",    "ambient",
    "translate", "scale",     "rotate",    "matrixRC",    "matrixCR",       "velocity",  "angularrate",
    "object",   "subgraph",   "file",      "diffuse",     "specular",       "reflect",   "transparent",
    "emit",     "shine",      "ior",       "gloss",       "texture",        "alpha",     "blend",     "cube",
    "cylinder", "cone",       "sphere",    "ellipsoid",   "cactus",         "cow",       "mesh",      "point",
    "directional", "spotlight",
};

inline constexpr std::size_t kTableSize = 256;

// From the length and three letters; `seed` is chosen below so that no two keywords collide.
constexpr std::size_t hash(std::string_view w, unsigned seed) {
    const auto at = [&](std::size_t i) { return unsigned(static_cast<unsigned char>(w[i])); };
    return (unsigned(w.size()) * seed + at(0) * 31u + at(w.size() / 2) * (seed >> 4) + at(w.size() - 1)) %
           kTableSize;
}

constexpr bool collision_free(unsigned seed) {
    std::array<bool, kTableSize> used{};
    for (std::size_t k = 1; k < kSpelling.size(); ++k) {
        const std::size_t h = hash(kSpelling[k], seed);
        if (used[h]) return false;
        used[h] = true;
    }
    return true;
}

constexpr unsigned find_seed() {
    for (unsigned seed = 1; seed < 4096; ++seed)
        if (collision_free(seed)) return seed;
    return 0;
}

inline constexpr unsigned kSeed = find_seed();
static_assert(kSeed != 0, "no collision-free seed: add a letter to the hash");

constexpr std::array<Keyword, kTableSize> make_table() {
    std::array<Keyword, kTableSize> table{};
    for (std::size_t k = 1; k < kSpelling.size(); ++k) table[hash(kSpelling[k], kSeed)] = Keyword(k);
    return table;
}
inline constexpr std::array<Keyword, kTableSize> kTable = make_table();

inline constexpr std::size_t kLongest = 14;  // mastersubgraph

// a[0..n) == b[0..n) for n <= 16, by two loads of each side that may overlap, never past n.
inline bool equal_short(const char* a, const char* b, std::size_t n) {
    const auto same = [&](std::size_t at, auto width) {
        decltype(width) x, y;
        std::memcpy(&x, a + at, sizeof x);
        std::memcpy(&y, b + at, sizeof y);
        return x == y;
    };
    if (n >= 8) return same(0, std::uint64_t()) && same(n - 8, std::uint64_t());
    if (n >= 4) return same(0, std::uint32_t()) && same(n - 4, std::uint32_t());
    if (n >= 2) return same(0, std::uint16_t()) && same(n - 2, std::uint16_t());
    return n == 0 || a[0] == b[0];
}

}  // namespace keyword_detail

// The keyword spelled exactly `word` (case-sensitive), or Keyword::None.
inline Keyword find_keyword(std::string_view word) {
    using namespace keyword_detail;
    if (word.empty() || word.size() > kLongest) return Keyword::None;
    const Keyword k = kTable[hash(word, kSeed)];
    const std::string_view spelling = kSpelling[std::size_t(k)];
    return spelling.size() == word.size() && equal_short(spelling.data(), word.data(), word.size()) ? k : Keyword::None;
}

}  // namespace whitted

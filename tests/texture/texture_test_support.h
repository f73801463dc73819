#pragma once
// Helpers for the texture tests: images written to disk in every format we read, a scene with
// one textured object rendered through the public API, and an independent re-statement of
// the camera (spec §5) and of the (u, v) formulas (spec §8) to compute expected pixels by hand.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include "film/image.h"
#include "support/run_process.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted::test {

// An 8-bit RGB picture, row 0 at the top, to be written as a texture file.
struct Picture {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
    Picture(int w, int h) : width(w), height(h), rgb(std::size_t(w) * h * 3, 0) {}
    void set(int x, int y, glm::u8vec3 c) {
        std::uint8_t* p = &rgb[(std::size_t(y) * width + x) * 3];
        p[0] = c.x, p[1] = c.y, p[2] = c.z;
    }
    glm::u8vec3 at(int x, int y) const {
        const std::uint8_t* p = &rgb[(std::size_t(y) * width + x) * 3];
        return {p[0], p[1], p[2]};
    }
};

// The four quadrant colours, distinct in every channel.
inline constexpr glm::u8vec3 kTopLeft{220, 30, 30}, kTopRight{30, 200, 40}, kBottomLeft{40, 70, 230},
    kBottomRight{240, 210, 20};

// A size × size picture of four solid quadrants (top-left = rows and columns < size/2).
inline Picture quadrant_picture(int size = 64) {
    Picture p(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool right = x >= size / 2, bottom = y >= size / 2;
            p.set(x, y, bottom ? (right ? kBottomRight : kBottomLeft) : (right ? kTopRight : kTopLeft));
        }
    return p;
}

// A small picture whose every texel differs (for exact decode checks of lossless formats).
inline Picture distinct_picture(int w = 5, int h = 3) {
    Picture p(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) p.set(x, y, {std::uint8_t(10 + 40 * x), std::uint8_t(20 + 70 * y), std::uint8_t(200 - 13 * (x + y))});
    return p;
}

// A 4 × 4 picture of one colour.
inline Picture solid(glm::u8vec3 c) {
    Picture p(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) p.set(x, y, c);
    return p;
}

inline bool write_png(const std::string& path, const Picture& p) {
    return stbi_write_png(path.c_str(), p.width, p.height, 3, p.rgb.data(), p.width * 3) != 0;
}
inline bool write_tga(const std::string& path, const Picture& p) {
    return stbi_write_tga(path.c_str(), p.width, p.height, 3, p.rgb.data()) != 0;
}
inline bool write_jpg(const std::string& path, const Picture& p) {
    return stbi_write_jpg(path.c_str(), p.width, p.height, 3, p.rgb.data(), 100) != 0;
}
// stb writes a 24-bit bottom-up BMP (positive height: the usual row order).
inline bool write_bmp_stb(const std::string& path, const Picture& p) {
    return stbi_write_bmp(path.c_str(), p.width, p.height, 3, p.rgb.data()) != 0;
}

// A BMP written by hand: 24- or 32-bit BI_RGB, rows bottom-up (positive height) or top-down
// (negative height).
inline bool write_bmp(const std::string& path, const Picture& p, int bits, bool top_down) {
    const int bpp = bits / 8;
    const int row_bytes = (p.width * bpp + 3) & ~3;
    const std::uint32_t data_size = std::uint32_t(row_bytes) * p.height, offset = 14 + 40;
    std::vector<std::uint8_t> f;
    auto u16 = [&](std::uint32_t v) { f.push_back(v & 0xff), f.push_back((v >> 8) & 0xff); };
    auto u32 = [&](std::uint32_t v) { u16(v & 0xffff), u16(v >> 16); };
    f.push_back('B'), f.push_back('M');
    u32(offset + data_size), u32(0), u32(offset);
    u32(40), u32(std::uint32_t(p.width)), u32(std::uint32_t(top_down ? -p.height : p.height));
    u16(1), u16(std::uint32_t(bits)), u32(0 /* BI_RGB */), u32(data_size), u32(2835), u32(2835), u32(0), u32(0);
    for (int i = 0; i < p.height; ++i) {
        const int y = top_down ? i : p.height - 1 - i;
        std::size_t start = f.size();
        for (int x = 0; x < p.width; ++x) {
            glm::u8vec3 c = p.at(x, y);
            f.push_back(c.z), f.push_back(c.y), f.push_back(c.x);  // BGR
            if (bpp == 4) f.push_back(255);
        }
        while (f.size() - start < std::size_t(row_bytes)) f.push_back(0);
    }
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(f.data()), std::streamsize(f.size()));
    return bool(out);
}

// Binary PPM (P6), by hand.
inline bool write_ppm(const std::string& path, const Picture& p) {
    std::ofstream out(path, std::ios::binary);
    out << "P6\n# written by the whitted texture tests\n" << p.width << " " << p.height << "\n255\n";
    out.write(reinterpret_cast<const char*>(p.rgb.data()), std::streamsize(p.rgb.size()));
    return bool(out);
}

inline void write_text(const std::string& path, const std::string& text) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

// Changes the current directory for the lifetime of the object.
class ScopedCwd {
public:
    explicit ScopedCwd(const std::string& dir) : saved_(std::filesystem::current_path()) {
        std::filesystem::current_path(dir);
    }
    ~ScopedCwd() { std::filesystem::current_path(saved_); }

private:
    std::filesystem::path saved_;
};

// A fixture whose scene directory, its parent and the current directory are all private to the
// test, so that no texture lookup can find a file another test left behind.
class PrivateTextureDirs : public ::testing::Test {
protected:
    // Every place a texture is looked for must be private to the test: the scene lives in
    // <tmp>/whitted-test-X/scenes (so its parent is ours too, not the shared /tmp) and the
    // current directory is <tmp>/whitted-test-X/cwd.
    void SetUp() override {
        const std::string base = whitted::test::make_temp_dir();
        ASSERT_FALSE(base.empty());
        dir_ = base + "/scenes";
        std::filesystem::create_directories(dir_);
        std::filesystem::create_directories(base + "/cwd");
        cwd_.emplace(base + "/cwd");
        scene_ = dir_ + "/scene.sc";
    }
    void TearDown() override { cwd_.reset(); }
    std::string dir_, scene_;
    std::optional<ScopedCwd> cwd_;
};

// ---------------------------------------------------------------------------------------------
// The camera of spec §5, restated: full vertical angle, basis from look and up, rays through
// pixel centres, row 0 at the top.
struct HandCamera {
    glm::dvec3 eye, forward, right, up;
    double tan_half;
    int width, height;

    HandCamera(glm::dvec3 eye_, glm::dvec3 look, glm::dvec3 up_, double angle_deg, int w, int h)
        : eye(eye_), tan_half(std::tan(angle_deg * std::numbers::pi / 360.0)), width(w), height(h) {
        forward = glm::normalize(look);
        right = glm::normalize(glm::cross(forward, up_));
        up = glm::cross(right, forward);
    }
    glm::dvec3 direction(int px, int py) const {
        const double x = px + 0.5, y = py + 0.5;
        const double sx = (2 * x / width - 1) * tan_half * double(width) / height;
        const double sy = (1 - 2 * y / height) * tan_half;
        return glm::normalize(forward + sx * right + sy * up);
    }
};

enum class Piece { Side, TopCap, BottomCap, PosX, NegX, PosY, NegY, PosZ, NegZ };

struct HandHit {
    Piece piece;
    glm::dvec3 p;      // object space
    double cos_view;   // |cos| between the ray and the surface normal (small = grazing)
    double edge;       // distance (object units) from the nearest edge of the piece
};

// The nearest hit of the ray o + t·d (object space, t > 0) with a unit shape, or nothing.
// Written from the shape definitions of spec §4, independently of src/shapes.
inline std::optional<HandHit> hand_intersect(ShapeKind kind, glm::dvec3 o, glm::dvec3 d) {
    d = glm::normalize(d);
    std::optional<HandHit> best;
    double best_t = 1e30;
    auto consider = [&](double t, Piece piece, glm::dvec3 n, double edge) {
        if (!(t > 1e-9) || t >= best_t) return;
        best_t = t;
        best = HandHit{piece, o + t * d, std::abs(glm::dot(d, glm::normalize(n))), edge};
    };
    auto plane = [&](int axis, double at) { return (at - o[axis]) / d[axis]; };
    auto quadratic_roots = [](double a, double b, double c, double& t0, double& t1) {
        const double disc = b * b - 4 * a * c;
        if (a == 0 || disc < 0) return false;
        t0 = (-b - std::sqrt(disc)) / (2 * a);
        t1 = (-b + std::sqrt(disc)) / (2 * a);
        return true;
    };
    switch (kind) {
        case ShapeKind::Cube: {
            const Piece pieces[3][2] = {{Piece::NegX, Piece::PosX}, {Piece::NegY, Piece::PosY}, {Piece::NegZ, Piece::PosZ}};
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side) {
                    const double at = side ? 0.5 : -0.5;
                    const double t = plane(axis, at);
                    const glm::dvec3 p = o + t * d;
                    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
                    const double edge = std::min(0.5 - std::abs(p[a1]), 0.5 - std::abs(p[a2]));
                    glm::dvec3 n(0.0);
                    n[axis] = at;
                    if (edge >= 0) consider(t, pieces[axis][side], n, edge);
                }
            break;
        }
        case ShapeKind::Sphere: {
            double t0, t1;
            if (quadratic_roots(1, 2 * glm::dot(o, d), glm::dot(o, o) - 0.25, t0, t1)) {
                for (double t : {t0, t1}) consider(t, Piece::Side, o + t * d, 1.0);
            }
            break;
        }
        case ShapeKind::Ellipsoid: {  // x² + 4y² + z² = 1, gradient ∝ (x, 4y, z)
            double t0, t1;
            const double a = d.x * d.x + 4 * d.y * d.y + d.z * d.z;
            const double b = 2 * (o.x * d.x + 4 * o.y * d.y + o.z * d.z);
            const double c = o.x * o.x + 4 * o.y * o.y + o.z * o.z - 1;
            if (quadratic_roots(a, b, c, t0, t1))
                for (double t : {t0, t1}) {
                    const glm::dvec3 p = o + t * d;
                    consider(t, Piece::Side, {p.x, 4 * p.y, p.z}, 1.0);
                }
            break;
        }
        case ShapeKind::Cylinder:
        case ShapeKind::Cone: {
            const bool cone = kind == ShapeKind::Cone;
            double t0, t1;
            // cylinder: x² + z² = 0.25; cone: x² + z² = ((0.5 − y)/2)².
            double a = d.x * d.x + d.z * d.z, b = 2 * (o.x * d.x + o.z * d.z), c = o.x * o.x + o.z * o.z - 0.25;
            if (cone) {
                const double k = 0.5 - o.y;  // radius·2 at the origin's height
                a -= d.y * d.y / 4;
                b += k * d.y / 2;
                c = o.x * o.x + o.z * o.z - k * k / 4;
            }
            if (quadratic_roots(a, b, c, t0, t1))
                for (double t : {t0, t1}) {
                    const glm::dvec3 p = o + t * d;
                    if (p.y < -0.5 || p.y > 0.5) continue;
                    const glm::dvec3 n = cone ? glm::dvec3(p.x, 0.5 * std::sqrt(p.x * p.x + p.z * p.z), p.z)
                                              : glm::dvec3(p.x, 0, p.z);
                    consider(t, Piece::Side, n, std::min(0.5 - p.y, p.y + 0.5));
                }
            for (int top = 0; top < 2; ++top) {
                if (cone && top) continue;
                const double t = plane(1, top ? 0.5 : -0.5);
                const glm::dvec3 p = o + t * d;
                const double r = std::sqrt(p.x * p.x + p.z * p.z);
                if (r <= 0.5) consider(t, top ? Piece::TopCap : Piece::BottomCap, {0, top ? 1 : -1, 0}, 0.5 - r);
            }
            break;
        }
        case ShapeKind::Mesh: break;  // not a unit shape
    }
    return best;
}

// The (u, v) formulas of spec §8, restated.
inline glm::dvec2 hand_uv(ShapeKind kind, const HandHit& h) {
    const glm::dvec3 p = h.p;
    const double phi = std::atan2(p.z, p.x);
    const double around = 0.5 - phi / (2 * std::numbers::pi);
    switch (h.piece) {
        case Piece::Side:
            if (kind == ShapeKind::Sphere || kind == ShapeKind::Ellipsoid) return {around, 0.5 - std::asin(std::clamp(2 * p.y, -1.0, 1.0)) / std::numbers::pi};
            return {around, 0.5 - p.y};
        case Piece::TopCap: return {p.x + 0.5, p.z + 0.5};
        case Piece::BottomCap: return {p.x + 0.5, 0.5 - p.z};
        case Piece::PosZ: return {p.x + 0.5, 0.5 - p.y};
        case Piece::NegZ: return {0.5 - p.x, 0.5 - p.y};
        case Piece::PosX: return {0.5 - p.z, 0.5 - p.y};
        case Piece::NegX: return {p.z + 0.5, 0.5 - p.y};
        case Piece::PosY: return {p.x + 0.5, p.z + 0.5};
        case Piece::NegY: return {p.x + 0.5, 0.5 - p.z};
    }
    return {0, 0};
}

inline double frac(double x) { return x - std::floor(x); }

// The quadrant colour at (s, t) of the quadrant picture.
inline glm::u8vec3 quadrant_colour(double s, double t) {
    const bool right = s >= 0.5, bottom = t >= 0.5;
    return bottom ? (right ? kBottomRight : kBottomLeft) : (right ? kTopRight : kTopLeft);
}

// Distance from s to the nearest quadrant boundary or wrap-around edge (0, ½, 1).
inline double quadrant_margin(double s) {
    return std::min({std::abs(s), std::abs(s - 0.5), std::abs(1 - s)});
}

// ---------------------------------------------------------------------------------------------
struct Rendered {
    LoadResult load;
    Image image;
    std::string messages;  // every diagnostic, for failure output
};

inline Rendered render_scene_text(const std::string& text, const std::string& path, int w, int h,
                                  RenderMode mode = RenderMode::Raycast, const LoadOptions& options = {}) {
    Rendered r;
    r.load = load_scene_text(text, path, options);
    for (const auto& d : r.load.diagnostics) r.messages += d.str() + "\n";
    if (!r.load.ok()) return r;
    r.image = Image(w, h);
    RenderJob ro;
    ro.width = w;
    ro.height = h;
    ro.integrator.mode = mode;
    ro.threads = 2;
    render(*r.load.scene, ro, r.image);
    return r;
}

inline std::string fmt(glm::dvec3 v) {
    return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z);
}

}  // namespace whitted::test

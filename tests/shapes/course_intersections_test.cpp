// Reproduces the course's reference table of ray/unit-shape hits
// (shared/scenes/wild/suziray__COURSE-452-computer-graphics/intersections.txt): for rays
// i = 13 … 1650 built from Halton points, every hit with t > 0 on each of the four shapes,
// printed as t, point, normal to 4 significant digits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "shapes/unit_shape_math.h"
#include "shapes/unit_shapes.h"
#include "support/needs.h"

namespace whitted {
namespace {

constexpr const char* kRelPath =
    "scenes/wild/suziray__COURSE-452-computer-graphics/intersections.txt";

std::filesystem::path table_path() {
    if (const char* dir = std::getenv("WHITTED_SHARED_DIR")) return std::filesystem::path(dir) / kRelPath;
    return std::filesystem::path(WHITTED_SOURCE_DIR) / ".." / "shared" / kRelPath;
}

// Radical inverse of n in base b: the Halton coordinate.
double radical_inverse(int n, int b) {
    const double inv = 1.0 / b;
    double f = inv, r = 0;
    for (; n > 0; n /= b, f *= inv) r += (n % b) * f;
    return r;
}

struct CourseRay {
    glm::dvec3 origin, direction;
};

CourseRay course_ray(int i) {
    auto h = [i](int b) { return radical_inverse(i + 1, b); };
    const double pi = std::numbers::pi;
    auto unit = [pi](double a, double b) {
        return glm::dvec3(std::sin(pi * a) * std::cos(2 * pi * b), std::sin(pi * a) * std::sin(2 * pi * b),
                          std::cos(pi * a));
    };
    return {h(11) * unit(h(2), h(3)), unit(h(5), h(7))};
}

struct Hit {
    double t;
    glm::dvec3 p, n;
};

struct Line {
    int number = 0;  // line in the file, 1-based
    int ray = 0;
    std::string shape;
    std::vector<Hit> hits;
    std::string text;
};

// "13 Cube     Hits: 1 | 0.5967 (0.3216, -0.1973, -0.5) (0, 0, -1)". Exponents may be
// printed in the MSVC style "2.959e-005"; strtod reads that.
bool parse_line(const std::string& text, Line& out) {
    std::string s = text;
    for (char& c : s)
        if (c == '(' || c == ')' || c == ',' || c == '|') c = ' ';
    std::istringstream in(s);
    std::string hits_word;
    int count = -1;
    if (!(in >> out.ray >> out.shape >> hits_word >> count) || hits_word != "Hits:" || count < 0)
        return false;
    for (int k = 0; k < count; ++k) {
        Hit h;
        if (!(in >> h.t >> h.p.x >> h.p.y >> h.p.z >> h.n.x >> h.n.y >> h.n.z)) return false;
        out.hits.push_back(h);
    }
    std::string rest;
    return !(in >> rest);
}

bool shape_from_name(const std::string& name, ShapeKind& kind) {
    if (name == "Cube") kind = ShapeKind::Cube;
    else if (name == "Cylinder") kind = ShapeKind::Cylinder;
    else if (name == "Cone") kind = ShapeKind::Cone;
    else if (name == "Sphere") kind = ShapeKind::Sphere;
    else return false;
    return true;
}

// The file prints 4 significant digits (%.4g), so a printed value v stands for anything within
// half a unit of its 4th digit: 0.5·10^(floor(log10|v|) − 3) (≤ 5e-4·|v|); the 1e-9 only absorbs
// the double rounding of that bound. That is the whole tolerance for our double instance.
// `slack` adds our own rounding error for the float instance (see below).
// Signed zero: -0 and 0 compare equal numerically, so "-0" vs "0" is not a disagreement.
bool agrees(double mine, double printed, double slack) {
    const double half_digit =
        printed == 0 ? 0 : 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(printed))) - 3);
    return std::abs(mine - printed) <= half_digit * (1 + 1e-9) + slack;
}

template <class T>
std::vector<Hit> my_hits(ShapeKind kind, const CourseRay& r) {
    using V = shape_math::Vec3<T>;
    const V o(r.origin), d(r.direction);
    const auto s = shape_math::intersect<T>(kind, o, d);
    std::vector<Hit> hits;
    for (int k = 0; k < s.count; ++k) {
        if (!(s.t[k] > 0)) continue;
        const V p = o + s.t[k] * d;
        hits.push_back({double(s.t[k]), glm::dvec3(p), glm::dvec3(shape_math::normal<T>(kind, s.part[k], p))});
    }
    return hits;
}

std::string describe(const std::vector<Hit>& hits) {
    std::ostringstream os;
    os.precision(7);
    os << "Hits: " << hits.size();
    for (const Hit& h : hits)
        os << " | " << h.t << " (" << h.p.x << ", " << h.p.y << ", " << h.p.z << ") (" << h.n.x << ", "
           << h.n.y << ", " << h.n.z << ")";
    return os.str();
}

// Compares every line; returns one message per disagreeing line (empty: all agree).
template <class T>
std::vector<std::string> compare_table(const std::vector<Line>& lines, double slack) {
    std::vector<std::string> bad;
    for (const Line& line : lines) {
        ShapeKind kind{};
        if (!shape_from_name(line.shape, kind)) {
            bad.push_back("line " + std::to_string(line.number) + ": unknown shape " + line.shape);
            continue;
        }
        const std::vector<Hit> mine = my_hits<T>(kind, course_ray(line.ray));
        bool ok = mine.size() == line.hits.size();
        for (size_t k = 0; ok && k < mine.size(); ++k) {
            const Hit &a = mine[k], &b = line.hits[k];
            ok = agrees(a.t, b.t, slack);
            for (int c = 0; c < 3; ++c) ok = ok && agrees(a.p[c], b.p[c], slack) && agrees(a.n[c], b.n[c], slack);
        }
        if (!ok)
            bad.push_back("line " + std::to_string(line.number) + " (ray " + std::to_string(line.ray) + " " +
                          line.shape + ")\n  file: " + line.text + "\n  ours: " + describe(mine));
    }
    return bad;
}

std::vector<Line> load_table(const std::filesystem::path& path, std::string& error) {
    std::ifstream in(path);
    std::vector<Line> lines;
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (text.empty()) continue;
        Line line;
        line.number = number;
        line.text = text;
        if (!parse_line(text, line)) {
            error = "cannot parse line " + std::to_string(number) + ": " + text;
            return {};
        }
        lines.push_back(std::move(line));
    }
    return lines;
}

template <class T>
void check_table(double slack) {
    const auto path = table_path();
    WHITTED_NEEDS(test::kSkipSharedTests, std::filesystem::exists(path)
                                              ? ""
                                              : "the course's intersection table is not at " + path.string() +
                                                    " (set WHITTED_SHARED_DIR to the shared folder)");
    std::string error;
    const std::vector<Line> lines = load_table(path, error);
    ASSERT_TRUE(error.empty()) << error;
    ASSERT_EQ(lines.size(), 6552u) << path;
    EXPECT_EQ(lines.front().ray, 13);
    EXPECT_EQ(lines.back().ray, 1650);
    const std::vector<std::string> bad = compare_table<T>(lines, slack);
    std::string all;
    for (const std::string& b : bad) all += b + "\n";
    EXPECT_TRUE(bad.empty()) << bad.size() << " of " << lines.size() << " lines disagree:\n" << all;
}

// The exact check: the shape math in double must reproduce every printed digit.
TEST(CourseIntersections, EveryLineMatchesInDouble) { check_table<double>(0.0); }

// The renderer's float instance. Its own rounding can flip a printed digit at a rounding tie
// (0.019865 vs 0.0198650x) or when a coordinate cancels to ~1e-5 (o + t·d with |o|, |t·d| ~ 0.5),
// so it gets an absolute slack of 1e-6: ~8 float ulps of the O(1) quantities involved.
TEST(CourseIntersections, EveryLineMatchesInFloat) { check_table<float>(1e-6); }

}  // namespace
}  // namespace whitted

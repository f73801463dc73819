#include "mesh/obj_line.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace whitted {

namespace {

bool digit(char c) { return static_cast<unsigned char>(c - '0') < 10; }
bool blank(char c) { return c == ' ' || c == '\t'; }

const char* skip_blanks(const char* p, const char* end) {
    while (p < end && blank(*p)) ++p;
    return p;
}

// The end of a word: the first space, tab or \r (a line has no \n), or the line's end.
const char* word_end(const char* p, const char* end) {
    while (p < end && !blank(*p) && *p != '\r') ++p;
    return p;
}

// A real in the line at p: blanks skipped, then the word (its number, or `fallback` if it is
// none); p past the word.
float read_real(const char*& p, const char* end, double fallback) {
    p = skip_blanks(p, end);
    const char* e = word_end(p, end);
    double value = fallback;
    parse_obj_number(p, e, value);
    p = e;
    return static_cast<float>(value);
}

// An index as C's atoi (strtol, base 10, then made an int) reads it at p: leading white space of
// any kind skipped, a sign, digits; saturated at the long's range, then wrapped to an int.
int read_index(const char* p, const char* end) {
    // Most indices: a few digits (up to 18 cannot leave the long's range).
    if (const char* q = p; q < end && digit(*q)) {
        std::int64_t value = 0;
        for (; q < end && digit(*q) && q - p < 18; ++q) value = value * 10 + (*q - '0');
        if (q == end || !digit(*q)) return static_cast<int>(value);  // modulo 2^32
    }
    while (p < end && (*p == ' ' || (*p >= '\t' && *p <= '\r'))) ++p;
    bool negative = false;
    if (p < end && (*p == '+' || *p == '-')) negative = *p++ == '-';
    constexpr std::uint64_t kLimit = std::uint64_t(1) << 63;  // |LONG_MIN|
    std::uint64_t magnitude = 0;
    for (; p < end && digit(*p); ++p) {
        const unsigned d = unsigned(*p - '0');
        magnitude = magnitude > (kLimit - d) / 10 ? kLimit + 1 : magnitude * 10 + d;  // past the range: saturated
    }
    std::int64_t value;
    if (negative) value = magnitude >= kLimit ? INT64_MIN : -std::int64_t(magnitude);
    else value = magnitude >= kLimit ? INT64_MAX : std::int64_t(magnitude);
    return static_cast<int>(value);  // modulo 2^32
}

// Past an index: to the next '/', space, tab or \r.
const char* index_end(const char* p, const char* end) {
    while (p < end && *p != '/' && !blank(*p) && *p != '\r') ++p;
    return p;
}

// A corner: `v`, `v/vt`, `v//vn` or `v/vt/vn`; p past it.
ObjCorner read_corner(const char*& p, const char* end) {
    ObjCorner c;
    c.v = read_index(p, end);
    p = index_end(p, end);
    if (p == end || *p != '/') return c;
    ++p;
    if (p < end && *p == '/') {
        ++p;
        c.vn = read_index(p, end);
        p = index_end(p, end);
        return c;
    }
    c.vt = read_index(p, end);
    p = index_end(p, end);
    if (p == end || *p != '/') return c;
    ++p;
    c.vn = read_index(p, end);
    p = index_end(p, end);
    return c;
}

}  // namespace

bool parse_obj_number(const char* s, const char* end, double& result) {
    if (s >= end) return false;
    const char* p = s;
    bool negative = false, leading_dot = false;
    if (*p == '+' || *p == '-') {
        negative = *p++ == '-';
        leading_dot = p != end && *p == '.';
    } else if (*p == '.') {
        leading_dot = true;
    } else if (!digit(*p)) {
        return false;
    }
    // The digits gathered into a double as tinyobjloader does, so that a file reads to the same
    // floats as it always has: the whole part exactly, each decimal as digit × 10^-k.
    double mantissa = 0.0;
    if (!leading_dot) {
        const char* first = p;
        for (; p < end && digit(*p); ++p) mantissa = mantissa * 10 + int(*p - '0');
        if (p == first) return false;
    }
    int exponent = 0;
    if (p < end && *p == '.') {
        ++p;
        static constexpr double kPowers[] = {1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001};
        for (int k = 1; p < end && digit(*p); ++k, ++p)
            mantissa += int(*p - '0') * (k < 8 ? kPowers[k] : std::pow(10.0, -k));
    }
    if (p < end && (*p == 'e' || *p == 'E')) {
        ++p;
        // "1e", "1e+" and "1ex" are no number (past the word's end is never a digit).
        bool exponent_negative = false;
        if (p < end && (*p == '+' || *p == '-')) exponent_negative = *p++ == '-';
        else if (p == end || !digit(*p)) return false;
        const char* first = p;
        std::uint32_t e = 0;  // wraps as that parser's int did (built with -fwrapv)
        for (; p < end && digit(*p); ++p) {
            if (std::int32_t(e) > 2147483647 / 10) return false;
            e = e * 10u + std::uint32_t(*p - '0');
        }
        if (p == first) return false;
        exponent = std::int32_t(exponent_negative ? 0u - e : e);
    }
    const double magnitude = exponent ? std::ldexp(mantissa * std::pow(5.0, exponent), exponent) : mantissa;
    result = (negative ? -1 : 1) * magnitude;
    return true;
}

void parse_obj_line(std::string_view text, ObjLine& out) {
    out.kind = ObjLineKind::Other;
    const char* p = text.data();
    // The line ends at a NUL, as a C string would.
    const char* end = p + text.size();
    if (const void* nul = std::memchr(p, '\0', text.size())) end = static_cast<const char*>(nul);
    p = skip_blanks(p, end);
    const std::size_t n = std::size_t(end - p);
    if (n < 2) return;
    if (p[0] == 'v') {
        if (blank(p[1])) {
            p += 2;
            for (float& c : out.xyz) c = read_real(p, end, 0.0);
            out.kind = ObjLineKind::Vertex;  // (a fourth number, w, is read by no one)
        } else if (n >= 3 && (p[1] == 'n' || p[1] == 't') && blank(p[2])) {
            out.kind = p[1] == 'n' ? ObjLineKind::Normal : ObjLineKind::TexCoord;
            p += 3;
            for (float& c : out.xyz) c = read_real(p, end, 0.0);
        }
    } else if (p[0] == 'f' && blank(p[1])) {
        out.kind = ObjLineKind::Face;
        out.corners.clear();
        p = skip_blanks(p + 2, end);
        while (p < end) {
            out.corners.push_back(read_corner(p, end));
            while (p < end && (blank(*p) || *p == '\r')) ++p;
        }
    }
}

}  // namespace whitted

#pragma once
// Strict C floating-point literals for scene files (scene-format.md §1).
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace whitted {

enum class NumberStatus {
    Ok,
    TrailingComma,  // "0.2125," — accepted, the caller warns
    Invalid,        // not a decimal literal: words, nan, inf, hex, "1.2.3", ...
    OutOfRange,     // a literal whose magnitude does not fit in a float
};

struct NumberParse {
    NumberStatus status = NumberStatus::Invalid;
    float value = 0;
};

// Accepts [+-]? (digits [. digits*] | . digits) ([eE] [+-]? digits)?, the whole token, and
// optionally one trailing ','. Locale-independent. The value is the double nearest the literal
// (as strtod or std::from_chars give it), rounded to float.
NumberParse parse_number_literal(std::string_view token);

namespace number_detail {
// Powers of ten that a double holds exactly.
inline constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                               1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                               1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
}  // namespace number_detail

struct PlainNumber {
    const char* end = nullptr;  // where the scan stopped
    bool ok = false;            // what came before `end` is a plain number
    float value = 0;
};

namespace number_detail {

inline PlainNumber plain_number(bool negative, std::uint64_t mantissa, std::size_t decimals, const char* end) {
    PlainNumber r;
    const double value = static_cast<double>(mantissa) / kExactPowersOfTen[decimals];
    r.value = static_cast<float>(negative ? -value : value);
    r.ok = true;
    r.end = end;
    return r;
}

}  // namespace number_detail

// The form nearly every number in a file has: [-]digits[.digits] with at most 15 digits, read
// from `p` as far as it goes (the caller checks that the token ends there). The digits are an
// exact double, and so is 10^decimals, so one correctly rounded division gives the double
// nearest the literal, as parse_number_literal does.
inline PlainNumber scan_plain_number(const char* p, const char* const end) {
    using namespace number_detail;
    const bool negative = p != end && *p == '-';
    p += negative;
    std::uint64_t mantissa = 0;
    auto digits_from = [&](const char* q) {  // up to the first non-digit
        for (; q != end; ++q) {
            const unsigned digit = unsigned(static_cast<unsigned char>(*q)) - unsigned('0');
            if (digit >= 10) break;
            mantissa = mantissa * 10 + digit;
        }
        return q;
    };
    const char* const int_end = digits_from(p);
    std::size_t digits = std::size_t(int_end - p), decimals = 0;
    const char* stop = int_end;
    if (int_end != end && *int_end == '.') {
        stop = digits_from(int_end + 1);
        decimals = std::size_t(stop - int_end - 1);
        digits += decimals;
    }
    if (digits == 0 || digits > 15) return {stop, false, 0};
    return plain_number(negative, mantissa, decimals, stop);
}

// parse_number_literal, with plain numbers read inline.
inline NumberParse parse_number(std::string_view token) {
    const char* const end = token.data() + token.size();
    const PlainNumber plain = scan_plain_number(token.data(), end);
    if (plain.ok && plain.end == end) return {NumberStatus::Ok, plain.value};
    return parse_number_literal(token);
}

}  // namespace whitted

#pragma once
// Strict C floating-point literals for scene files (scene-format.md §1).
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
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

inline std::uint64_t load8(const char* p) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
}

// How many of the 8 bytes of v (first byte lowest) are ASCII digits before the first that is not.
inline unsigned leading_digits(std::uint64_t v) {
    constexpr std::uint64_t ones = 0x0101010101010101u;
    // Zero in a byte that is a digit: high nibble 3, and low nibble + 6 still below 16 (no carry
    // leaves a byte on either side).
    const std::uint64_t z = ((v & (ones * 0xF0)) ^ (ones * 0x30)) | (((v & (ones * 0x0F)) + ones * 0x06) & (ones * 0xF0));
    const std::uint64_t nonzero = (((z & (ones * 0x7F)) + ones * 0x7F) | z) & (ones * 0x80);
    return nonzero ? unsigned(std::countr_zero(nonzero)) / 8 : 8;
}

// The value of the first k (1-8) bytes of v, all digits (Lemire's eight digits at once: the
// digits moved to the top, zeros before them).
inline std::uint64_t digits_value(std::uint64_t v, unsigned k) {
    constexpr std::uint64_t ones = 0x0101010101010101u;
    v = (v - ones * 0x30) << (8 * (8 - k));  // a digit never borrows; what follows is shifted out
    v = v * 10 + (v >> 8);
    constexpr std::uint64_t mask = 0x000000FF000000FFu;
    constexpr std::uint64_t mul1 = 100 + (std::uint64_t(1000000) << 32), mul2 = 1 + (std::uint64_t(10000) << 32);
    return (((v & mask) * mul1) + (((v >> 16) & mask) * mul2)) >> 32;
}

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
    // Eight bytes at a time where the text goes on that far (no branch per digit).
    if (end - p >= 8) {
        const std::uint64_t head = load8(p);
        const unsigned a = leading_digits(head);
        if (a < 8) {
            const std::uint64_t whole = a ? digits_value(head, a) : 0;
            if (p[a] != '.') {
                if (a == 0) return {p, false, 0};
                return plain_number(negative, whole, 0, p + a);
            }
            const char* const decimals_at = p + a + 1;
            if (end - decimals_at >= 8) {
                const std::uint64_t tail = load8(decimals_at);
                const unsigned b = leading_digits(tail);
                if (b < 8) {
                    if (a + b == 0) return {decimals_at, false, 0};
                    const std::uint64_t mantissa = b ? whole * std::uint64_t(kExactPowersOfTen[b]) + digits_value(tail, b) : whole;
                    return plain_number(negative, mantissa, b, decimals_at + b);
                }
            }
        }
    }
    // Near the end of the text, or long: one digit at a time.
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

#include "parse/number.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>

namespace whitted {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

using number_detail::kExactPowersOfTen;
constexpr std::uint64_t kExactMantissa = std::uint64_t(1) << 53;  // every integer up to it is a double

// The value of a literal whose shape has been checked, through std::from_chars: the nearest
// double, then that rounded to float (which may differ from the float nearest the literal).
NumberParse read_through_from_chars(std::string_view literal) {
    NumberParse result;
    if (literal.front() == '+') literal.remove_prefix(1);  // from_chars rejects a leading '+'
    double value = 0;  // in double so that float overflow is seen; float underflow gives 0
    const auto [ptr, ec] = std::from_chars(literal.data(), literal.data() + literal.size(), value);
    if (ec == std::errc::result_out_of_range) {  // beyond double: 1e999 or 1e-999
        result.status = NumberStatus::OutOfRange;
        return result;
    } else if (ec != std::errc() || ptr != literal.data() + literal.size()) {
        return result;
    }
    if (std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
        result.status = NumberStatus::OutOfRange;
        return result;
    }
    result.value = static_cast<float>(value);
    result.status = NumberStatus::Ok;
    return result;
}

}  // namespace

NumberParse parse_number_literal(std::string_view token) {
    // One pass checks the shape (we do it ourselves: from_chars and strtod also take hex, inf and
    // nan) and gathers the digits: value = ±mantissa · 10^exponent.
    NumberParse result;
    const char* p = token.data();
    const char* end = p + token.size();
    bool comma = false;
    if (p != end && end[-1] == ',') {
        --end;
        comma = true;
    }
    const char* const literal = p;
    bool negative = false;
    if (p != end && (*p == '+' || *p == '-')) negative = *p++ == '-';
    std::uint64_t mantissa = 0;  // wraps past 19 digits, and is not used then
    const char* const int_start = p;
    for (; p != end && is_digit(*p); ++p) mantissa = mantissa * 10 + std::uint64_t(*p - '0');
    std::size_t digits = std::size_t(p - int_start), frac_digits = 0;
    if (p != end && *p == '.') {
        const char* const frac_start = ++p;
        for (; p != end && is_digit(*p); ++p) mantissa = mantissa * 10 + std::uint64_t(*p - '0');
        frac_digits = std::size_t(p - frac_start);
        digits += frac_digits;
    }
    if (digits == 0) return result;
    int written_exponent = 0;
    bool small_exponent = true;
    if (p != end && (*p == 'e' || *p == 'E')) {
        ++p;
        bool negative_exponent = false;
        if (p != end && (*p == '+' || *p == '-')) negative_exponent = *p++ == '-';
        if (p == end || !is_digit(*p)) return result;
        for (; p != end && is_digit(*p); ++p) {
            written_exponent = written_exponent * 10 + (*p - '0');
            if (written_exponent > 99999) small_exponent = false, written_exponent = 0;
        }
        if (negative_exponent) written_exponent = -written_exponent;
    }
    if (p != end) return result;
    // With at most 19 digits the mantissa is exact; with at most 2^53 a double holds it, and then
    // a power of ten up to 10^22 is an exact double too, so one correctly rounded multiplication
    // or division gives the double nearest the literal, as from_chars would (Clinger's fast path),
    // far below float's maximum. Zero is zero at any scale. Anything else goes to from_chars.
    const bool exact = digits <= 19 && small_exponent;
    const int exponent = exact ? written_exponent - static_cast<int>(frac_digits) : 0;
    if (exact && mantissa == 0) {
        result.value = negative ? -0.0f : 0.0f;
    } else if (exact && mantissa <= kExactMantissa && exponent >= -22 && exponent <= 22) {
        double value = static_cast<double>(mantissa);
        value = exponent >= 0 ? value * kExactPowersOfTen[exponent] : value / kExactPowersOfTen[-exponent];
        result.value = static_cast<float>(negative ? -value : value);
    } else {
        result = read_through_from_chars(std::string_view(literal, std::size_t(end - literal)));
        if (result.status != NumberStatus::Ok) return result;
    }
    result.status = comma ? NumberStatus::TrailingComma : NumberStatus::Ok;
    return result;
}

}  // namespace whitted

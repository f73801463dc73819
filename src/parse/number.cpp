#include "parse/number.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace whitted {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// True when s is exactly a C decimal floating literal (no hex, inf, nan: we check the shape
// ourselves because from_chars and strtod accept those).
bool is_decimal_literal(std::string_view s) {
    size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t int_digits = 0, frac_digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++int_digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && is_digit(s[i])) ++i, ++frac_digits;
    }
    if (int_digits + frac_digits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        size_t exp_digits = 0;
        while (i < s.size() && is_digit(s[i])) ++i, ++exp_digits;
        if (exp_digits == 0) return false;
    }
    return i == s.size();
}

}  // namespace

NumberParse parse_number(std::string_view token) {
    NumberParse result;
    bool comma = false;
    if (!token.empty() && token.back() == ',') {
        token.remove_suffix(1);
        comma = true;
    }
    if (!is_decimal_literal(token)) return result;
    if (token.front() == '+') token.remove_prefix(1);  // from_chars rejects a leading '+'

    double value =
        0;  // parse in double so that float overflow is detected; float underflow gives 0
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec == std::errc::result_out_of_range) {  // beyond double: 1e999 or 1e-999
        result.status = NumberStatus::OutOfRange;
        return result;
    } else if (ec != std::errc() || ptr != token.data() + token.size()) {
        return result;
    }
    if (std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
        result.status = NumberStatus::OutOfRange;
        return result;
    }
    result.value = static_cast<float>(value);
    result.status = comma ? NumberStatus::TrailingComma : NumberStatus::Ok;
    return result;
}

}  // namespace whitted

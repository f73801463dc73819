#pragma once
// Strict C floating-point literals for scene files (scene-format.md §1).
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
// optionally one trailing ','. Locale-independent.
NumberParse parse_number(std::string_view token);

}  // namespace whitted

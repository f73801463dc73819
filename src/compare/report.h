#pragma once
// A comparison told to a person (a few aligned lines ending in idiff's PASS / WARNING / FAILURE)
// or to a script (one JSON object with every metric).
#include <string>

#include "compare/compare.h"

namespace whitted {

struct CompareInputs {
    std::string path_a, format_a;  // the reference
    std::string path_b, format_b;  // the image compared with it
    std::string diff_path;         // where the FLIP error image went, or ""
};

std::string report_text(const CompareInputs& in, const CompareOptions& options, const CompareReport& r);

// One JSON object (a line of its own). Infinite or NaN numbers (the PSNR of equal images, the
// error against a NaN) are null.
std::string report_json(const CompareInputs& in, const CompareOptions& options, const CompareReport& r);

// `s` as a JSON string literal, quotes included; bytes that are not UTF-8 become U+FFFD.
std::string json_string(const std::string& s);

}  // namespace whitted

#pragma once
// An explanation told to a person (what differs, which mistake it looks like, which term, where)
// or to a script (one JSON object).
#include <string>

#include "compare/explain.h"

namespace whitted {

struct ExplainInputs {
    std::string scene_path, image_path, image_format;
    std::string diff_path;  // where the error image went, or ""
    std::string base_dir;   // the scene's folder: file locations are shown relative to it
};

// The phrase for a fitted term ("the specular highlights are missing"), or "" when the image has
// the term as the reference has it (within 10%).
std::string term_words(const TermFit& fit);

// The fit over one region in words: the terms that are off there, with their coefficients, and how
// much of the region's difference the fit explains (or that no mix of the terms makes it).
std::string region_fit_words(const Region& g);

// The explanation in one line, as a grading table shows it: the best-matching named mistake ("looks
// like: the image upside down (47.0 dB against 19.0 dB as is)") and the term the fit names first ("the
// specular highlights are missing"); "no difference" for a PASS, "no named mistake or term" when
// neither is found.
std::string explain_summary(const Explanation& e);

std::string explain_text(const ExplainInputs& in, const ExplainOptions& options, const Explanation& e);
std::string explain_json(const ExplainInputs& in, const ExplainOptions& options, const Explanation& e);

}  // namespace whitted

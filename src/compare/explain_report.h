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

std::string explain_text(const ExplainInputs& in, const ExplainOptions& options, const Explanation& e);
std::string explain_json(const ExplainInputs& in, const ExplainOptions& options, const Explanation& e);

}  // namespace whitted

#pragma once
// "did you mean 'X'?" for a misspelt keyword, object type or light type.
#include <string>
#include <string_view>

namespace whitted {

// Levenshtein distance (insertions, deletions, substitutions; a swap of two letters counts 2).
int edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word`, from `candidates` written as "a, b, c", when it is close
// enough to be a likely misspelling: an edit distance of at most 2 (1 for words of up to 4
// letters), or a word that begins with the whole candidate's stem, i.e. all of it but its last
// letter and at least 4 letters (`shininess` → `shine`). Empty when nothing is close.
std::string closest_word(std::string_view word, std::string_view candidates);

// " (did you mean 'X'?)" or "".
std::string did_you_mean(std::string_view word, std::string_view candidates);

}  // namespace whitted

#include "parse/suggest.h"

#include <algorithm>
#include <vector>

namespace whitted {

int edit_distance(std::string_view a, std::string_view b) {
    std::vector<int> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = int(j);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        int diagonal = row[0];
        row[0] = int(i);
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const int substitute = diagonal + (a[i - 1] != b[j - 1]);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
        }
    }
    return row[b.size()];
}

std::string closest_word(std::string_view word, std::string_view candidates) {
    if (word.size() > 64) return {};  // not a keyword anyone meant; keeps the work bounded
    std::string best;
    int best_distance = 1 << 30;
    std::size_t start = 0;
    while (start < candidates.size()) {
        std::size_t end = candidates.find(',', start);
        if (end == std::string_view::npos) end = candidates.size();
        std::string_view c = candidates.substr(start, end - start);
        while (!c.empty() && c.front() == ' ') c.remove_prefix(1);
        start = end + 1;
        if (c.empty() || c == word) continue;
        const int d = edit_distance(word, c);
        const int limit = std::min(word.size(), c.size()) <= 4 ? 1 : 2;
        const std::string_view stem = c.substr(0, c.size() - 1);
        const bool extends_stem = stem.size() >= 4 && word.size() > c.size() && word.substr(0, stem.size()) == stem;
        if ((d <= limit || extends_stem) && d < best_distance) {
            best = std::string(c);
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(std::string_view word, std::string_view candidates) {
    const std::string c = closest_word(word, candidates);
    return c.empty() ? std::string() : " (did you mean '" + c + "'?)";
}

}  // namespace whitted

#pragma once
// Splits scene text into tokens: words, `[`, `]`, with 1-based line/column (scene-format.md §1).
#include <string_view>
#include <vector>

namespace whitted {

enum class TokenKind { Word, Open, Close, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  // points into the scanned text
    int line = 0, col = 0;  // 1-based; col counts bytes (a tab is one column)
};

// Never fails: any byte that is not whitespace or a bracket belongs to a word. `#` at the start of
// a token comments out the rest of the line. A leading UTF-8 BOM is ignored. The result always ends
// with one End token, placed just past the last real token (1:1 when there is none).
std::vector<Token> tokenize(std::string_view text);

}  // namespace whitted

#include "parse/lexer.h"

namespace whitted {
namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

}  // namespace

std::vector<Token> tokenize(std::string_view text) {
    std::vector<Token> tokens;
    size_t i = 0;
    int line = 1, col = 1;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // BOM: editors add it, it is not a token

    // Advances over one byte, keeping line/col right for LF, CRLF and lone-CR line ends.
    auto advance = [&] {
        const char c = text[i++];
        if (c == '\n' || (c == '\r' && (i >= text.size() || text[i] != '\n'))) {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    };

    int end_line = 1, end_col = 1;
    while (i < text.size()) {
        const char c = text[i];
        if (is_space(c)) {
            advance();
            continue;
        }
        if (c == '#') {  // comment to end of line (the line break itself is whitespace)
            while (i < text.size() && text[i] != '\n' && text[i] != '\r') advance();
            continue;
        }
        Token t;
        t.line = line;
        t.col = col;
        const size_t start = i;
        if (c == '[' || c == ']') {
            t.kind = c == '[' ? TokenKind::Open : TokenKind::Close;
            advance();
        } else {
            t.kind = TokenKind::Word;
            while (i < text.size() && !is_space(text[i]) && text[i] != '[' && text[i] != ']')
                advance();
        }
        t.text = text.substr(start, i - start);
        end_line = line;  // a word never spans lines, so this is just past it
        end_col = col;
        tokens.push_back(t);
    }
    Token end;
    end.kind = TokenKind::End;
    end.line = end_line;
    end.col = end_col;
    tokens.push_back(end);
    return tokens;
}

}  // namespace whitted

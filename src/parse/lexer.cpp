#include "parse/lexer.h"

namespace whitted {

std::vector<Token> tokenize(std::string_view text) {
    std::vector<Token> tokens;
    Lexer lexer(text);
    do tokens.push_back(lexer.next());
    while (tokens.back().kind != TokenKind::End);
    return tokens;
}

}  // namespace whitted

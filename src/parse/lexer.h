#pragma once
// Splits scene text into tokens: words, `[`, `]`, with 1-based line/column (scene-format.md §1).
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "parse/number.h"

namespace whitted {

enum class TokenKind { Word, Open, Close, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  // points into the scanned text
    int line = 0, col = 0;  // 1-based; col counts bytes (a tab is one column)
};

namespace lexer_detail {

// What a byte is to the lexer. A word goes on over the first two.
enum ByteClass : unsigned char { kWordByte, kHash, kSpace, kLineFeed, kReturn, kOpen, kClose };

constexpr std::array<ByteClass, 256> make_classes() {
    std::array<ByteClass, 256> c{};
    for (const unsigned char s : {' ', '\t', '\v', '\f'}) c[s] = kSpace;
    c['\n'] = kLineFeed;
    c['\r'] = kReturn;
    c['['] = kOpen;
    c[']'] = kClose;
    c['#'] = kHash;
    return c;
}
inline constexpr std::array<ByteClass, 256> kClass = make_classes();

inline ByteClass byte_class(char c) { return kClass[static_cast<unsigned char>(c)]; }

static_assert(std::endian::native == std::endian::little, "the lexer reads the first of 8 bytes as the lowest");

// Bit 7 of each byte of `w` that might end a word: every byte below 0x21 (white space among
// them) and every byte that is '[' or ']' once bits 1-2 are cleared (also 'Y' and '_'). All
// that is certain is that no byte below the lowest flagged one ends a word.
inline std::uint64_t may_end_word(std::uint64_t w) {
    constexpr std::uint64_t ones = 0x0101010101010101u, highs = 0x8080808080808080u;
    const std::uint64_t below_0x21 = (w - ones * 0x21) & ~w & highs;
    const std::uint64_t bracket = (w & ~(ones * 0x06)) ^ (ones * 0x59);  // '[' 0x5B, ']' 0x5D → 0
    return below_0x21 | ((bracket - ones) & ~bracket & highs);
}

}  // namespace lexer_detail

// One token at a time, so that a file's tokens are never all in memory at once. Never fails: any
// byte that is not whitespace or a bracket belongs to a word. `#` at the start of a token comments
// out the rest of the line. A leading UTF-8 BOM is ignored. After the last real token comes End,
// placed just past it (1:1 when there is none), again on every later call.
class Lexer {
public:
    explicit Lexer(std::string_view text) : text_(text) {
        if (text.substr(0, 3) == "\xEF\xBB\xBF") i_ = line_start_ = 3;  // BOM: editors add it, it is not a token
    }
    inline Token next();
    // When the next token is a plain number, [-]digits[.digits] with at most 15 digits (nearly
    // every number of a file), reads it into `value`, as parse_number would, and returns true;
    // otherwise reads nothing but the white space before it. A shortcut past Token and
    // parse_number for the parser.
    inline bool read_plain_number(float& value);
    // How many bytes of the text have been read.
    std::size_t offset() const { return i_; }

private:
    // Up to the next token or the end (white space and comments).
    inline void skip_space();
    // The token has ended at i: i_ and the end position follow it.
    void end_token(std::size_t i) {
        i_ = i;
        end_line_ = line_;  // a token never spans lines, so this is just past it
        end_col_ = static_cast<int>(i - line_start_ + 1);
    }

    std::string_view text_;
    std::size_t i_ = 0;
    std::size_t line_start_ = 0;  // offset of the current line's first byte (column 1)
    int line_ = 1;
    int end_line_ = 1, end_col_ = 1;  // just past the last token
};

// Every token of the text, End last (for tests and tools; the parser uses Lexer).
std::vector<Token> tokenize(std::string_view text);

inline void Lexer::skip_space() {
    using namespace lexer_detail;
    const char* const s = text_.data();
    const std::size_t n = text_.size();
    std::size_t i = i_;
    while (i < n) {
        if (s[i] == ' ') {  // most of it
            ++i;
            continue;
        }
        const ByteClass c = byte_class(s[i]);
        if (c == kSpace) {
            ++i;
        } else if (c == kLineFeed || (c == kReturn && (i + 1 >= n || s[i + 1] != '\n'))) {
            // Line ends: LF, CRLF and a lone CR each end one line.
            line_start_ = ++i;
            ++line_;
        } else if (c == kReturn) {  // of a CRLF: the LF ends the line
            ++i;
        } else if (c == kHash) {  // a comment to the end of the line (the line end itself is white space)
            while (i < n && s[i] != '\n' && s[i] != '\r') ++i;
        } else {
            break;
        }
    }
    i_ = i;
}

inline Token Lexer::next() {
    using namespace lexer_detail;
    skip_space();
    const char* const s = text_.data();
    const std::size_t n = text_.size();
    std::size_t i = i_;
    Token t;
    if (i == n) {
        t.kind = TokenKind::End;
        t.line = end_line_;
        t.col = end_col_;
        return t;
    }
    t.line = line_;
    t.col = static_cast<int>(i - line_start_ + 1);
    const ByteClass c = byte_class(s[i]);
    const std::size_t start = i++;
    if (c == kOpen || c == kClose) {
        t.kind = c == kOpen ? TokenKind::Open : TokenKind::Close;
    } else {
        t.kind = TokenKind::Word;
        // Eight bytes at a time up to the first that might end the word, then one by one.
        while (i + 8 <= n) {
            std::uint64_t w;
            std::memcpy(&w, s + i, 8);
            if (const std::uint64_t m = may_end_word(w)) {
                i += static_cast<std::size_t>(std::countr_zero(m)) / 8;
                break;
            }
            i += 8;
        }
        while (i < n && byte_class(s[i]) <= kHash) ++i;
    }
    t.text = std::string_view(s + start, i - start);
    end_token(i);
    return t;
}

inline bool Lexer::read_plain_number(float& value) {
    skip_space();
    const char* const s = text_.data();
    const char* const end = s + text_.size();
    const PlainNumber plain = scan_plain_number(s + i_, end);
    // The word must end there for this to be the whole token ("1.5x", "2," and "1e3" are not plain).
    if (!plain.ok || (plain.end != end && lexer_detail::byte_class(*plain.end) <= lexer_detail::kHash)) return false;
    value = plain.value;
    end_token(static_cast<std::size_t>(plain.end - s));
    return true;
}

}  // namespace whitted

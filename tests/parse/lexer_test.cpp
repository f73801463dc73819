#include "parse/lexer.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace whitted {
namespace {

TEST(ParseLexer, EmptyTextHasOnlyEnd) {
    const auto t = tokenize("");
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].kind, TokenKind::End);
}

TEST(ParseLexer, BracketsAreTokensEvenWhenGlued) {
    const auto t = tokenize("[color a]b");
    ASSERT_EQ(t.size(), 6u);
    EXPECT_EQ(t[0].kind, TokenKind::Open);
    EXPECT_EQ(t[0].col, 1);
    EXPECT_EQ(t[1].text, "color");
    EXPECT_EQ(t[1].col, 2);
    EXPECT_EQ(t[2].text, "a");
    EXPECT_EQ(t[2].col, 8);
    EXPECT_EQ(t[3].kind, TokenKind::Close);
    EXPECT_EQ(t[3].col, 9);
    EXPECT_EQ(t[4].text, "b");
    EXPECT_EQ(t[4].col, 10);
}

TEST(ParseLexer, LinesAndColumnsWithCrlfAndTabs) {
    const auto t = tokenize("a\r\n\tb  c\n\n  d");
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t[1].text, "b");
    EXPECT_EQ(t[1].line, 2);
    EXPECT_EQ(t[1].col, 2);  // a tab is one column
    EXPECT_EQ(t[2].line, 2);
    EXPECT_EQ(t[2].col, 5);
    EXPECT_EQ(t[3].line, 4);
    EXPECT_EQ(t[3].col, 3);
}

TEST(ParseLexer, LoneCarriageReturnEndsALine) {
    const auto t = tokenize("a\rb");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[1].line, 2);
    EXPECT_EQ(t[1].col, 1);
}

TEST(ParseLexer, HashStartsACommentOnlyAtTokenStart) {
    const auto t = tokenize("a # b c ]\nx#y [#z\nw");
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t[0].text, "a");
    EXPECT_EQ(t[1].text, "x#y");
    EXPECT_EQ(t[1].line, 2);
    EXPECT_EQ(t[2].kind, TokenKind::Open);
    EXPECT_EQ(t[3].text, "w");
    EXPECT_EQ(t[3].line, 3);
}

TEST(ParseLexer, EndIsJustPastTheLastToken) {
    const auto t = tokenize("ab\n cde  \n\n# trailing comment\n");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[2].kind, TokenKind::End);
    EXPECT_EQ(t[2].line, 2);
    EXPECT_EQ(t[2].col, 5);
}

TEST(ParseLexer, Utf8BomIsIgnored) {
    const auto t = tokenize(
        "\xEF\xBB\xBF"
        "camera");
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].text, "camera");
    EXPECT_EQ(t[0].col, 1);
}

TEST(ParseLexer, VerticalTabAndFormFeedAreSpaceButNotLineEnds) {
    const auto t = tokenize("a\v\fb\nc");
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[1].text, "b");
    EXPECT_EQ(t[1].line, 1);
    EXPECT_EQ(t[1].col, 4);
    EXPECT_EQ(t[2].line, 2);
}

TEST(ParseLexer, MixedLineEndsEachCountOnce) {
    // CR, then CRLF, then LF, then LF CR (two ends: LF, then a lone CR).
    const auto t = tokenize("a\rb\r\nc\nd\n\re");
    ASSERT_EQ(t.size(), 6u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(t[i].line, i + 1) << i;
        EXPECT_EQ(t[i].col, 1) << i;
    }
    EXPECT_EQ(t[4].line, 6);
}

TEST(ParseLexer, ACommentEndsAtALoneCarriageReturn) {
    const auto t = tokenize("# a [ ]\r  b # c\r\n]");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].text, "b");
    EXPECT_EQ(t[0].line, 2);
    EXPECT_EQ(t[0].col, 3);
    EXPECT_EQ(t[1].kind, TokenKind::Close);
    EXPECT_EQ(t[1].line, 3);
    EXPECT_EQ(t[2].line, 3);  // End just past the ']'
    EXPECT_EQ(t[2].col, 2);
}

TEST(ParseLexer, ABomLaterInTheTextIsPartOfAWord) {
    const auto t = tokenize("\xEF\xBB\xBF\xEF\xBB\xBF" "a b");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].text, "\xEF\xBB\xBF" "a");
    EXPECT_EQ(t[0].col, 1);
    EXPECT_EQ(t[1].col, 6);  // columns count from the end of the first BOM
}

TEST(ParseLexer, WordsEndAtBracketsAndHashesDoNot) {
    const auto t = tokenize("]a#b[#c\n1]");
    ASSERT_EQ(t.size(), 6u);
    EXPECT_EQ(t[0].kind, TokenKind::Close);
    EXPECT_EQ(t[1].text, "a#b");
    EXPECT_EQ(t[2].kind, TokenKind::Open);
    EXPECT_EQ(t[3].text, "1");
    EXPECT_EQ(t[3].line, 2);
    EXPECT_EQ(t[4].kind, TokenKind::Close);
    EXPECT_EQ(t[4].col, 2);
    EXPECT_EQ(t[5].kind, TokenKind::End);
    EXPECT_EQ(t[5].col, 3);
}

// The rules of §1 one byte at a time, as plainly as they can be written: the reference for the
// lexer, which reads words eight bytes at a time.
std::vector<Token> reference_tokens(std::string_view text) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    int line = 1, col = 1, end_line = 1, end_col = 1;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; };
    auto step = [&] {
        const char c = text[i++];
        if (c == '\n' || (c == '\r' && (i >= text.size() || text[i] != '\n'))) ++line, col = 1;
        else ++col;
    };
    while (i < text.size()) {
        const char c = text[i];
        if (space(c)) {
            step();
        } else if (c == '#') {
            while (i < text.size() && text[i] != '\n' && text[i] != '\r') step();
        } else {
            Token t;
            t.line = line;
            t.col = col;
            const std::size_t start = i;
            if (c == '[' || c == ']') {
                t.kind = c == '[' ? TokenKind::Open : TokenKind::Close;
                step();
            } else {
                t.kind = TokenKind::Word;
                while (i < text.size() && !space(text[i]) && text[i] != '[' && text[i] != ']') step();
            }
            t.text = text.substr(start, i - start);
            end_line = line;
            end_col = col;
            tokens.push_back(t);
        }
    }
    Token end;
    end.line = end_line;
    end.col = end_col;
    tokens.push_back(end);
    return tokens;
}

TEST(ParseLexer, AgreesWithTheRulesByteByByteOnRandomText) {
    // Bytes near the ones the word scan looks for ('Y' and '_' share their bits with the
    // brackets; control bytes lie below the space), in runs long and short.
    static const char kAlphabet[] = "  \t\n\r\v\f[]#YZ_^\\\0\x01\x1f!\x7f\x80\xa0\xff" "a1.-,e";
    const std::string alphabet(kAlphabet, sizeof kAlphabet - 1);  // the NUL inside kept, the last one not
    std::mt19937 rng(3);
    for (int round = 0; round < 3000; ++round) {
        std::string text;
        const int pieces = int(rng() % 40);
        for (int p = 0; p < pieces; ++p) {
            const std::size_t run = rng() % 4 == 0 ? rng() % 40 : 1 + rng() % 3;
            const char c = alphabet[rng() % alphabet.size()];
            for (std::size_t k = 0; k < run; ++k) text += rng() % 3 ? c : alphabet[rng() % alphabet.size()];
        }
        if (round % 7 == 0) text = "\xEF\xBB\xBF" + text;
        const auto got = tokenize(text), want = reference_tokens(text);
        ASSERT_EQ(got.size(), want.size()) << "round " << round;
        for (std::size_t k = 0; k < got.size(); ++k) {
            EXPECT_EQ(got[k].kind, want[k].kind) << round << ":" << k;
            EXPECT_EQ(got[k].text, want[k].text) << round << ":" << k;
            EXPECT_EQ(got[k].text.data(), want[k].text.data()) << round << ":" << k;
            EXPECT_EQ(got[k].line, want[k].line) << round << ":" << k;
            EXPECT_EQ(got[k].col, want[k].col) << round << ":" << k;
        }
    }
}

TEST(ParseLexer, ArbitraryBytesBelongToWords) {
    const std::string text("a\0b\x80\xff", 5);
    const auto t = tokenize(text);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].text.size(), 5u);
}

}  // namespace
}  // namespace whitted

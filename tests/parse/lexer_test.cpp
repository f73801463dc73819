#include "parse/lexer.h"

#include <gtest/gtest.h>

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

TEST(ParseLexer, ArbitraryBytesBelongToWords) {
    const std::string text("a\0b\x80\xff", 5);
    const auto t = tokenize(text);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].text.size(), 5u);
}

}  // namespace
}  // namespace whitted

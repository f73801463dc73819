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

TEST(ParseLexer, ArbitraryBytesBelongToWords) {
    const std::string text("a\0b\x80\xff", 5);
    const auto t = tokenize(text);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].text.size(), 5u);
}

}  // namespace
}  // namespace whitted

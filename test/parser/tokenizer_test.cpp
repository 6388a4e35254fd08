// Tokenizer and number parsing.

#include "core/parser/tokenizer.h"

#include <gtest/gtest.h>

#include "core/parser/diagnostics.h"

namespace kiln {

namespace {

std::vector<Token> All(Tokenizer& t) {
    std::vector<Token> v;
    while (std::optional<Token> tok = t.Next()) v.push_back(*tok);
    return v;
}

}  // namespace

TEST(Tokenizer, KindsPositionsAndComments) {
    Tokenizer t("Shape \"sphere\"# c\n\t\"float r\"[1.5]# x\r\n  -2e3", "f.pbrt");
    std::vector<Token> v = All(t);
    ASSERT_EQ(v.size(), 7u);
    EXPECT_TRUE(v[0].IsWord("Shape"));
    EXPECT_EQ(v[1].kind, TokenKind::String);
    EXPECT_EQ(v[1].text, "sphere");
    EXPECT_EQ(v[1].raw, "\"sphere\"");
    EXPECT_EQ(v[1].column, 7);
    EXPECT_EQ(v[2].text, "float r");
    EXPECT_EQ(v[2].line, 2);
    EXPECT_EQ(v[2].column, 2);
    EXPECT_EQ(v[3].kind, TokenKind::OpenBracket);
    EXPECT_TRUE(v[4].IsWord("1.5"));
    EXPECT_EQ(v[5].kind, TokenKind::CloseBracket);
    EXPECT_TRUE(v[6].IsWord("-2e3"));
    EXPECT_EQ(v[6].line, 3);
    EXPECT_EQ(v[6].column, 3);
    EXPECT_EQ(t.Loc(v[6]).ToString(), "f.pbrt:3:3");
    EXPECT_EQ(t.EndLoc().ToString(), "f.pbrt:3:7");
}

TEST(Tokenizer, EscapesAndByteOrderMark) {
    Tokenizer t("\xef\xbb\xbf\"a\\tb\\\\c\\\"d\\'e\\n\" x", "f");
    std::vector<Token> v = All(t);
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(v[0].text, "a\tb\\c\"d'e\n");
    EXPECT_EQ(v[0].column, 1);
}

TEST(Tokenizer, Errors) {
    auto error = [](std::string text) -> std::string {
        try {
            Tokenizer t(std::move(text), "f");
            All(t);
        } catch (const SceneError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_EQ(error("\xff\xfeS\0"),
              "f:1:1: error: file is encoded as UTF-16; scene files must "
              "be ASCII or UTF-8");
    EXPECT_EQ(error("x \"abc"), "f:1:3: error: unterminated string (at '\"abc')");
    EXPECT_EQ(error("x\n \"ab\\x\""), "f:2:5: error: unknown escape sequence in string (at '\\x')");
}

TEST(Numbers, ParseFloat) {
    Float f = 0;
    for (auto [s, v] : {std::pair<const char*, Float>{"1", 1},
                        {"-2.5", -2.5f},
                        {"+3", 3},
                        {".5", 0.5f},
                        {"-.25", -0.25f},
                        {"1.", 1},
                        {"1e3", 1000},
                        {"2.5E-1", 0.25f},
                        {"1e-50", 0}}) {
        EXPECT_TRUE(ParseFloat(s, &f)) << s;
        EXPECT_EQ(f, v) << s;
    }
    for (const char* s : {"", "-", "+-1", "nan", "inf", "-inf", "0x10", "1,2", "1e", "e5", "1.2.3",
                          "1e999", "true", "--1"})
        EXPECT_FALSE(ParseFloat(s, &f)) << s;
}

TEST(Numbers, ParseInt) {
    int n = 0;
    EXPECT_TRUE(ParseInt("42", &n));
    EXPECT_EQ(n, 42);
    EXPECT_TRUE(ParseInt("+7", &n));
    EXPECT_EQ(n, 7);
    EXPECT_TRUE(ParseInt("-2147483648", &n));
    EXPECT_EQ(n, -2147483648);
    for (const char* s : {"", "1.0", "2147483648", "1e3", "x", "+-3"})
        EXPECT_FALSE(ParseInt(s, &n)) << s;
}

}  // namespace kiln

#include "engine/vrml/vrml_tokenizer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pw::engine::vrml {
namespace {

TEST(VrmlTokenizer, SeparatesTokensAndSkipsCommasAndComments) {
  Tokenizer t("Shape { # a comment\n  size 1, 2.5,-3e2 ] [ . }", SourcePos{});
  std::vector<TokenKind> kinds;
  std::vector<std::string> texts;
  while (t.peek().kind != TokenKind::kEnd) {
    Token k = t.next();
    kinds.push_back(k.kind);
    texts.emplace_back(k.text);
  }
  EXPECT_EQ(texts, (std::vector<std::string>{"Shape", "{", "size", "1", "2.5", "-3e2", "]", "[", ".", "}"}));
  EXPECT_EQ(kinds[3], TokenKind::kInteger);
  EXPECT_EQ(kinds[4], TokenKind::kFloat);
  EXPECT_EQ(kinds[5], TokenKind::kFloat);
}

TEST(VrmlTokenizer, TracksLineAndColumn) {
  Tokenizer t("a\n  b\r\n\tc \"x\ny\" d", SourcePos{});
  Token a = t.next(), b = t.next(), c = t.next(), s = t.next(), d = t.next();
  EXPECT_EQ(a.pos.line, 1u);
  EXPECT_EQ(b.pos.line, 2u);
  EXPECT_EQ(b.pos.column, 3u);
  EXPECT_EQ(c.pos.line, 3u);
  EXPECT_EQ(c.pos.column, 2u);
  EXPECT_EQ(s.pos.line, 3u);
  EXPECT_EQ(d.pos.line, 4u);  // the string spans a line
  EXPECT_EQ(d.pos.column, 4u);
}

TEST(VrmlTokenizer, NumbersInAllForms) {
  Tokenizer t("0x1F -0xff +.5 1. 7 -0 1E3 2147483648", SourcePos{});
  Token hex = t.next();
  EXPECT_EQ(hex.kind, TokenKind::kInteger);
  EXPECT_EQ(hex.integer, 31);
  EXPECT_EQ(t.next().integer, -255);
  Token half = t.next();
  EXPECT_DOUBLE_EQ(half.number, 0.5);
  EXPECT_DOUBLE_EQ(t.next().number, 1.0);
  EXPECT_EQ(t.next().integer, 7);
  Token negZero = t.next();
  EXPECT_TRUE(std::signbit(negZero.number));
  EXPECT_DOUBLE_EQ(t.next().number, 1000.0);
  EXPECT_EQ(t.next().integer, 2147483648LL);
}

TEST(VrmlTokenizer, StringEscapes) {
  Tokenizer t(R"("say \"hi\" \\ there")", SourcePos{});
  Token s = t.next();
  ASSERT_EQ(s.kind, TokenKind::kString);
  EXPECT_EQ(unescape(s), "say \"hi\" \\ there");
}

TEST(VrmlTokenizer, UnterminatedStringIsAnErrorAtItsStart) {
  Tokenizer t("a\n  \"never closed\n\n", SourcePos{});
  t.next();
  Token bad = t.next();
  EXPECT_EQ(bad.kind, TokenKind::kInvalid);
  EXPECT_EQ(bad.pos.line, 2u);
  EXPECT_EQ(bad.pos.column, 3u);
  EXPECT_NE(std::string(bad.text).find("unterminated string"), std::string::npos);
  EXPECT_EQ(t.next().kind, TokenKind::kInvalid);  // the error is sticky
}

TEST(VrmlTokenizer, MalformedNumbersAndStrayCharactersAreErrors) {
  EXPECT_EQ(Tokenizer("12abc", SourcePos{}).peek().kind, TokenKind::kInvalid);
  EXPECT_EQ(Tokenizer("1.2.3", SourcePos{}).peek().kind, TokenKind::kInvalid);
  EXPECT_EQ(Tokenizer("1e999", SourcePos{}).peek().kind, TokenKind::kInvalid);
  EXPECT_EQ(Tokenizer(std::string_view("\x01", 1), SourcePos{}).peek().kind, TokenKind::kInvalid);
}

TEST(VrmlTokenizer, IdentifiersMayHoldPunctuationOtherThanSeparators) {
  Tokenizer t("OB_Cube-001 a:b+c x.y", SourcePos{});
  EXPECT_EQ(t.next().text, "OB_Cube-001");
  EXPECT_EQ(t.next().text, "a:b+c");
  EXPECT_EQ(t.next().text, "x");
  EXPECT_EQ(t.next().kind, TokenKind::kPeriod);
  EXPECT_EQ(t.next().text, "y");
}

}  // namespace
}  // namespace pw::engine::vrml

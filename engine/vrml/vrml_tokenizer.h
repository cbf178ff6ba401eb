// The VRML97 classic-encoding lexer (ISO/IEC 14772-1, 5.1 and Annex A.2).
//
// Tokens are scanned on demand so that a 500 MB coordinate array never exists as a
// token list. Commas and whitespace separate tokens; '#' starts a comment that runs
// to the end of the line; strings are double-quoted with \" and \\ escapes and may
// span lines. Line and column (1-based, column counted in bytes) travel with each
// token for error messages.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace pw::engine::vrml {

struct SourcePos {
  uint32_t line = 1;
  uint32_t column = 1;
};

enum class TokenKind : uint8_t {
  kEnd,           // end of input
  kIdentifier,    // node type, field name, DEF name, keyword (DEF USE PROTO IS TRUE NULL ...)
  kInteger,       // decimal or 0x hexadecimal; also usable where a float is wanted
  kFloat,         // has a '.' or an exponent
  kString,        // contents without quotes; escapes still in place (see unescape)
  kOpenBrace,     // {
  kCloseBrace,    // }
  kOpenBracket,   // [
  kCloseBracket,  // ]
  kPeriod,        // . (ROUTE Node.field)
  kInvalid,       // a lexical error; `text` holds the message
};

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string_view text;
  SourcePos pos;
  double number = 0;       // kInteger, kFloat
  int64_t integer = 0;     // kInteger (hexadecimal values up to 0xFFFFFFFF included)
  bool hasEscapes = false;  // kString: text contains backslashes to remove
  bool hexadecimal = false;  // kInteger written as 0x...
};

// Describes a token for "expected X, found Y" messages: "'}'", "end of file",
// "the number 3.5", "the identifier Shape".
std::string describe(const Token& token);

// The string token's text with its escapes resolved.
std::string unescape(const Token& token);

class Tokenizer {
 public:
  // `text` must outlive the tokenizer; `start` is the position of text[0] (after a header line).
  Tokenizer(std::string_view text, SourcePos start);

  const Token& peek() { return lookahead_[0]; }
  // The token after peek(), scanned on demand.
  const Token& peekSecond();
  Token next();

 private:
  Token scan();
  Token invalid(SourcePos pos, std::string message);
  void skipSpaceAndComments();
  Token scanNumber(SourcePos pos, size_t begin);
  Token scanString(SourcePos pos);
  void advance(size_t n);

  std::string_view text_;
  size_t offset_ = 0;
  SourcePos pos_;
  Token lookahead_[2];
  int buffered_ = 0;  // tokens in lookahead_ (1 or 2 once constructed)
  // The first lexical error. It is sticky: every token after it is the same kInvalid
  // token, whose text views this string (which therefore never changes once set).
  std::string error_;
};

// Characters of identifiers (Annex A.2): anything printable except the separators
// and the characters that start numbers (for the first character).
bool isIdFirstChar(unsigned char c);
bool isIdRestChar(unsigned char c);

}  // namespace pw::engine::vrml

#include "engine/vrml/vrml_tokenizer.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace pw::engine::vrml {

bool isIdRestChar(unsigned char c) {
  if (c <= 0x20 || c == 0x7f) return false;
  switch (c) {
    case '"': case '#': case '\'': case ',': case '.': case '[': case '\\': case ']': case '{': case '}':
      return false;
    default:
      return true;
  }
}

bool isIdFirstChar(unsigned char c) {
  return isIdRestChar(c) && c != '+' && c != '-' && !(c >= '0' && c <= '9');
}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isHexDigit(char c) { return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

std::string clip(std::string_view text) {
  constexpr size_t kMax = 40;
  std::string out(text.substr(0, kMax));
  if (text.size() > kMax) out += "...";
  return out;
}

}  // namespace

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::kEnd: return "end of file";
    case TokenKind::kIdentifier: return "'" + clip(token.text) + "'";
    case TokenKind::kInteger:
    case TokenKind::kFloat: return "the number " + clip(token.text);
    case TokenKind::kString: return "the string \"" + clip(token.text) + "\"";
    case TokenKind::kOpenBrace: return "'{'";
    case TokenKind::kCloseBrace: return "'}'";
    case TokenKind::kOpenBracket: return "'['";
    case TokenKind::kCloseBracket: return "']'";
    case TokenKind::kPeriod: return "'.'";
    case TokenKind::kInvalid: return std::string(token.text);
  }
  return "?";
}

std::string unescape(const Token& token) {
  if (!token.hasEscapes) return std::string(token.text);
  std::string out;
  out.reserve(token.text.size());
  for (size_t i = 0; i < token.text.size(); ++i) {
    // 5.1.5 / SFString: a backslash quotes the next character (only \" and \\ are meaningful).
    if (token.text[i] == '\\' && i + 1 < token.text.size()) ++i;
    out += token.text[i];
  }
  return out;
}

Tokenizer::Tokenizer(std::string_view text, SourcePos start) : text_(text), pos_(start) {
  lookahead_[0] = scan();
  buffered_ = 1;
}

const Token& Tokenizer::peekSecond() {
  if (buffered_ < 2) {
    lookahead_[1] = lookahead_[0].kind == TokenKind::kInvalid ? lookahead_[0] : scan();
    buffered_ = 2;
  }
  return lookahead_[1];
}

Token Tokenizer::next() {
  const Token current = lookahead_[0];
  if (current.kind == TokenKind::kInvalid) return current;  // stay on the error
  if (buffered_ == 2) {
    lookahead_[0] = lookahead_[1];
    buffered_ = 1;
  } else {
    lookahead_[0] = scan();
  }
  return current;
}

Token Tokenizer::invalid(SourcePos pos, std::string message) {
  Token t;
  t.kind = TokenKind::kInvalid;
  t.pos = pos;
  if (error_.empty()) error_ = std::move(message);
  t.text = error_;
  return t;
}

void Tokenizer::advance(size_t n) {
  for (size_t i = 0; i < n && offset_ < text_.size(); ++i) {
    const char c = text_[offset_++];
    if (c == '\n' || (c == '\r' && (offset_ >= text_.size() || text_[offset_] != '\n'))) {
      ++pos_.line;
      pos_.column = 1;
    } else if (c != '\r') {
      ++pos_.column;
    }
  }
}

void Tokenizer::skipSpaceAndComments() {
  while (offset_ < text_.size()) {
    const char c = text_[offset_];
    if (c == ' ' || c == '\t' || c == ',' || c == '\n' || c == '\r') {
      advance(1);
    } else if (c == '#') {
      size_t end = offset_;
      while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
      pos_.column += static_cast<uint32_t>(end - offset_);
      offset_ = end;
    } else {
      break;
    }
  }
}

Token Tokenizer::scan() {
  if (!error_.empty()) return invalid(pos_, {});
  skipSpaceAndComments();
  Token t;
  t.pos = pos_;
  if (offset_ >= text_.size()) return t;
  const size_t begin = offset_;
  const char c = text_[offset_];
  switch (c) {
    case '{': t.kind = TokenKind::kOpenBrace; break;
    case '}': t.kind = TokenKind::kCloseBrace; break;
    case '[': t.kind = TokenKind::kOpenBracket; break;
    case ']': t.kind = TokenKind::kCloseBracket; break;
    case '"': return scanString(t.pos);
    default: break;
  }
  if (t.kind != TokenKind::kEnd) {
    t.text = text_.substr(begin, 1);
    advance(1);
    return t;
  }
  const bool startsNumber = isDigit(c) || ((c == '+' || c == '-' || c == '.') && begin + 1 < text_.size() &&
                                           (isDigit(text_[begin + 1]) ||
                                            (c != '.' && text_[begin + 1] == '.' && begin + 2 < text_.size() &&
                                             isDigit(text_[begin + 2]))));
  if (startsNumber) return scanNumber(t.pos, begin);
  if (c == '.') {
    t.kind = TokenKind::kPeriod;
    t.text = text_.substr(begin, 1);
    advance(1);
    return t;
  }
  if (isIdFirstChar(static_cast<unsigned char>(c))) {
    size_t end = begin + 1;
    while (end < text_.size() && isIdRestChar(static_cast<unsigned char>(text_[end]))) ++end;
    t.kind = TokenKind::kIdentifier;
    t.text = text_.substr(begin, end - begin);
    pos_.column += static_cast<uint32_t>(end - begin);
    offset_ = end;
    return t;
  }
  static const char* const kHex = "0123456789abcdef";
  const unsigned char u = static_cast<unsigned char>(c);
  return invalid(t.pos, std::string("an unexpected character 0x") + kHex[u >> 4] + kHex[u & 15]);
}

Token Tokenizer::scanNumber(SourcePos pos, size_t begin) {
  Token t;
  t.pos = pos;
  size_t i = begin;
  const bool negative = text_[i] == '-';
  if (text_[i] == '+' || text_[i] == '-') ++i;
  bool isFloat = false;
  bool hex = false;
  // Decimal digits are accumulated while scanning, so that integers (most of a big
  // file: coordIndex) need no second pass.
  uint64_t digits = 0;
  bool digitsOverflow = false;
  if (text_[i] == '0' && i + 1 < text_.size() && (text_[i + 1] == 'x' || text_[i + 1] == 'X') &&
      i + 2 < text_.size() && isHexDigit(text_[i + 2])) {
    hex = true;
    i += 2;
    while (i < text_.size() && isHexDigit(text_[i])) ++i;
  } else {
    while (i < text_.size() && isDigit(text_[i])) {
      if (digits > (UINT64_MAX - 9) / 10) digitsOverflow = true;
      digits = digits * 10 + static_cast<uint64_t>(text_[i] - '0');
      ++i;
    }
    if (i < text_.size() && text_[i] == '.') {
      isFloat = true;
      ++i;
      while (i < text_.size() && isDigit(text_[i])) ++i;
    }
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      size_t j = i + 1;
      if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) ++j;
      if (j < text_.size() && isDigit(text_[j])) {
        isFloat = true;
        i = j;
        while (i < text_.size() && isDigit(text_[i])) ++i;
      }
    }
  }
  // A number glued to identifier characters ("12abc", "1.5.3") is a typo, not two tokens.
  size_t end = i;
  while (end < text_.size() && (isIdRestChar(static_cast<unsigned char>(text_[end])) || text_[end] == '.')) ++end;
  const std::string_view all = text_.substr(begin, end - begin);
  pos_.column += static_cast<uint32_t>(end - begin);
  offset_ = end;
  if (end != i) return invalid(pos, "a malformed number '" + clip(all) + "'");
  t.text = all;
  const char* first = all.data() + ((all[0] == '+' || all[0] == '-') ? 1 : 0);
  const char* last = all.data() + all.size();
  if (hex) {
    uint64_t value = 0;
    auto r = std::from_chars(first + 2, last, value, 16);
    if (r.ec != std::errc() || value > 0xFFFFFFFFull) {
      return invalid(pos, "the hexadecimal number " + clip(all) + " does not fit in 32 bits");
    }
    t.kind = TokenKind::kInteger;
    t.hexadecimal = true;
    t.integer = negative ? -static_cast<int64_t>(value) : static_cast<int64_t>(value);
    t.number = static_cast<double>(t.integer);
    return t;
  }
  if (!isFloat && !digitsOverflow && digits <= static_cast<uint64_t>(INT64_MAX)) {
    t.kind = TokenKind::kInteger;
    t.integer = negative ? -static_cast<int64_t>(digits) : static_cast<int64_t>(digits);
    t.number = negative ? -static_cast<double>(digits) : static_cast<double>(digits);
    return t;
  }
  double value = 0;
  auto r = std::from_chars(first, last, value);
  if (r.ec != std::errc() || r.ptr != last || !std::isfinite(value)) {
    return invalid(pos, "the number " + clip(all) + " is out of range");
  }
  t.kind = TokenKind::kFloat;
  t.number = negative ? -value : value;
  return t;
}

Token Tokenizer::scanString(SourcePos pos) {
  Token t;
  t.pos = pos;
  const size_t begin = offset_;
  advance(1);  // opening quote
  size_t i = offset_;
  bool escapes = false;
  while (i < text_.size() && text_[i] != '"') {
    if (text_[i] == '\\') {
      escapes = true;
      ++i;
    }
    ++i;
  }
  if (i >= text_.size()) {
    advance(text_.size() - offset_);
    return invalid(pos, "an unterminated string (its opening '\"' is never closed)");
  }
  t.kind = TokenKind::kString;
  t.text = text_.substr(begin + 1, i - begin - 1);
  t.hasEscapes = escapes;
  advance(i + 1 - offset_);  // through the closing quote, counting lines inside the string
  return t;
}

}  // namespace pw::engine::vrml

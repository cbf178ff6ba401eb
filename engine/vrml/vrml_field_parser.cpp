#include "engine/vrml/vrml_field_parser.h"

#include <cfloat>
#include <cmath>
#include <limits>
#include <string>

namespace pw::engine::vrml {

Error errorAt(std::string_view fileName, SourcePos pos, std::string_view message) {
  return makeError(std::string(fileName) + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column) + ": " +
                   std::string(message));
}

namespace {

// The parsing state for one value, to keep the per-number loop small.
class ValueReader {
 public:
  ValueReader(Tokenizer& tokens, FieldType type, std::string_view fileName, std::string_view fieldName)
      : tokens_(tokens), type_(type), fileName_(fileName), fieldName_(fieldName) {}

  Status read(FieldValue& out);

 private:
  Status readOne(FieldValue& out);
  Status number(double& value, bool singlePrecision);
  Status integer(int32_t& value);
  Status boolean(int32_t& value);
  Status string(std::string& value);
  Status image(FieldValue& out);
  Error expected(const char* what, const Token& found) const;

  Tokenizer& tokens_;
  FieldType type_;
  std::string_view fileName_;
  std::string_view fieldName_;
};

Error ValueReader::expected(const char* what, const Token& found) const {
  if (found.kind == TokenKind::kInvalid) return errorAt(fileName_, found.pos, describe(found));
  return errorAt(fileName_, found.pos,
                 "field '" + std::string(fieldName_) + "' (" + fieldTypeName(type_) + ") expects " + what +
                     ", found " + describe(found));
}

Status ValueReader::number(double& value, bool singlePrecision) {
  const Token& t = tokens_.peek();
  if (t.kind != TokenKind::kInteger && t.kind != TokenKind::kFloat) return expected("a number", t);
  if (singlePrecision && std::fabs(t.number) > static_cast<double>(FLT_MAX)) {
    return errorAt(fileName_, t.pos, "the number " + std::string(t.text) + " in field '" + std::string(fieldName_) +
                                         "' is outside the single-precision range");
  }
  value = t.number;
  tokens_.next();
  return {};
}

Status ValueReader::integer(int32_t& value) {
  const Token& t = tokens_.peek();
  if (t.kind != TokenKind::kInteger) return expected("an integer", t);
  // Hexadecimal values up to 0xFFFFFFFF (SFImage pixels) wrap to the int32 they spell.
  const int64_t lo = std::numeric_limits<int32_t>::min();
  const int64_t hi = t.hexadecimal ? int64_t{0xFFFFFFFF} : std::numeric_limits<int32_t>::max();
  if (t.integer < lo || t.integer > hi) {
    return errorAt(fileName_, t.pos, "the integer " + std::string(t.text) + " in field '" + std::string(fieldName_) +
                                         "' does not fit in 32 bits");
  }
  value = static_cast<int32_t>(static_cast<uint32_t>(t.integer));
  tokens_.next();
  return {};
}

Status ValueReader::boolean(int32_t& value) {
  const Token& t = tokens_.peek();
  if (t.kind == TokenKind::kIdentifier && (t.text == "TRUE" || t.text == "FALSE")) {
    value = t.text == "TRUE" ? 1 : 0;
    tokens_.next();
    return {};
  }
  return expected("TRUE or FALSE", t);
}

Status ValueReader::string(std::string& value) {
  const Token& t = tokens_.peek();
  if (t.kind != TokenKind::kString) return expected("a quoted string", t);
  value = unescape(t);
  tokens_.next();
  return {};
}

// SFImage (5.5): width height components, then width*height pixel integers.
Status ValueReader::image(FieldValue& out) {
  int32_t header[3];
  const Token start = tokens_.peek();
  for (int32_t& h : header) PW_TRY(integer(h));
  if (header[0] < 0 || header[1] < 0 || header[2] < 0 || header[2] > 4) {
    return errorAt(fileName_, start.pos, "SFImage wants width height components (0..4), not " +
                                             std::to_string(header[0]) + " " + std::to_string(header[1]) + " " +
                                             std::to_string(header[2]));
  }
  const int64_t pixels = int64_t{header[0]} * header[1];
  if (pixels > (int64_t{1} << 26)) {
    return errorAt(fileName_, start.pos, "SFImage of " + std::to_string(header[0]) + "x" + std::to_string(header[1]) +
                                             " pixels is larger than the 64 megapixels photowalk accepts");
  }
  out.ints.assign(header, header + 3);
  for (int64_t i = 0; i < pixels; ++i) {
    int32_t p = 0;
    PW_TRY(integer(p));
    out.ints.push_back(p);
  }
  return {};
}

Status ValueReader::readOne(FieldValue& out) {
  switch (type_) {
    case FieldType::kSFBool: {
      int32_t v = 0;
      PW_TRY(boolean(v));
      out.ints.push_back(v);
      return {};
    }
    case FieldType::kSFInt32:
    case FieldType::kMFInt32: {
      int32_t v = 0;
      PW_TRY(integer(v));
      out.ints.push_back(v);
      return {};
    }
    case FieldType::kSFString:
    case FieldType::kMFString:
      out.strings.emplace_back();
      return string(out.strings.back());
    case FieldType::kSFImage:
      return image(out);
    case FieldType::kSFTime:
    case FieldType::kMFTime: {
      double v = 0;
      PW_TRY(number(v, false));
      out.doubles.push_back(v);
      return {};
    }
    default:
      break;
  }
  const int n = componentCount(type_);
  const bool multiple = isMultiple(type_);
  for (int i = 0; i < n; ++i) {
    double v = 0;
    if (Status s = number(v, true); !s) {
      if (i > 0) {
        return expected((std::to_string(n) + " numbers per value (got " + std::to_string(i) + ")").c_str(),
                        tokens_.peek());
      }
      return s;
    }
    if (multiple) {
      out.floats.push_back(static_cast<float>(v));
    } else {
      out.doubles.push_back(v);
    }
  }
  return {};
}

Status ValueReader::read(FieldValue& out) {
  if (!isMultiple(type_) || tokens_.peek().kind != TokenKind::kOpenBracket) return readOne(out);
  const Token open = tokens_.next();
  // Big arrays are MFVec3f / MFVec2f / MFInt32 in brackets: a tight loop for them,
  // falling back to the general path for anything unusual (and for its errors).
  const bool floats = type_ == FieldType::kMFVec3f || type_ == FieldType::kMFVec2f || type_ == FieldType::kMFFloat ||
                      type_ == FieldType::kMFColor || type_ == FieldType::kMFRotation;
  const size_t group = static_cast<size_t>(componentCount(type_));
  if (floats || type_ == FieldType::kMFInt32) {
    while (true) {
      const Token& t = tokens_.peek();
      if (t.kind == TokenKind::kFloat && floats && std::fabs(t.number) <= static_cast<double>(FLT_MAX)) {
        out.floats.push_back(static_cast<float>(t.number));
      } else if (t.kind == TokenKind::kInteger && floats) {
        out.floats.push_back(static_cast<float>(t.number));
      } else if (t.kind == TokenKind::kInteger && !floats && !t.hexadecimal &&
                 t.integer >= std::numeric_limits<int32_t>::min() && t.integer <= std::numeric_limits<int32_t>::max()) {
        out.ints.push_back(static_cast<int32_t>(t.integer));
      } else {
        break;
      }
      tokens_.next();
    }
    // Leave the general loop below a list ending on a whole value.
    const size_t count = floats ? out.floats.size() : out.ints.size();
    if (floats && count % group != 0) {
      const size_t partial = count % group;
      for (size_t i = 0; i < partial; ++i) out.floats.pop_back();
      return expected((std::to_string(group) + " numbers per value (got " + std::to_string(partial) + ")").c_str(),
                      tokens_.peek());
    }
  }
  while (true) {
    const Token& t = tokens_.peek();
    if (t.kind == TokenKind::kCloseBracket) {
      tokens_.next();
      return {};
    }
    if (t.kind == TokenKind::kEnd) {
      return errorAt(fileName_, t.pos, "expected ']' to close the list of field '" + std::string(fieldName_) +
                                           "' opened at " + std::to_string(open.pos.line) + ":" +
                                           std::to_string(open.pos.column) + ", found end of file");
    }
    PW_TRY(readOne(out));
  }
}

}  // namespace

Status parseFieldValue(Tokenizer& tokens, FieldType type, FieldValue& out, std::string_view fileName,
                       std::string_view fieldName) {
  return ValueReader(tokens, type, fileName, fieldName).read(out);
}

}  // namespace pw::engine::vrml

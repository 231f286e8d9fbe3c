#include "spec/json.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace shadergen::json {

const char* type_name(Type type) {
  switch (type) {
    case Type::null: return "null";
    case Type::boolean: return "a boolean";
    case Type::number: return "a number";
    case Type::string: return "a string";
    case Type::array: return "an array";
    case Type::object: return "an object";
  }
  return "?";
}

const Value* Value::find(std::string_view key) const {
  for (const Member& member : object)
    if (member.first == key) return &member.second;
  return nullptr;
}

namespace {

bool in_range(std::string_view bytes, std::size_t i, unsigned low, unsigned high) {
  if (i >= bytes.size()) return false;
  auto byte = static_cast<unsigned char>(bytes[i]);
  return byte >= low && byte <= high;
}

// The length of the well-formed UTF-8 sequence at the start of `bytes` (2 to 4), or 0.
std::size_t utf8_sequence_length(std::string_view bytes) {
  auto lead = static_cast<unsigned char>(bytes[0]);
  unsigned second_low = 0x80, second_high = 0xBF;
  std::size_t length = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) second_low = 0xA0;   // shorter forms are overlong
    if (lead == 0xED) second_high = 0x9F;  // U+D800..U+DFFF are surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) second_low = 0x90;   // overlong
    if (lead == 0xF4) second_high = 0x8F;  // above U+10FFFF
  } else {
    return 0;
  }
  if (!in_range(bytes, 1, second_low, second_high)) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (!in_range(bytes, i, 0x80, 0xBF)) return 0;
  return length;
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  Result<Value> run() {
    if (text_.size() > kMaxJsonBytes)
      return fail("spec is " + std::to_string(text_.size()) + " bytes; the limit is " + std::to_string(kMaxJsonBytes));
    skip_byte_order_mark();
    skip_space();
    Value root;
    if (!parse_value(root, 0)) return error_;
    skip_space();
    if (pos_ != text_.size()) return fail("unexpected text after the JSON document");
    return root;
  }

 private:
  Diagnostic fail(std::string message) {
    error_ = Diagnostic{Severity::error, file_, line_, column(), std::move(message)};
    return error_;
  }
  // For the parse steps, which report success as a bool: records the error, returns false.
  bool failed(std::string message) {
    fail(std::move(message));
    return false;
  }
  // The same, placed at the character just read rather than the next one.
  bool failed_at_last_character(std::string message) {
    --pos_;
    return failed(std::move(message));
  }
  int column() const { return static_cast<int>(pos_ - line_start_) + 1; }
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }

  // RFC 8259 lets a reader ignore a leading UTF-8 byte order mark, and some editors write one;
  // nlohmann accepts it too. Columns count from after it, as an editor shows the line.
  void skip_byte_order_mark() {
    if (text_.substr(0, 3) != "\xEF\xBB\xBF") return;
    pos_ = line_start_ = 3;
  }

  void skip_space() {
    while (!at_end()) {
      char c = text_[pos_];
      if (c == '\n') {
        ++pos_;
        ++line_;
        line_start_ = pos_;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++pos_;
      } else {
        break;
      }
    }
  }

  bool parse_value(Value& out, int depth) {
    out.line = line_;
    out.column = column();
    if (++values_ > kMaxJsonValues) return failed("more than " + std::to_string(kMaxJsonValues) + " JSON values");
    if (at_end()) return failed("unexpected end of file (the spec is truncated?)");
    char c = peek();
    if (c == '{' || c == '[') {
      if (depth >= kMaxJsonDepth) return failed("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      return c == '{' ? parse_object(out, depth + 1) : parse_array(out, depth + 1);
    }
    if (c == '"') {
      out.type = Type::string;
      return parse_string(out.string);
    }
    if (c == '-' || (c >= '0' && c <= '9')) return parse_number(out);
    if (match_word("true")) return out.type = Type::boolean, out.boolean = true, true;
    if (match_word("false")) return out.type = Type::boolean, out.boolean = false, true;
    if (match_word("null")) return out.type = Type::null, true;
    return failed(std::string("unexpected character '") + printable(c) + "'");
  }

  static std::string printable(char c) {
    if (static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f) return std::string(1, c);
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "\\x%02x", static_cast<unsigned char>(c));
    return buffer;
  }

  bool match_word(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }

  // Steps over a ',' between members or items. A ',' right before the closing `close` is the
  // commonest JSON slip (JavaScript and JSON5 allow it): it is called what it is, at the comma.
  bool skip_comma(char close) {
    int comma_line = line_, comma_column = column();
    ++pos_;
    skip_space();
    if (peek() != close) return true;
    error_ = Diagnostic{Severity::error, file_, comma_line, comma_column,
                        std::string("trailing comma before '") + close + "' (JSON allows none: remove it)"};
    return false;
  }

  bool parse_object(Value& out, int depth) {
    out.type = Type::object;
    ++pos_;  // '{'
    skip_space();
    if (peek() == '}') return ++pos_, true;
    for (;;) {
      skip_space();
      if (peek() != '"') {
        if (at_end()) return failed("unexpected end of file inside an object (the spec is truncated?)");
        return failed("expected a quoted key");
      }
      int key_line = line_, key_column = column();
      std::string key;
      if (!parse_string(key)) return false;
      if (out.find(key)) {
        error_ = Diagnostic{Severity::error, file_, key_line, key_column, "duplicate key \"" + key + "\""};
        return false;
      }
      skip_space();
      if (peek() != ':') return failed("expected ':' after key \"" + key + "\"");
      ++pos_;
      skip_space();
      Value member;
      if (!parse_value(member, depth)) return false;
      out.object.push_back(Member{std::move(key), std::move(member)});
      skip_space();
      if (peek() == ',') {
        if (!skip_comma('}')) return false;
        continue;
      }
      if (peek() == '}') return ++pos_, true;
      if (at_end()) return failed("unexpected end of file inside an object (the spec is truncated?)");
      return failed("expected ',' or '}' in an object");
    }
  }

  bool parse_array(Value& out, int depth) {
    out.type = Type::array;
    ++pos_;  // '['
    skip_space();
    if (peek() == ']') return ++pos_, true;
    for (;;) {
      skip_space();
      Value item;
      if (!parse_value(item, depth)) return false;
      out.array.push_back(std::move(item));
      skip_space();
      if (peek() == ',') {
        if (!skip_comma(']')) return false;
        continue;
      }
      if (peek() == ']') return ++pos_, true;
      if (at_end()) return failed("unexpected end of file inside an array (the spec is truncated?)");
      return failed("expected ',' or ']' in an array");
    }
  }

  bool parse_string(std::string& out) {
    ++pos_;  // opening quote
    for (;;) {
      if (at_end()) return failed("unterminated string");
      char c = text_[pos_++];
      if (c == '"') return true;
      if (c == '\n') return failed_at_last_character("newline inside a string");
      if (static_cast<unsigned char>(c) < 0x20) return failed_at_last_character("control character inside a string");
      if (static_cast<unsigned char>(c) >= 0x80) {
        if (!copy_utf8_sequence(out)) return false;
        continue;
      }
      if (c != '\\') {
        out += c;
        continue;
      }
      if (at_end()) return failed("unterminated string");
      char e = text_[pos_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u':
          if (!parse_unicode_escape(out)) return false;
          break;
        default: return failed_at_last_character(std::string("invalid escape '\\") + printable(e) + "'");
      }
    }
  }

  // Copies the UTF-8 sequence whose lead byte was just read. RFC 8259 text is UTF-8: overlong
  // forms, encoded surrogates and code points above U+10FFFF are rejected (Unicode's table of
  // well-formed byte sequences), as nlohmann does.
  bool copy_utf8_sequence(std::string& out) {
    std::size_t start = --pos_;
    std::size_t length = utf8_sequence_length(text_.substr(start));
    if (length == 0) return failed("invalid UTF-8 in a string");
    out.append(text_.substr(start, length));
    pos_ = start + length;
    return true;
  }

  bool parse_hex4(unsigned& code) {
    if (pos_ + 4 > text_.size()) return failed("truncated \\u escape");
    code = 0;
    for (int i = 0; i < 4; ++i) {
      char h = text_[pos_++];
      code <<= 4;
      if (h >= '0' && h <= '9')
        code |= static_cast<unsigned>(h - '0');
      else if (h >= 'a' && h <= 'f')
        code |= static_cast<unsigned>(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F')
        code |= static_cast<unsigned>(h - 'A' + 10);
      else
        return failed("invalid hex digit in \\u escape");
    }
    return true;
  }

  bool parse_unicode_escape(std::string& out) {
    unsigned code = 0;
    if (!parse_hex4(code)) return false;
    if (code >= 0xD800 && code <= 0xDBFF) {
      if (!match_word("\\u")) return failed("unpaired UTF-16 surrogate");
      unsigned low = 0;
      if (!parse_hex4(low)) return false;
      if (low < 0xDC00 || low > 0xDFFF) return failed("unpaired UTF-16 surrogate");
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    } else if (code >= 0xDC00 && code <= 0xDFFF) {
      return failed("unpaired UTF-16 surrogate");
    }
    append_utf8(out, code);
    return true;
  }

  static void append_utf8(std::string& out, unsigned code) {
    auto byte = [&](unsigned v) { out += static_cast<char>(v); };
    if (code < 0x80) {
      byte(code);
    } else if (code < 0x800) {
      byte(0xC0 | (code >> 6));
      byte(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      byte(0xE0 | (code >> 12));
      byte(0x80 | ((code >> 6) & 0x3F));
      byte(0x80 | (code & 0x3F));
    } else {
      byte(0xF0 | (code >> 18));
      byte(0x80 | ((code >> 12) & 0x3F));
      byte(0x80 | ((code >> 6) & 0x3F));
      byte(0x80 | (code & 0x3F));
    }
  }

  bool parse_number(Value& out) {
    std::size_t start = pos_;
    if (peek() == '-') ++pos_;
    if (peek() == '0') {
      ++pos_;
    } else if (peek() >= '1' && peek() <= '9') {
      while (peek() >= '0' && peek() <= '9') ++pos_;
    } else {
      return failed("invalid number");
    }
    if (peek() == '.') {
      ++pos_;
      if (!(peek() >= '0' && peek() <= '9')) return failed("invalid number: digits must follow '.'");
      while (peek() >= '0' && peek() <= '9') ++pos_;
    }
    if (peek() == 'e' || peek() == 'E') {
      ++pos_;
      if (peek() == '+' || peek() == '-') ++pos_;
      if (!(peek() >= '0' && peek() <= '9')) return failed("invalid number: exponent has no digits");
      while (peek() >= '0' && peek() <= '9') ++pos_;
    }
    std::string digits(text_.substr(start, pos_ - start));
    out.type = Type::number;
    out.number = std::strtod(digits.c_str(), nullptr);
    if (!std::isfinite(out.number)) return failed("number out of range: " + digits);
    return true;
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  std::size_t line_start_ = 0;
  std::size_t values_ = 0;
  int line_ = 1;
  Diagnostic error_;
};

}  // namespace

Result<Value> parse(std::string_view text, const std::string& file) { return Parser(text, file).run(); }

}  // namespace shadergen::json

#include "output/cpp_text.h"

namespace shadergen {
namespace {

// Appends `c` escaped for the inside of a literal or a comment.
void append_escaped(std::string& out, char c, bool quote) {
  unsigned char byte = static_cast<unsigned char>(c);
  switch (c) {
    case '\\': out += "\\\\"; return;
    case '\n': out += "\\n"; return;
    case '\r': out += "\\r"; return;
    case '\t': out += "\\t"; return;
    case '"': out += quote ? "\\\"" : "\""; return;
    default: break;
  }
  if (byte < 0x20 || byte == 0x7f) {
    out += '\\';
    out += static_cast<char>('0' + (byte >> 6));
    out += static_cast<char>('0' + ((byte >> 3) & 7));
    out += static_cast<char>('0' + (byte & 7));
    return;
  }
  out += c;
}

}  // namespace

std::string cpp_string_literal(std::string_view text) {
  std::string out = "\"";
  for (char c : text) append_escaped(out, c, true);
  return out + "\"";
}

std::string cpp_comment_text(std::string_view text) {
  std::string out;
  for (char c : text) append_escaped(out, c, false);
  return out;
}

}  // namespace shadergen

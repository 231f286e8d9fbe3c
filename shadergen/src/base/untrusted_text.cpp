#include "base/untrusted_text.h"

#include <algorithm>

namespace shadergen {
namespace {

void append_escaped(std::string& out, unsigned char c) {
  static constexpr char kDigits[] = "0123456789abcdef";
  switch (c) {
    case '\n': out += "\\n"; return;
    case '\t': out += "\\t"; return;
    case '\\': out += "\\\\"; return;
    default: break;
  }
  // Non-ASCII bytes too: UTF-8's C1 controls (U+0080..U+009F) start escape sequences on some
  // terminals, and no message we print needs anything beyond ASCII.
  if (c >= 0x20 && c < 0x7f) {
    out += static_cast<char>(c);
    return;
  }
  out += "\\x";
  out += kDigits[c >> 4];
  out += kDigits[c & 15];
}

// The "user:password" between "scheme://" and the last '@' before the path; empty if none.
std::string_view userinfo(std::string_view url) {
  std::size_t scheme = url.find("://");
  if (scheme == std::string_view::npos) return {};
  std::string_view rest = url.substr(scheme + 3);
  std::string_view authority = rest.substr(0, rest.find_first_of("/?#"));
  std::size_t at = authority.rfind('@');
  if (at == std::string_view::npos) return {};
  return authority.substr(0, at);
}

void replace_all(std::string& text, std::string_view secret) {
  if (secret.empty()) return;
  for (std::size_t at = text.find(secret); at != std::string::npos; at = text.find(secret, at + 3))
    text.replace(at, secret.size(), "***");
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out;
  std::size_t shown = std::min(text.size(), max_bytes);
  out.reserve(shown + 16);
  for (std::size_t i = 0; i < shown; ++i) append_escaped(out, static_cast<unsigned char>(text[i]));
  if (shown < text.size()) out += " ... (" + std::to_string(text.size() - shown) + " more bytes)";
  return out;
}

std::string redacted_url(std::string_view url) {
  std::string_view info = userinfo(url);
  if (info.empty()) return std::string(url);
  std::size_t start = static_cast<std::size_t>(info.data() - url.data());
  return std::string(url.substr(0, start)) + "***" + std::string(url.substr(start + info.size()));
}

std::string without_credentials(std::string message, std::string_view url) {
  std::string_view info = userinfo(url);
  replace_all(message, info);
  if (std::size_t colon = info.find(':'); colon != std::string_view::npos) replace_all(message, info.substr(colon + 1));
  return message;
}

}  // namespace shadergen

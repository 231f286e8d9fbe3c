#include "cache/signed_entry.h"

#include <openssl/crypto.h>

#include "base/sha256.h"

namespace shadergen {
namespace {

constexpr std::string_view kTrailerMagic = "SGHMAC1";
constexpr std::size_t kTrailerSize = kTrailerMagic.size() + 32;

bool has_trailer(std::string_view body) {
  return body.size() > kTrailerSize && body.substr(body.size() - kTrailerSize, kTrailerMagic.size()) == kTrailerMagic;
}

}  // namespace

std::string signed_entry(std::string_view entry, std::string_view secret) {
  auto mac = hmac_sha256(secret, entry);
  std::string out(entry);
  out += kTrailerMagic;
  out.append(reinterpret_cast<const char*>(mac.data()), mac.size());
  return out;
}

std::optional<std::string_view> verified_entry(std::string_view body, std::string_view secret) {
  if (!has_trailer(body)) return std::nullopt;
  std::string_view entry = body.substr(0, body.size() - kTrailerSize);
  std::string_view given = body.substr(body.size() - 32);
  auto expected = hmac_sha256(secret, entry);
  // In the same time wherever the two differ, so that a forger cannot find the MAC byte by byte.
  if (CRYPTO_memcmp(expected.data(), given.data(), expected.size()) != 0) return std::nullopt;
  return entry;
}

std::string_view unsigned_entry(std::string_view body) {
  return has_trailer(body) ? body.substr(0, body.size() - kTrailerSize) : body;
}

}  // namespace shadergen

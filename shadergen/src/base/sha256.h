// sha256.h - SHA-256 (FIPS 180-4), used for content addressing: cache keys, blob names and the
// hashes in the manifest, and HMAC-SHA256 for signed remote-cache entries. Collisions must be
// practically impossible because a cache hit skips compilation entirely, so a cheap
// non-cryptographic hash is not enough.
//
// Both come from OpenSSL's libcrypto (Debian: libssl-dev); only the project's own framing is
// here (field(), the hex form, the byte order of SPIR-V words). A failure inside libcrypto (out
// of memory, no provider of SHA-256) throws std::runtime_error naming the call: a hash that
// failed never yields a key.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

struct evp_md_ctx_st;  // OpenSSL's EVP_MD_CTX, kept out of this header

namespace shadergen {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(Sha256&&) noexcept;
  Sha256& operator=(Sha256&&) noexcept;
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  Sha256& update(std::span<const std::uint8_t> bytes);
  Sha256& update(std::string_view text);
  // SPIR-V words, as the little-endian bytes a .spv file holds, whatever the host's byte order:
  // one call into libcrypto for a whole blob, not one per word (each call has a cost of its own).
  Sha256& update_words(std::span<const std::uint32_t> words);
  // A length-prefixed field, so ("ab","c") and ("a","bc") hash differently: the length as 8
  // little-endian bytes, then the text.
  Sha256& field(std::string_view text);
  // The digest of everything given. Once per hasher: update() or finish() after it throws
  // std::logic_error.
  std::array<std::uint8_t, 32> finish();
  std::string finish_hex();

 private:
  struct ContextDeleter {
    void operator()(evp_md_ctx_st* context) const;
  };
  std::unique_ptr<evp_md_ctx_st, ContextDeleter> context_;
  bool finished_ = false;
};

std::string sha256_hex(std::string_view text);
// The words as the little-endian bytes a .spv file holds, whatever the host's byte order.
std::string sha256_hex(std::span<const std::uint32_t> words);
std::string to_hex(std::span<const std::uint8_t> bytes);

// HMAC-SHA256 (RFC 2104): the signature of remote-cache entries, keyed by a team's secret. A
// key longer than SHA-256's 64-byte block is hashed first, as the RFC says.
std::array<std::uint8_t, 32> hmac_sha256(std::string_view key, std::string_view message);

}  // namespace shadergen

// sha256.h - SHA-256 (FIPS 180-4), used for content addressing: cache keys, blob names and the
// hashes in the manifest. Collisions must be practically impossible because a cache hit skips
// compilation entirely, so a cheap non-cryptographic hash is not enough.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace shadergen {

class Sha256 {
 public:
  Sha256();
  Sha256& update(std::span<const std::uint8_t> bytes);
  Sha256& update(std::string_view text);
  // A length-prefixed field, so ("ab","c") and ("a","bc") hash differently.
  Sha256& field(std::string_view text);
  std::array<std::uint8_t, 32> finish();
  std::string finish_hex();

 private:
  void compress(const std::uint8_t* block);

  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
};

std::string sha256_hex(std::string_view text);
std::string sha256_hex(std::span<const std::uint32_t> words);
std::string to_hex(std::span<const std::uint8_t> bytes);

// HMAC-SHA256 (RFC 2104): the signature of remote-cache entries, keyed by a team's secret.
std::array<std::uint8_t, 32> hmac_sha256(std::string_view key, std::string_view message);

// The block function the hashers run: the x86 SHA extensions where the CPU has them (a warm
// build hashes every cache entry it loads, about 2 MB for Split/Second, and the extensions do
// that several times faster), else portable C++. Both give the same digests.
enum class Sha256Engine { portable, x86_sha_extensions };
Sha256Engine sha256_engine();
// For tests and benchmarks: hashers run `engine` from now on. Returns false, changing nothing,
// when this CPU lacks it. Not to be called while another thread is hashing.
bool use_sha256_engine(Sha256Engine engine);

}  // namespace shadergen

#include "base/sha256.h"

#include <openssl/core_names.h>
#include <openssl/err.h>
#include <openssl/evp.h>
#include <openssl/params.h>

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <utility>

namespace shadergen {
namespace {

// Throws with what libcrypto says went wrong: its first queued error, if it queued one. The
// queue is emptied, so the next call's failure is reported with its own reason.
[[noreturn]] void libcrypto_failed(std::string_view call) {
  std::string message = "hashing with OpenSSL's libcrypto: " + std::string(call) + " failed";
  if (unsigned long code = ERR_get_error(); code != 0) {
    std::array<char, 256> reason{};
    ERR_error_string_n(code, reason.data(), reason.size());
    message += std::string(" (") + reason.data() + ")";
  }
  ERR_clear_error();
  throw std::runtime_error(message);
}

// libcrypto's calls return 1 on success.
void check(int result, std::string_view call) {
  if (result != 1) libcrypto_failed(call);
}

struct DigestDeleter {
  void operator()(EVP_MD* digest) const { EVP_MD_free(digest); }
};
struct MacDeleter {
  void operator()(EVP_MAC* mac) const { EVP_MAC_free(mac); }
};
struct MacContextDeleter {
  void operator()(EVP_MAC_CTX* context) const { EVP_MAC_CTX_free(context); }
};

// SHA-256 and HMAC, each fetched from libcrypto's providers once per process (EVP_sha256()
// would look the implementation up again at every init) on first use; C++ makes the first use
// thread-safe, and a fetched algorithm may be shared by any number of threads. A failed fetch
// stays failed: every use throws.
const EVP_MD* sha256_digest() {
  static const std::unique_ptr<EVP_MD, DigestDeleter> digest(EVP_MD_fetch(nullptr, "SHA2-256", nullptr));
  if (!digest) libcrypto_failed("EVP_MD_fetch(SHA2-256)");
  return digest.get();
}

EVP_MAC* hmac() {
  static const std::unique_ptr<EVP_MAC, MacDeleter> mac(EVP_MAC_fetch(nullptr, "HMAC", nullptr));
  if (!mac) libcrypto_failed("EVP_MAC_fetch(HMAC)");
  return mac.get();
}

const std::uint8_t* bytes_of(std::string_view text) { return reinterpret_cast<const std::uint8_t*>(text.data()); }

}  // namespace

void Sha256::ContextDeleter::operator()(evp_md_ctx_st* context) const { EVP_MD_CTX_free(context); }

Sha256::Sha256() : context_(EVP_MD_CTX_new()) {
  if (!context_) libcrypto_failed("EVP_MD_CTX_new");
  check(EVP_DigestInit_ex(context_.get(), sha256_digest(), nullptr), "EVP_DigestInit_ex");
}

Sha256::~Sha256() = default;
Sha256::Sha256(Sha256&&) noexcept = default;
Sha256& Sha256::operator=(Sha256&&) noexcept = default;

Sha256& Sha256::update(std::span<const std::uint8_t> bytes) {
  if (finished_ || !context_) throw std::logic_error("Sha256::update() after finish()");
  if (!bytes.empty()) check(EVP_DigestUpdate(context_.get(), bytes.data(), bytes.size()), "EVP_DigestUpdate");
  return *this;
}

Sha256& Sha256::update(std::string_view text) { return update(std::span(bytes_of(text), text.size())); }

Sha256& Sha256::update_words(std::span<const std::uint32_t> words) {
  // On a little-endian host, the words' own bytes.
  if constexpr (std::endian::native == std::endian::little)
    return update(std::span(reinterpret_cast<const std::uint8_t*>(words.data()), words.size_bytes()));
  std::array<std::uint8_t, 1024> bytes{};
  while (!words.empty()) {
    const std::size_t count = std::min(words.size(), bytes.size() / 4);
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t b = 0; b < 4; ++b) bytes[4 * i + b] = static_cast<std::uint8_t>(words[i] >> (8 * b));
    update(std::span(bytes.data(), 4 * count));
    words = words.subspan(count);
  }
  return *this;
}

Sha256& Sha256::field(std::string_view text) {
  std::array<std::uint8_t, 8> length{};
  const std::uint64_t n = text.size();
  for (std::size_t i = 0; i < length.size(); ++i) length[i] = static_cast<std::uint8_t>(n >> (8 * i));
  update(length);
  return update(text);
}

std::array<std::uint8_t, 32> Sha256::finish() {
  if (finished_ || !context_) throw std::logic_error("Sha256::finish() called twice");
  finished_ = true;
  std::array<std::uint8_t, 32> digest{};
  unsigned int size = 0;
  check(EVP_DigestFinal_ex(context_.get(), digest.data(), &size), "EVP_DigestFinal_ex");
  if (size != digest.size()) libcrypto_failed("EVP_DigestFinal_ex (a digest of " + std::to_string(size) + " bytes)");
  return digest;
}

std::string Sha256::finish_hex() {
  auto digest = finish();
  return to_hex(digest);
}

std::string to_hex(std::span<const std::uint8_t> bytes) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  out.reserve(bytes.size() * 2);
  for (std::uint8_t b : bytes) {
    out += kDigits[b >> 4];
    out += kDigits[b & 15];
  }
  return out;
}

std::string sha256_hex(std::string_view text) { return Sha256().update(text).finish_hex(); }

std::string sha256_hex(std::span<const std::uint32_t> words) { return Sha256().update_words(words).finish_hex(); }

std::array<std::uint8_t, 32> hmac_sha256(std::string_view key, std::string_view message) {
  const std::unique_ptr<EVP_MAC_CTX, MacContextDeleter> context(EVP_MAC_CTX_new(hmac()));
  if (!context) libcrypto_failed("EVP_MAC_CTX_new(HMAC)");
  std::string digest_name = "SHA256";
  const std::array<OSSL_PARAM, 2> parameters = {
      OSSL_PARAM_construct_utf8_string(OSSL_MAC_PARAM_DIGEST, digest_name.data(), 0), OSSL_PARAM_construct_end()};
  // An empty key is still a key (64 zero bytes once padded): libcrypto takes it only with a
  // pointer, a null one meaning "the key set before".
  static constexpr std::uint8_t kNoKeyBytes = 0;
  const std::uint8_t* key_bytes = key.empty() ? &kNoKeyBytes : bytes_of(key);
  check(EVP_MAC_init(context.get(), key_bytes, key.size(), parameters.data()), "EVP_MAC_init(HMAC, SHA256)");
  if (!message.empty()) check(EVP_MAC_update(context.get(), bytes_of(message), message.size()), "EVP_MAC_update");
  std::array<std::uint8_t, 32> mac{};
  std::size_t size = 0;
  check(EVP_MAC_final(context.get(), mac.data(), &size, mac.size()), "EVP_MAC_final");
  if (size != mac.size()) libcrypto_failed("EVP_MAC_final (a MAC of " + std::to_string(size) + " bytes)");
  return mac;
}

}  // namespace shadergen

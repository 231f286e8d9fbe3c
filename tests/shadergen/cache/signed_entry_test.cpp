// The signature a remote-cache upload carries when a team shares a secret (cache/signed_entry.h):
// the entry, "SGHMAC1" and the HMAC-SHA-256 of the entry under the secret. The golden trailers
// are what f4b0d10 (the hand-written HMAC, before it came from OpenSSL's libcrypto) wrote for
// these entries (Python's hmac agrees): a server filled by that build must still verify under
// this one, and the other way round.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "base/sha256.h"
#include "cache/cache.h"
#include "cache/signed_entry.h"

namespace signed_entry_test {
namespace {

using shadergen::signed_entry;
using shadergen::unsigned_entry;
using shadergen::verified_entry;

constexpr std::string_view kMagic = "SGHMAC1";
constexpr std::size_t kTrailerSize = kMagic.size() + 32;

// A content-cache entry as it is uploaded: a four-word blob under a key of 64 'c's.
std::string cache_entry() {
  return shadergen::encode_cache_entry(std::string(64, 'c'),
                                       shadergen::CachedBlob{{0x07230203u, 0x00010500u, 7u, 0xdeadbeefu}, false, {}});
}

// A secret longer than the HMAC's 64-byte block, which is hashed first.
std::string long_secret() {
  std::string secret;
  for (int i = 0; i < 100; ++i) secret += static_cast<char>('A' + i % 26);
  return secret;
}

// The trailer's HMAC, in hex, after checking that `body` is `entry` followed by a trailer.
std::string trailer_hex(const std::string& body, const std::string& entry) {
  EXPECT_EQ(body.size(), entry.size() + kTrailerSize);
  EXPECT_EQ(body.substr(0, entry.size()), entry);
  EXPECT_EQ(body.substr(entry.size(), kMagic.size()), kMagic);
  const std::string_view mac = std::string_view(body).substr(body.size() - 32);
  return shadergen::to_hex(std::span(reinterpret_cast<const std::uint8_t*>(mac.data()), mac.size()));
}

TEST(SignedEntryGolden, TrailersAreTheOnesAlreadyOnServers) {
  const std::string entry = cache_entry();
  EXPECT_EQ(trailer_hex(signed_entry(entry, "team secret"), entry),
            "3a07e2ab9f60df3ef005527bf252e5deb5d42262949e08d625c62d6293eb1ae6");
  EXPECT_EQ(trailer_hex(signed_entry(entry, long_secret()), entry),
            "c0bc29bd62115b400549f8130e4d5faade48eadd1488600bbe4d56652f3cb7b1");
  const std::string text = "shadergen-shard-record 1\nindex 0\ncount 4\n";
  EXPECT_EQ(trailer_hex(signed_entry(text, "k"), text),
            "02f50e502288c2d73e183a729bf68ed4b8f7cda7fb5ff493cca42c611fa9f440");
}

TEST(SignedEntry, VerifiesItsOwnSignatureAndGivesTheEntry) {
  const std::string entry = cache_entry();
  for (const std::string& secret : {std::string("team secret"), long_secret()}) {
    const std::string body = signed_entry(entry, secret);
    auto verified = verified_entry(body, secret);
    ASSERT_TRUE(verified.has_value());
    EXPECT_EQ(*verified, entry);
    EXPECT_EQ(unsigned_entry(body), entry);
  }
}

TEST(SignedEntry, RefusesAnotherSecretAnyFlippedByteAndUnsignedBodies) {
  const std::string entry = cache_entry();
  const std::string body = signed_entry(entry, "team secret");
  EXPECT_FALSE(verified_entry(body, "team secreT"));
  EXPECT_FALSE(verified_entry(body, long_secret()));
  for (std::size_t at = 0; at < body.size(); ++at) {
    std::string flipped = body;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x01);
    EXPECT_FALSE(verified_entry(flipped, "team secret")) << "byte " << at << " flipped";
  }
  EXPECT_FALSE(verified_entry(entry, "team secret")) << "no trailer";
  EXPECT_FALSE(verified_entry(body.substr(0, body.size() - 1), "team secret")) << "truncated";
  EXPECT_FALSE(verified_entry(body + "x", "team secret")) << "a byte after the trailer";
  EXPECT_FALSE(verified_entry(body.substr(entry.size()), "team secret")) << "a trailer alone";
  EXPECT_EQ(unsigned_entry(entry), entry) << "an unsigned body is the entry";
}

}  // namespace
}  // namespace signed_entry_test

// SHA-256 known answers: the FIPS 180-4 / NIST example messages, and messages on each side of
// the padding boundaries (55 bytes is the longest that pads within one block, 56 forces a second
// block, 64 is a whole block), whose digests were taken from coreutils `sha256sum`:
//   s=$(for i in $(seq 1 20); do printf '0123456789abcdef'; done)
//   printf '%s' "${s:0:N}" | sha256sum
// Every case is also fed in pieces, so the buffering across update() calls is checked too.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "base/sha256.h"

namespace {

struct KnownAnswer {
  const char* name;
  std::string message;
  const char* digest;
};

// The first `n` bytes of "0123456789abcdef" repeated.
std::string hex_pattern(std::size_t n) {
  std::string text;
  while (text.size() < n) text += "0123456789abcdef";
  return text.substr(0, n);
}

std::vector<KnownAnswer> known_answers() {
  return {
      {"empty", "", "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"},
      {"abc", "abc", "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"},
      {"nist_448_bits", "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq",
       "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1"},
      {"million_a", std::string(1000000, 'a'), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"},
      {"pattern_55", hex_pattern(55), "72fa96f64bf2dd082aafb08cf80ed17f5b3d2c6cd527c4b138b69506f5e5c173"},
      {"pattern_56", hex_pattern(56), "67e4026bfbe6f1cd3f40518f324bcdf4426ae00faf5a0cddeae67a0e60ecf665"},
      {"pattern_57", hex_pattern(57), "c5acf2328bc8bb46744c0d87810eb30571e953de6e4e2edc18e5e522aae917dc"},
      {"pattern_63", hex_pattern(63), "057ee79ece0b9a849552ab8d3c335fe9a5f1c46ef5f1d9b190c295728628299c"},
      {"pattern_64", hex_pattern(64), "a8ae6e6ee929abea3afcfc5258c8ccd6f85273e0d4626d26c7279f3250f77c8e"},
      {"pattern_65", hex_pattern(65), "2a6ad82f3620d3ebe9d678c812ae12312699d673240d5be8fac0910a70000d93"},
      {"pattern_119", hex_pattern(119), "d35c1f1837833831770e239839643070c6502a21b1df3b55fe81a4f7f6d33063"},
      {"pattern_120", hex_pattern(120), "b55c6052a3c9b52cfe373d8a12149b45d01df4477a91ad7c7925b0a02d8f2a30"},
      {"pattern_128", hex_pattern(128), "b320e85978db05134003a2914eebddd8d3b8726818f2e2c679e1898c721562a9"},
  };
}

class Sha256KnownAnswer : public ::testing::TestWithParam<KnownAnswer> {};

TEST_P(Sha256KnownAnswer, WholeMessage) { EXPECT_EQ(shadergen::sha256_hex(GetParam().message), GetParam().digest); }

// Piece sizes that straddle the 64-byte block in different ways.
TEST_P(Sha256KnownAnswer, MessageInPieces) {
  const std::string& message = GetParam().message;
  for (std::size_t piece : {1u, 7u, 55u, 56u, 63u, 64u, 65u}) {
    if (message.size() > 4096 && piece < 55) continue;  // the million: whole blocks are enough
    shadergen::Sha256 hasher;
    for (std::size_t at = 0; at < message.size(); at += piece)
      hasher.update(std::string_view(message).substr(at, piece));
    EXPECT_EQ(hasher.finish_hex(), GetParam().digest) << "pieces of " << piece << " bytes";
  }
}

INSTANTIATE_TEST_SUITE_P(Fips180, Sha256KnownAnswer, ::testing::ValuesIn(known_answers()),
                         [](const ::testing::TestParamInfo<KnownAnswer>& c) { return c.param.name; });

// Each block engine (the x86 SHA extensions where this CPU has them, and portable C++) on every
// known answer, whole and in pieces, and on messages of every length up to 300 bytes, against
// the other engine. The engine in use before is restored.
TEST(Sha256Engines, EachEngineGivesTheKnownAnswersAndTheSameDigests) {
  using shadergen::Sha256Engine;
  const Sha256Engine before = shadergen::sha256_engine();
  std::vector<std::string> messages;
  for (std::size_t n = 0; n <= 300; ++n) {
    std::string message(n, '\0');
    for (std::size_t i = 0; i < n; ++i) message[i] = static_cast<char>((i * 131 + n * 7) & 0xff);
    messages.push_back(message);
  }
  std::vector<std::string> portable_digests;
  int engines_run = 0;
  for (Sha256Engine engine : {Sha256Engine::portable, Sha256Engine::x86_sha_extensions}) {
    if (!shadergen::use_sha256_engine(engine)) continue;
    ++engines_run;
    const char* name = engine == Sha256Engine::portable ? "portable" : "x86 SHA extensions";
    for (const KnownAnswer& answer : known_answers()) {
      EXPECT_EQ(shadergen::sha256_hex(answer.message), answer.digest) << name << ", " << answer.name;
      shadergen::Sha256 hasher;
      for (std::size_t at = 0; at < answer.message.size(); at += 65)
        hasher.update(std::string_view(answer.message).substr(at, 65));
      EXPECT_EQ(hasher.finish_hex(), answer.digest) << name << ", " << answer.name << " in pieces of 65 bytes";
    }
    for (std::size_t i = 0; i < messages.size(); ++i) {
      std::string digest = shadergen::sha256_hex(messages[i]);
      if (engine == Sha256Engine::portable)
        portable_digests.push_back(digest);
      else
        EXPECT_EQ(digest, portable_digests[i]) << name << " against portable, " << i << " bytes";
    }
  }
  shadergen::use_sha256_engine(before);
  EXPECT_GE(engines_run, 1);
  if (engines_run == 1) GTEST_SKIP() << "this CPU has no SHA extensions: only the portable engine was checked";
}

// SPIR-V words are hashed as the little-endian bytes a .spv file holds: the word 0x64636261 is
// the bytes "abcd" (printf abcd | sha256sum).
TEST(Sha256Words, HashesWordsAsLittleEndianBytes) {
  const std::vector<std::uint32_t> words = {0x64636261u};
  EXPECT_EQ(shadergen::sha256_hex(words), "88d4266fd4e6338d13b845fcf289579d209c897823b9217da3e161936f031589");
  EXPECT_EQ(shadergen::sha256_hex(std::vector<std::uint32_t>{}), shadergen::sha256_hex(""));
}

// Cache keys are built from fields: moving a byte across a field boundary must change the key.
TEST(Sha256Fields, FieldBoundariesAreHashed) {
  const std::string ab_c = shadergen::Sha256().field("ab").field("c").finish_hex();
  const std::string a_bc = shadergen::Sha256().field("a").field("bc").finish_hex();
  EXPECT_NE(ab_c, a_bc);
  EXPECT_NE(ab_c, shadergen::sha256_hex("abc"));
}

TEST(Sha256Hex, LowercaseTwoDigitsPerByte) {
  const std::vector<std::uint8_t> bytes = {0x00, 0x0f, 0xa0, 0xff};
  EXPECT_EQ(shadergen::to_hex(bytes), "000fa0ff");
}

// RFC 4231 test cases 2 (a short key) and 6 (a key longer than the block, hashed first).
TEST(HmacSha256, MatchesRfc4231) {
  EXPECT_EQ(shadergen::to_hex(shadergen::hmac_sha256("Jefe", "what do ya want for nothing?")),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
  EXPECT_EQ(shadergen::to_hex(shadergen::hmac_sha256(std::string(131, '\xaa'),
                                                     "Test Using Larger Than Block-Size Key - Hash Key First")),
            "60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54");
}

}  // namespace

// SHA-256 known answers: the FIPS 180-4 / NIST example messages, and messages on each side of
// the padding boundaries (55 bytes is the longest that pads within one block, 56 forces a second
// block, 64 is a whole block), whose digests were taken from coreutils `sha256sum`:
//   s=$(for i in $(seq 1 20); do printf '0123456789abcdef'; done)
//   printf '%s' "${s:0:N}" | sha256sum
// Every case is also fed in pieces, so the buffering across update() calls is checked too.
// The hashing itself is OpenSSL's libcrypto (shadergen/src/base/sha256.cpp); the golden values
// further down hold it to what the hand-written implementation before it gave.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "base/sha256.h"

namespace sha256_test {
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

// A hasher gives one digest: using it after finish() is a mistake that must not yield a key.
TEST(Sha256Use, NothingAfterFinish) {
  shadergen::Sha256 hasher;
  hasher.update("abc");
  EXPECT_EQ(hasher.finish_hex(), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_THROW(hasher.update("d"), std::logic_error);
  EXPECT_THROW(hasher.finish(), std::logic_error);
}

// A moved hasher carries on where it was; the one moved from is spent.
TEST(Sha256Use, MovesKeepTheStateSoFar) {
  shadergen::Sha256 first;
  first.update("ab");
  shadergen::Sha256 second = std::move(first);
  second.update("c");
  EXPECT_EQ(second.finish_hex(), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_THROW(first.update("c"), std::logic_error);  // NOLINT(bugprone-use-after-move): on purpose
}

TEST(Sha256Hex, LowercaseTwoDigitsPerByte) {
  const std::vector<std::uint8_t> bytes = {0x00, 0x0f, 0xa0, 0xff};
  EXPECT_EQ(shadergen::to_hex(bytes), "000fa0ff");
}

// RFC 4231, HMAC-SHA-256 test cases 1 to 4, 6 and 7 (case 5 truncates the output to 128
// bits, which nothing here does): another implementation's answers. Case 6 and 7's 131-byte
// key is longer than the block, so it is hashed first.
struct HmacCase {
  const char* name;
  std::string key;
  std::string message;
  const char* mac;
};

std::string bytes_from(std::uint8_t first, std::size_t count) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) out += static_cast<char>(first + i);
  return out;
}

class HmacSha256Rfc4231 : public ::testing::TestWithParam<HmacCase> {};

TEST_P(HmacSha256Rfc4231, GivesTheRfcAnswer) {
  EXPECT_EQ(shadergen::to_hex(shadergen::hmac_sha256(GetParam().key, GetParam().message)), GetParam().mac);
}

INSTANTIATE_TEST_SUITE_P(
    Rfc4231, HmacSha256Rfc4231,
    ::testing::Values(
        HmacCase{"case_1", std::string(20, '\x0b'), "Hi There",
                 "b0344c61d8db38535ca8afceaf0bf12b881dc200c9833da726e9376c2e32cff7"},
        HmacCase{"case_2", "Jefe", "what do ya want for nothing?",
                 "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843"},
        HmacCase{"case_3", std::string(20, '\xaa'), std::string(50, '\xdd'),
                 "773ea91e36800e46854db8ebd09181a72959098b3ef8c122d9635514ced565fe"},
        HmacCase{"case_4", bytes_from(0x01, 25), std::string(50, '\xcd'),
                 "82558a389a443c0ea4cc819899f2083a85f0faa3e578f8077a2e3ff46729665b"},
        HmacCase{"case_6", std::string(131, '\xaa'), "Test Using Larger Than Block-Size Key - Hash Key First",
                 "60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54"},
        HmacCase{"case_7", std::string(131, '\xaa'),
                 "This is a test using a larger than block-size key and a larger than block-size data. The key "
                 "needs to be hashed before being used by the HMAC algorithm.",
                 "9b09ffa71b942fcb27635fbcd5b0e944bfdc63644f0713938a7f51535c3a35e2"}),
    [](const ::testing::TestParamInfo<HmacCase>& c) { return c.param.name; });

// Golden digests: what the hand-written SHA-256 and HMAC of f4b0d10 (shadergen/src/base/
// sha256.cpp before it moved to OpenSSL's libcrypto) printed for these inputs. Every cache key,
// blob name, entry checksum and remote-cache signature is made of these functions, so they must
// never change: a change would make every existing cache miss and every signed server refuse.
//
// They were printed by this test's first version against f4b0d10's build, and agree with
// Python's hashlib and hmac on the same bytes. Byte i of a golden message is (i * 167 + 13)
// mod 256, binary rather than text.
std::string golden_message(std::size_t n) {
  std::string out(n, '\0');
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<char>((i * 167 + 13) & 0xffu);
  return out;
}

// `message` hashed in pieces of 1, 3, 7, 13, 61, 127 and 4099 bytes in turn: odd sizes, so the
// pieces start at every offset within a block.
std::string digest_in_odd_pieces(const std::string& message) {
  static constexpr std::size_t kPieces[] = {1, 3, 7, 13, 61, 127, 4099};
  shadergen::Sha256 hasher;
  std::size_t at = 0;
  for (std::size_t turn = 0; at < message.size(); ++turn) {
    const std::size_t piece = kPieces[turn % std::size(kPieces)];
    hasher.update(std::string_view(message).substr(at, piece));
    at += piece;
  }
  return hasher.finish_hex();
}

struct GoldenDigest {
  std::size_t length;
  const char* digest;
  friend std::ostream& operator<<(std::ostream& out, const GoldenDigest& golden) {
    return out << golden.length << " bytes";
  }
};

class Sha256GoldenLengths : public ::testing::TestWithParam<GoldenDigest> {};

TEST_P(Sha256GoldenLengths, WholeAndInOddPieces) {
  const std::string message = golden_message(GetParam().length);
  EXPECT_EQ(shadergen::sha256_hex(message), GetParam().digest);
  EXPECT_EQ(digest_in_odd_pieces(message), GetParam().digest);
}

INSTANTIATE_TEST_SUITE_P(
    Golden, Sha256GoldenLengths,
    ::testing::Values(GoldenDigest{0, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"},
                      GoldenDigest{55, "b2ca0adc388a66d3a5a7f6541239331d5a867eede554e11262241271faaf36c5"},
                      GoldenDigest{56, "3768eff44f1df02704a832cf708935fbed9bb74d0714fbe75454c266c4e12856"},
                      GoldenDigest{63, "dc06ea9e456da9f9fc2276564018231c36196ff7745bf505fd7f503aec5c67fd"},
                      GoldenDigest{64, "b68fe543b0b5a544e32eb08712e697bfcd3a3cb491563c3b1cba112d378f4bdb"},
                      GoldenDigest{65, "587cdb9ad9be371721f2f84a84eb09f2b698ec19bbe2d7c222179996547a04a6"},
                      GoldenDigest{1000, "fa10d4e76ab24b0ff9d6c596a00df178cd2a80a15c70770dee68d374ccb39bc6"},
                      GoldenDigest{std::size_t{1} << 20,
                                   "d5beffaebd800b191153e756463134b31e30f268432cd034c1212c43b368859a"}),
    [](const ::testing::TestParamInfo<GoldenDigest>& c) { return "bytes_" + std::to_string(c.param.length); });

// Sha256::field chains, the way every key is built: the 8-byte little-endian length, then the
// bytes. A 300-byte field has two non-zero length bytes.
TEST(Sha256GoldenFields, Chains) {
  using shadergen::Sha256;
  EXPECT_EQ(Sha256().field("").finish_hex(), "af5570f5a1810b7af78caf4bc70a660f0df51e42baf91d4de5b2328de0e83dfc");
  EXPECT_EQ(Sha256().field("ab").field("c").finish_hex(),
            "43ee655579de01ca739b3f95c1c2d3f46d353b2c0df818064ea594506cdb2617");
  EXPECT_EQ(Sha256().field("a").field("bc").finish_hex(),
            "9a8acca1b6c6c0befd3fbc756aed625da998c998f7252e738c4ef061906b9b21");
  EXPECT_EQ(Sha256().field("shadergen-cache-entry").field(golden_message(300)).update("raw").field("").finish_hex(),
            "5e9f43e6b530b363e55bdaa6e3227a61b3372a54ebc13c3fbb5721acdbb61d19");
}

// SPIR-V words, hashed as their little-endian bytes: the blob names and the manifest's hashes.
TEST(Sha256GoldenWords, LittleEndianBytes) {
  std::vector<std::uint32_t> words;
  for (std::uint32_t i = 0; i < 1000; ++i) words.push_back(0x07230203u + i * 0x9e3779b9u);
  EXPECT_EQ(shadergen::sha256_hex(std::span<const std::uint32_t>(words.data(), 1)),
            "b263db113857145cd1ec390021310f185f50bd5e3027f4111c1c5d9b7c0890a4");
  EXPECT_EQ(shadergen::sha256_hex(words), "c16796751e9b17a991d00ab955a59613b3702729f6f4f3163d6dd6c32bb0a5ff");
  // The same bytes through update_words() in two pieces, and as bytes through update().
  const std::span<const std::uint32_t> all(words);
  EXPECT_EQ(shadergen::Sha256().update_words(all.first(257)).update_words(all.subspan(257)).finish_hex(),
            "c16796751e9b17a991d00ab955a59613b3702729f6f4f3163d6dd6c32bb0a5ff");
  std::string bytes;
  for (std::uint32_t word : words)
    for (int b = 0; b < 4; ++b) bytes += static_cast<char>((word >> (8 * b)) & 0xffu);
  EXPECT_EQ(shadergen::sha256_hex(bytes), "c16796751e9b17a991d00ab955a59613b3702729f6f4f3163d6dd6c32bb0a5ff");
}

// HMAC-SHA-256 under keys shorter than the block, exactly a block, one byte over and over two
// blocks long (hashed first), on an empty and a 1000-byte message. Byte i of a key of length n
// is (i * 29 + n) mod 256.
TEST(HmacSha256Golden, KeysOfEachLength) {
  const std::pair<std::size_t, const char*> empty_message[] = {
      {0, "b613679a0814d9ec772f95d778c35fc5ff1697c493715653c6c712144292c5ad"},
      {20, "0cb11a891c3e9850fa1a07ac3a8e6a4027c38d68fecce35f770618db9e674df3"},
      {64, "3e0f16ef4ed5f90da706932c46f0f5b59d7b62a8dcecc181e3dadb2d63ce930f"},
      {65, "33365f81263ba28432fd7a615ff8f3996b713c0bc2461c533e46cb13cb0cb77f"},
      {131, "49ee16c346f6e25cd2f304cc27c1c8ce85b6f4a0639f5ef49531e8aee03d5fe1"}};
  const std::pair<std::size_t, const char*> long_message[] = {
      {0, "8477b6909c246005c996b4276333b616fc0ddc24210b6f099b8cf51179ea5dec"},
      {20, "07fc5867aa000171419b497b9403269d8711942deeab1d948481870c01a0b5cc"},
      {64, "e8810556b77459437616da22fa15259c90aec3f78b1492f20080ed1eee3479bf"},
      {65, "b32abab0fa989c3b39cd49b39dd4864a67edeee350c5de9b9f7182ffc83ee464"},
      {131, "b895649f0bd936c544345a3e99e1b5e1819e8a0fa5978e1fb3004d1db7d93d93"}};
  auto key_of = [](std::size_t n) {
    std::string key(n, '\0');
    for (std::size_t i = 0; i < n; ++i) key[i] = static_cast<char>((i * 29 + n) & 0xffu);
    return key;
  };
  for (const auto& [length, mac] : empty_message)
    EXPECT_EQ(shadergen::to_hex(shadergen::hmac_sha256(key_of(length), "")), mac) << "key of " << length;
  for (const auto& [length, mac] : long_message)
    EXPECT_EQ(shadergen::to_hex(shadergen::hmac_sha256(key_of(length), golden_message(1000))), mac)
        << "key of " << length;
}

}  // namespace
}  // namespace sha256_test

// Fuzz entry point: what the remote cache does with a server's answers. One input is a mode byte,
// an HTTP status (two bytes, little-endian) and a payload. The payload becomes the body every
// request is answered with: as it is (mode 0), as a well-formed entry of the payload's words and
// text (1; one byte flipped when the payload's first byte has bit 2 set), as such an entry signed
// (2), or as an input-set entry (3, its bytes as they are). Bit 3 gives the remote cache a secret. Then load(), store() and offer()
// run through a fake HTTP client, and the decoders run on the body directly.
//
// Beyond "no crash, no hang, no leak", it checks that a decoded entry re-encodes to the same
// bytes (the format has one spelling), that load() returns only what the decoder accepts with
// the key asked for, that with a secret nothing unsigned is accepted, and that every warning is
// one line of printable ASCII of bounded length.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "base/untrusted_text.h"
#include "cache/cache.h"
#include "cache/http_client.h"
#include "cache/input_cache.h"
#include "cache/remote_cache.h"
#include "cache/signed_entry.h"
#include "fuzz_check.h"

namespace {

using shadergen::fuzz::require;

const std::string kKey = "0f" + std::string(62, 'a');
constexpr std::string_view kSecret = "fuzz secret";

class AnswerEverything final : public shadergen::HttpClient {
 public:
  AnswerEverything(long status, std::string body) : status_(status), body_(std::move(body)) {}
  shadergen::Result<shadergen::HttpResponse> send(const shadergen::HttpRequest& request) override {
    require(request.timeout.count() > 0, "every request has a positive time limit");
    if (status_ < 0) return shadergen::make_error("connection reset: \x1b[2J" + body_.substr(0, 64));
    return shadergen::HttpResponse{status_, request.method == "HEAD" ? std::string() : body_};
  }

 private:
  long status_;
  std::string body_;
};

shadergen::CachedBlob blob_of(std::string_view payload) {
  shadergen::CachedBlob blob;
  std::size_t text = payload.empty() ? 0 : static_cast<unsigned char>(payload[0]) % 64;
  text = std::min(text, payload.size());
  blob.fell_back = text % 2 == 1;
  blob.fallback_reason = std::string(payload.substr(0, text));
  for (std::size_t i = text; i + 4 <= payload.size(); i += 4) {
    std::uint32_t word = 0;
    for (int b = 0; b < 4; ++b)
      word |= static_cast<std::uint32_t>(static_cast<unsigned char>(payload[i + b])) << (8 * b);
    blob.words.push_back(word);
  }
  if (blob.words.empty()) blob.words.push_back(0x07230203u);
  return blob;
}

std::string body_for(int mode, std::string_view payload) {
  if (mode == 0 || mode == 3) return std::string(payload);
  std::string entry = shadergen::encode_cache_entry(kKey, blob_of(payload));
  if (mode == 2) return shadergen::signed_entry(entry, kSecret);
  if (!payload.empty() && (static_cast<unsigned char>(payload[0]) & 4))
    entry[static_cast<unsigned char>(payload[0]) % entry.size()] ^= 0x20;
  return entry;
}

void check_decoders(const std::string& body) {
  if (auto blob = shadergen::decode_cache_entry(kKey, body))
    require(shadergen::encode_cache_entry(kKey, *blob) == body, "a decoded entry re-encodes to its bytes");
  if (auto entry = shadergen::verified_entry(body, kSecret))
    require(shadergen::signed_entry(*entry, kSecret) == body, "a verified body is its entry signed");
  if (auto set = shadergen::decode_input_set(kKey, body))
    require(shadergen::decode_input_set(kKey, shadergen::encode_input_set(kKey, *set)).has_value(),
            "a decoded input set re-encodes to a valid one");
}

void check_warning(const std::string& line) {
  require(line.rfind("warning: remote cache ", 0) == 0, "warnings name the remote cache");
  require(line.size() < 2000, "warnings are bounded");
  for (char c : line) require(c >= 0x20 && c < 0x7f, "warnings are printable ASCII on one line");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const int mode = data[0] & 3;
  const bool with_secret = (data[0] & 8) != 0;
  long status = static_cast<long>(data[1] | (data[2] << 8)) % 1000;
  if (data[0] & 16) status = -1;  // no answer at all
  std::string_view payload(reinterpret_cast<const char*>(data + 3), size - 3);
  const std::string body = body_for(mode, payload);
  check_decoders(body);

  shadergen::RemoteCacheSettings settings{"http://user:pw@fuzz.invalid/cache", false,
                                          with_secret ? std::string(kSecret) : std::string()};
  shadergen::RemoteCache cache(std::move(settings), std::make_unique<AnswerEverything>(status, body),
                               [](const std::string& line) { check_warning(line); });
  if (mode == 3) {
    if (auto set = cache.load_input_set(kKey)) require(with_secret, "an input set is only taken with a secret");
    return 0;
  }
  auto blob = cache.load(kKey, [](const shadergen::CachedBlob& b) { return b.words.size() % 7 == 3 ? "odd" : ""; });
  if (blob) {
    require(status == 200, "only a 200 answer gives an entry");
    std::string_view entry =
        with_secret ? shadergen::verified_entry(body, kSecret).value_or("") : shadergen::unsigned_entry(body);
    auto decoded = shadergen::decode_cache_entry(kKey, entry);
    require(decoded.has_value() && decoded->words == blob->words, "load() returns exactly what the decoder accepts");
    require(!with_secret || mode == 2, "with a secret only signed entries are used");
  }
  cache.store(kKey, blob_of(payload));
  cache.offer(kKey, blob_of(payload));
  shadergen::RemoteCacheStats stats = cache.stats();
  require(stats.fetched <= 1, "one load fetches at most one entry");
  require(shadergen::printable(body).size() <= 400 * 4 + 40, "printable() bounds its output");
  return 0;
}

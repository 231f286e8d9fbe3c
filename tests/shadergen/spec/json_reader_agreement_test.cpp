// Our spec reader (json::parse) against a second reader, nlohmann::json: on every file of the
// fuzz corpus and on a table of edge cases, both must accept the same documents and read the
// same values (types, string bytes, numbers, array items, object keys in document order).
//
// Our reader rejects on purpose what nlohmann accepts in two cases only, both documented in
// json.h and docs/spec-format.md: its limits (depth, value count, bytes) and a key that appears
// twice in one object. There the test requires our message to be exactly that limit's or
// that duplicate's message; any other disagreement is a bug in our reader.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "spec/json.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

using Theirs = nlohmann::ordered_json;

// Empty when the trees are equal, else where they first differ.
std::string difference(const json::Value& ours, const Theirs& theirs, const std::string& at);

std::string array_difference(const json::Value& ours, const Theirs& theirs, const std::string& at) {
  if (ours.array.size() != theirs.size())
    return at + ": " + std::to_string(ours.array.size()) + " items vs " + std::to_string(theirs.size());
  for (std::size_t i = 0; i < ours.array.size(); ++i)
    if (std::string d = difference(ours.array[i], theirs[i], at + "[" + std::to_string(i) + "]"); !d.empty()) return d;
  return "";
}

std::string object_difference(const json::Value& ours, const Theirs& theirs, const std::string& at) {
  if (ours.object.size() != theirs.size())
    return at + ": " + std::to_string(ours.object.size()) + " members vs " + std::to_string(theirs.size());
  auto theirs_member = theirs.items().begin();
  for (const json::Member& member : ours.object) {
    if (member.first != theirs_member.key())
      return at + ": key \"" + member.first + "\" vs \"" + theirs_member.key() + "\"";
    if (std::string d = difference(member.second, theirs_member.value(), at + "." + member.first); !d.empty()) return d;
    ++theirs_member;
  }
  return "";
}

bool same_scalar(const json::Value& ours, const Theirs& theirs) {
  switch (ours.type) {
    case json::Type::null: return theirs.is_null();
    case json::Type::boolean: return theirs.is_boolean() && theirs.get<bool>() == ours.boolean;
    case json::Type::number: return theirs.is_number() && theirs.get<double>() == ours.number;
    case json::Type::string: return theirs.is_string() && theirs.get_ref<const std::string&>() == ours.string;
    default: return false;
  }
}

std::string difference(const json::Value& ours, const Theirs& theirs, const std::string& at) {
  if (ours.type == json::Type::array)
    return theirs.is_array() ? array_difference(ours, theirs, at) : at + ": an array vs " + theirs.type_name();
  if (ours.type == json::Type::object)
    return theirs.is_object() ? object_difference(ours, theirs, at) : at + ": an object vs " + theirs.type_name();
  return same_scalar(ours, theirs) ? "" : at + ": " + json::type_name(ours.type) + " vs " + theirs.dump();
}

// What our reader's limits and duplicate rule look at, as nlohmann sees the document: its
// deepest nesting, its number of values (keys are not values) and the first key that repeats
// within its object, in document order (nlohmann itself keeps the last of two equal keys).
class DocumentFacts : public nlohmann::json_sax<Theirs> {
 public:
  std::size_t deepest = 0;
  std::size_t values = 0;
  bool has_duplicate = false;
  std::string duplicate;

  bool start_object(std::size_t) override { return keys_.emplace_back(), open(); }
  bool end_object() override { return keys_.pop_back(), --depth_, true; }
  bool start_array(std::size_t) override { return keys_.emplace_back(), open(); }
  bool end_array() override { return keys_.pop_back(), --depth_, true; }
  bool key(string_t& name) override {
    if (!has_duplicate && !keys_.back().insert(name).second) has_duplicate = true, duplicate = name;
    return true;
  }
  bool null() override { return ++values, true; }
  bool boolean(bool) override { return ++values, true; }
  bool number_integer(number_integer_t) override { return ++values, true; }
  bool number_unsigned(number_unsigned_t) override { return ++values, true; }
  bool number_float(number_float_t, const string_t&) override { return ++values, true; }
  bool string(string_t&) override { return ++values, true; }
  bool binary(binary_t&) override { return ++values, true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  bool open() {
    deepest = std::max(deepest, ++depth_);
    return ++values, true;
  }
  std::size_t depth_ = 0;
  std::vector<std::set<std::string>> keys_;  // an array's entry stays empty
};

// The messages our reader documents for a document nlohmann accepts, each only where the
// document really is over that limit or really repeats a key.
std::set<std::string> documented_rejections(const std::string& text) {
  DocumentFacts facts;
  Theirs::sax_parse(text, &facts);
  std::set<std::string> messages;
  if (facts.deepest > static_cast<std::size_t>(json::kMaxJsonDepth))
    messages.insert("nesting deeper than " + std::to_string(json::kMaxJsonDepth) + " levels");
  if (facts.values > json::kMaxJsonValues)
    messages.insert("more than " + std::to_string(json::kMaxJsonValues) + " JSON values");
  if (text.size() > json::kMaxJsonBytes)
    messages.insert("spec is " + std::to_string(text.size()) + " bytes; the limit is " +
                    std::to_string(json::kMaxJsonBytes));
  if (facts.has_duplicate) messages.insert("duplicate key \"" + facts.duplicate + "\"");
  return messages;
}

// Empty when the readers agree (or differ only as documented), else why not.
std::string disagreement(const std::string& text) {
  Result<json::Value> ours = json::parse(text, "agree.json");
  Theirs theirs = Theirs::parse(text, nullptr, false);
  if (!ours && theirs.is_discarded()) return "";
  if (ours && theirs.is_discarded()) return "only our reader accepts it";
  if (!ours) {
    const std::string& message = ours.errors().front().message;
    if (documented_rejections(text).count(message)) return "";
    return "only nlohmann accepts it; ours says: " + message;
  }
  std::string d = difference(*ours, theirs, "$");
  return d.empty() ? "" : "values differ at " + d;
}

std::string nested(int depth) {
  return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']');
}

// An array of `items` zeros: items + 1 values.
std::string zeros(std::size_t items) {
  std::string text = "[0";
  for (std::size_t i = 1; i < items; ++i) text += ",0";
  return text + "]";
}

enum class Outcome { both_accept, both_reject, ours_rejects };

struct EdgeCase {
  const char* name;
  std::string text;
  Outcome outcome;
  std::string our_message = "";  // ours_rejects: the documented message, exactly
};

void PrintTo(const EdgeCase& c, std::ostream* out) { *out << c.name; }

class JsonReaderEdgeCase : public ::testing::TestWithParam<EdgeCase> {};

TEST_P(JsonReaderEdgeCase, ReadersAgree) {
  const EdgeCase& c = GetParam();
  Result<json::Value> ours = json::parse(c.text, "agree.json");
  bool theirs_accepts = !Theirs::parse(c.text, nullptr, false).is_discarded();
  EXPECT_EQ(disagreement(c.text), "");
  switch (c.outcome) {
    case Outcome::both_accept: EXPECT_TRUE(ours && theirs_accepts); break;
    case Outcome::both_reject: EXPECT_TRUE(!ours && !theirs_accepts); break;
    case Outcome::ours_rejects:
      ASSERT_FALSE(ours);
      EXPECT_TRUE(theirs_accepts);
      EXPECT_EQ(ours.errors().front().message, c.our_message);
      break;
  }
}

const std::string kDepthMessage = "nesting deeper than 32 levels";
const std::string kValuesMessage = "more than 65536 JSON values";

INSTANTIATE_TEST_SUITE_P(
    Table, JsonReaderEdgeCase,
    ::testing::Values(
        EdgeCase{"simple_escapes", R"(["\" \\ \/ \b \f \n \r \t"])", Outcome::both_accept},
        EdgeCase{"unicode_escapes", R"(["\u0041 \u00e9 \u20AC \u0000"])", Outcome::both_accept},
        EdgeCase{"surrogate_pair", R"("\uD83D\uDE00")", Outcome::both_accept},
        EdgeCase{"lone_high_surrogate", R"("\uD83D")", Outcome::both_reject},
        EdgeCase{"high_surrogate_then_text", R"("\uD83Dx")", Outcome::both_reject},
        EdgeCase{"lone_low_surrogate", R"("\uDE00")", Outcome::both_reject},
        EdgeCase{"two_high_surrogates", R"("\uD83D\uD83D")", Outcome::both_reject},
        EdgeCase{"bad_escape", R"("\x41")", Outcome::both_reject},
        EdgeCase{"short_unicode_escape", R"("\u12")", Outcome::both_reject},
        EdgeCase{"raw_utf8", "\"caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80\"", Outcome::both_accept},
        EdgeCase{"utf8_lead_byte_alone", "\"\xC3\"", Outcome::both_reject},
        EdgeCase{"utf8_continuation_alone", "\"\x80\"", Outcome::both_reject},
        EdgeCase{"utf8_overlong_slash", "\"\xC0\xAF\"", Outcome::both_reject},
        EdgeCase{"utf8_overlong_three_bytes", "\"\xE0\x80\xAF\"", Outcome::both_reject},
        EdgeCase{"utf8_encoded_surrogate", "\"\xED\xA0\x80\"", Outcome::both_reject},
        EdgeCase{"utf8_above_u10ffff", "\"\xF4\x90\x80\x80\"", Outcome::both_reject},
        EdgeCase{"utf8_byte_ff", "\"\xFF\"", Outcome::both_reject},
        EdgeCase{"utf8_truncated_four_bytes", "\"\xF0\x9F\x98\"", Outcome::both_reject},
        EdgeCase{"raw_control_character", "\"a\x01\"", Outcome::both_reject},
        EdgeCase{"raw_newline_in_string", "\"a\nb\"", Outcome::both_reject},
        EdgeCase{"raw_tab_in_string", "\"a\tb\"", Outcome::both_reject},
        EdgeCase{"nul_byte_outside_string", std::string("[1,\0 2]", 7), Outcome::both_reject},
        EdgeCase{"big_integer", "[18446744073709551615, 18446744073709551616, -9223372036854775809]",
                 Outcome::both_accept},
        EdgeCase{"big_and_small_doubles", "[1.7976931348623157e308, 5e-324, 1e-400, 123456789012345678901234567890]",
                 Outcome::both_accept},
        EdgeCase{"overflowing_double", "[1e400]", Outcome::both_reject},
        EdgeCase{"negative_overflow", "-1e400", Outcome::both_reject},
        EdgeCase{"negative_zero", "[-0, -0.0, -0e0, 0]", Outcome::both_accept},
        EdgeCase{"exponent_forms", "[1e5, 1E5, 1e+5, 1e-5, 1.5E-0, 0e0]", Outcome::both_accept},
        EdgeCase{"exponent_without_digits", "[1e]", Outcome::both_reject},
        EdgeCase{"exponent_sign_only", "[1e+]", Outcome::both_reject},
        EdgeCase{"fraction_without_digits", "[1.]", Outcome::both_reject},
        EdgeCase{"fraction_without_integer", "[.5]", Outcome::both_reject},
        EdgeCase{"leading_zero", "[01]", Outcome::both_reject},
        EdgeCase{"leading_zero_negative", "[-01]", Outcome::both_reject},
        EdgeCase{"plus_sign", "[+1]", Outcome::both_reject}, EdgeCase{"minus_alone", "[-]", Outcome::both_reject},
        EdgeCase{"hex_number", "[0x10]", Outcome::both_reject},
        EdgeCase{"nan_and_infinity", "[NaN, Infinity]", Outcome::both_reject},
        EdgeCase{"trailing_comma_array", "[1, 2,]", Outcome::both_reject},
        EdgeCase{"trailing_comma_object", R"({"a": 1,})", Outcome::both_reject},
        EdgeCase{"missing_comma", "[1 2]", Outcome::both_reject},
        EdgeCase{"line_comment", "// note\n{}", Outcome::both_reject},
        EdgeCase{"block_comment", "{ /* note */ }", Outcome::both_reject},
        EdgeCase{"single_quotes", "['a']", Outcome::both_reject},
        EdgeCase{"unquoted_key", "{a: 1}", Outcome::both_reject},
        EdgeCase{"byte_order_mark", "\xEF\xBB\xBF{\"a\": [1]}", Outcome::both_accept},
        EdgeCase{"byte_order_mark_alone", "\xEF\xBB\xBF", Outcome::both_reject},
        EdgeCase{"broken_byte_order_mark", "\xEF\xBB{}", Outcome::both_reject},
        EdgeCase{"byte_order_mark_after_space", " \xEF\xBB\xBF{}", Outcome::both_reject},
        EdgeCase{"empty_input", "", Outcome::both_reject},
        EdgeCase{"whitespace_only", " \t\r\n ", Outcome::both_reject},
        EdgeCase{"all_whitespace_kinds", " \t\r\n[ \t\r\n1 \t\r\n] \t\r\n", Outcome::both_accept},
        EdgeCase{"form_feed_is_not_whitespace", "\f[]", Outcome::both_reject},
        EdgeCase{"text_after_document", "{} {}", Outcome::both_reject},
        EdgeCase{"truncated_object", R"({"a": )", Outcome::both_reject},
        EdgeCase{"truncated_literal", "[tru]", Outcome::both_reject},
        EdgeCase{"literal_with_suffix", "[truex]", Outcome::both_reject},
        EdgeCase{"capitalised_literal", "[True]", Outcome::both_reject},
        EdgeCase{"top_level_string", R"("text")", Outcome::both_accept},
        EdgeCase{"top_level_number", "42", Outcome::both_accept},
        EdgeCase{"top_level_null", "null", Outcome::both_accept},
        EdgeCase{"top_level_true", "true", Outcome::both_accept},
        EdgeCase{"empty_containers", R"({"a": [], "b": {}, "": ""})", Outcome::both_accept},
        EdgeCase{"keys_in_document_order", R"({"z": 1, "a": 2, "m": {"y": 3, "b": 4}})", Outcome::both_accept},
        EdgeCase{"escaped_keys", R"({"\u0061": 1, "a\nb": 2})", Outcome::both_accept},
        EdgeCase{"depth_at_limit", nested(json::kMaxJsonDepth), Outcome::both_accept},
        EdgeCase{"depth_over_limit", nested(json::kMaxJsonDepth + 1), Outcome::ours_rejects, kDepthMessage},
        EdgeCase{"values_at_limit", zeros(json::kMaxJsonValues - 1), Outcome::both_accept},
        EdgeCase{"values_over_limit", zeros(json::kMaxJsonValues), Outcome::ours_rejects, kValuesMessage},
        EdgeCase{"bytes_at_limit", "[]" + std::string(json::kMaxJsonBytes - 2, ' '), Outcome::both_accept},
        EdgeCase{"bytes_over_limit", "[]" + std::string(json::kMaxJsonBytes - 1, ' '), Outcome::ours_rejects,
                 "spec is 1048577 bytes; the limit is 1048576"},
        EdgeCase{"duplicate_key", R"({"a": 1, "b": 2, "a": 3})", Outcome::ours_rejects, R"(duplicate key "a")"},
        EdgeCase{"duplicate_key_nested", R"({"x": {"k": 1, "k": 1}})", Outcome::ours_rejects, R"(duplicate key "k")"},
        EdgeCase{"duplicate_key_spelt_differently", R"({"a": 1, "\u0061": 2})", Outcome::ours_rejects,
                 R"(duplicate key "a")"},
        EdgeCase{"same_key_in_sibling_objects", R"([{"a": 1}, {"a": 2}])", Outcome::both_accept}),
    [](const ::testing::TestParamInfo<EdgeCase>& param_info) { return std::string(param_info.param.name); });

TEST(JsonReaderAgreement, EveryFuzzCorpusFile) {
  std::size_t compared = 0;
  // shadergen's corpora only: corpus/gltf holds glTF and GLB files for tilelight's loader.
  for (const char* folder : {"domain", "cli"}) {
    const std::filesystem::path corpus = std::filesystem::path(SHADERGEN_FUZZ_CORPUS_DIR) / folder;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(corpus)) {
      if (!entry.is_regular_file()) continue;
      SCOPED_TRACE(entry.path().string());
      EXPECT_EQ(disagreement(sgtest::read_file(entry.path())), "");
      ++compared;
    }
  }
  // The corpus holds a few hundred files (tests/fuzz/corpus/domain and cli).
  EXPECT_GT(compared, 100u) << "compared " << compared << " corpus files";
  RecordProperty("corpus_files_compared", static_cast<int>(compared));
}

}  // namespace
}  // namespace shadergen

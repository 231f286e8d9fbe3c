#include "output/renumbering.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

namespace shadergen {
namespace {

// A SAX reader of the manifest's top-level "raw_features" (each entry's "name" and "kind", absent
// for a variant) and "raw" (each entry's "id" and "optimised"). It stops the parse at the end of
// "raw": the blobs after it are most of a large manifest.
class NumberingReader : public nlohmann::json_sax<nlohmann::json> {
 public:
  PreviousNumbering numbering;

  bool key(string_t& name) override {
    if (depth_ == 1)
      section_ = name == "raw_features" ? Section::features : name == "raw" ? Section::raw : Section::other;
    if (depth_ == 3) key_ = name;
    return true;
  }
  bool string(string_t& value) override {
    if (section_ == Section::features && depth_ == 3 && key_ == "name") name_ = value;
    if (section_ == Section::features && depth_ == 3 && key_ == "kind") kind_ = value;
    return true;
  }
  bool number_unsigned(number_unsigned_t value) override {
    if (section_ == Section::raw && depth_ == 3 && key_ == "id") id_ = static_cast<std::uint32_t>(value);
    if (section_ == Section::raw && depth_ == 3 && key_ == "optimised") optimised_ = static_cast<std::int64_t>(value);
    return true;
  }
  bool start_object(std::size_t) override {
    if (++depth_ == 3) name_.clear(), kind_ = "variant", optimised_ = -1;
    return true;
  }
  bool end_object() override {
    if (depth_ == 3 && section_ == Section::features && !name_.empty()) numbering.kinds[name_] = kind_;
    if (depth_ == 3 && section_ == Section::raw && optimised_ >= 0)
      numbering.table.emplace_back(id_, static_cast<std::uint32_t>(optimised_));
    --depth_;
    return true;
  }
  bool start_array(std::size_t) override {
    ++depth_;
    return true;
  }
  bool end_array() override {
    --depth_;
    return !(section_ == Section::raw && depth_ == 1);  // false: done, stop reading
  }
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  enum class Section { other, features, raw };
  int depth_ = 0;
  Section section_ = Section::other;
  std::string key_, name_, kind_;
  std::uint32_t id_ = 0;
  std::int64_t optimised_ = -1;
};

}  // namespace

PreviousNumbering previous_numbering(const std::filesystem::path& manifest_path) {
  std::ifstream in(manifest_path, std::ios::binary);
  if (!in) return {};
  NumberingReader reader;
  nlohmann::json::sax_parse(in, &reader);
  return std::move(reader.numbering);
}

Renumbering renumbering(const PreviousNumbering& previous, const DomainSpec& spec, const PermutationPlan& plan) {
  Renumbering out;
  if (!spec.collapsed || previous.table.empty()) return out;
  // Both lists ascend by raw ID (the manifest lists the plan's raw IDs in order).
  auto was = previous.table.begin();
  for (const RawPermutation& raw : plan.raw) {
    if (raw.pruned) continue;  // drawn with nothing, whatever its entry
    while (was != previous.table.end() && was->first < raw.id) ++was;
    if (was != previous.table.end() && was->first == raw.id && was->second != raw.optimised) ++out.raw_ids;
  }
  if (out.raw_ids == 0) return out;
  for (const RawFeature* f : spec.features_in_spec_order()) {
    auto kind = previous.kinds.find(f->name);
    if (kind != previous.kinds.end() && (kind->second == "variant") != f->is_variant())
      out.features.push_back(f->name + " (" + kind->second + " -> " + std::string(feature_kind_name(f->kind)) + ")");
  }
  return out;
}

}  // namespace shadergen

#include "spec/variants_file.h"

#include <algorithm>
#include <fstream>

#include "base/sha256.h"
#include "base/untrusted_text.h"
#include "shadergen/permutations.h"
#include "spec/combination_text.h"

namespace shadergen {
namespace {

// Where the file was named, for the errors about the file as a whole.
Diagnostic file_error(const DomainSpec& spec, const std::string& problem) {
  if (spec.variants_line == 0) return make_error("--variants " + spec.variants_path.string() + ": " + problem);
  return make_error(spec.spec_path.string(), spec.variants_line,
                    "\"variants_file\": " + spec.variants_path.string() + ": " + problem);
}

// The line without its comment, its line ending and the blanks around it; `first` is the
// offset of what is left within the line. parse_combination() trims blanks as well, but this
// trim stays: a blank or comment-only line must be skipped (the parser reads "" as "(none)",
// raw ID 0), the parser leaves a CRLF file's '\r', and an impossible line's error quotes the
// trimmed text at the column where it starts.
std::string_view content_of(std::string_view line, std::size_t& first) {
  if (std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  first = 0;
  while (first < line.size() && (line[first] == ' ' || line[first] == '\t')) ++first;
  std::size_t last = line.size();
  while (last > first && (line[last - 1] == ' ' || line[last - 1] == '\t' || line[last - 1] == '\r')) --last;
  return line.substr(first, last - first);
}

class VariantsReader {
 public:
  explicit VariantsReader(DomainSpec& spec) : spec_(spec), table_(spec) {}

  // One line of the file, 1-based `number`.
  void line(std::string_view text, int number) {
    std::size_t first = 0;
    std::string_view content = content_of(text, first);
    if (content.empty()) return;
    ParsedCombination parsed = parse_combination(table_.features(), content);
    if (!parsed) {
      // Past the reported lines the message (its "did you mean" search) is not even worded.
      if (errors_.size() < kMaxSpecErrors)
        error(number, first + parsed.position, describe_combination_error(parsed, table_.features()));
      return;
    }
    if (int rule = first_impossible_rule(spec_, parsed.raw_id); rule >= 0) {
      error(number, first, impossible(content, spec_.impossible[static_cast<std::size_t>(rule)]));
      return;
    }
    ids_.push_back(parsed.raw_id);
  }

  bool failed() const { return !errors_.empty(); }
  Diagnostics take_errors() { return std::move(errors_); }

  std::vector<std::uint32_t> take_ids() {
    std::sort(ids_.begin(), ids_.end());
    ids_.erase(std::unique(ids_.begin(), ids_.end()), ids_.end());
    return std::move(ids_);
  }

 private:
  std::string impossible(std::string_view content, const ImpossibleSet& rule) const {
    std::string text = "\"" + printable(content, 200) + "\" is impossible: the rule \"" + rule.when.text + "\" (" +
                       spec_.spec_path.filename().string() + ":" + std::to_string(rule.when.line) + ") prunes it";
    if (!rule.why.empty()) text += " (" + rule.why + ")";
    return text;
  }

  void error(int number, std::size_t offset, std::string message) {
    if (errors_.size() >= kMaxSpecErrors) return;
    Diagnostic d = make_error(spec_.variants_path.string(), number, std::move(message));
    d.column = static_cast<int>(offset) + 1;
    errors_.push_back(std::move(d));
  }

  DomainSpec& spec_;
  FeatureTable table_;
  std::vector<std::uint32_t> ids_;
  Diagnostics errors_;
};

}  // namespace

Result<std::string> read_variants_file(DomainSpec& spec, const std::filesystem::path& override_path) {
  if (!override_path.empty()) spec.variants_path = override_path, spec.variants_line = 0;
  spec.listed_raw_ids.clear();
  if (!spec.listed()) return std::string();
  std::error_code ec;
  if (!std::filesystem::exists(spec.variants_path, ec)) return file_error(spec, "the file does not exist");
  if (std::filesystem::is_directory(spec.variants_path, ec))
    return file_error(spec, "a directory, not a variants file");
  std::ifstream in(spec.variants_path, std::ios::binary);
  if (!in) return file_error(spec, "cannot open the file for reading");
  VariantsReader reader(spec);
  Sha256 digest;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    if (++number > kMaxVariantsLines)
      return file_error(spec, "more than " + std::to_string(kMaxVariantsLines) + " lines");
    digest.update(line).update(in.eof() ? "" : "\n");
    reader.line(line, static_cast<int>(number));
  }
  if (in.bad()) return file_error(spec, "cannot read the file");
  if (reader.failed()) return reader.take_errors();
  spec.listed_raw_ids = reader.take_ids();
  if (spec.listed_raw_ids.empty())
    return file_error(spec,
                      "lists no combination (a line such as \"(none)\" builds the raw ID with every feature off)");
  return digest.finish_hex();
}

}  // namespace shadergen

#include "compile/source_scan.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <set>
#include <string_view>

#include "base/file_io.h"

namespace shadergen {

namespace {

bool starts_identifier(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool continues_identifier(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The text with comments replaced by spaces (line breaks kept, so lines keep their numbers).
std::string without_comments(std::string_view text) {
  std::string out(text);
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] == '/' && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out[i] == '/' && out[i + 1] == '*') {
      out[i] = out[i + 1] = ' ';
      for (i += 2; i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/'); ++i)
        if (out[i] != '\n') out[i] = ' ';
      if (i < out.size()) out[i] = ' ';
      if (i + 1 < out.size()) out[i + 1] = ' ';
    }
  }
  return out;
}

std::vector<std::string_view> identifiers_in(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < line.size();) {
    if (std::isdigit(static_cast<unsigned char>(line[i]))) {  // 1.0e5f: no identifier inside a number
      while (i < line.size() && continues_identifier(line[i])) ++i;
      continue;
    }
    if (!starts_identifier(line[i])) {
      ++i;
      continue;
    }
    std::size_t start = i;
    while (i < line.size() && continues_identifier(line[i])) ++i;
    out.push_back(line.substr(start, i - start));
  }
  return out;
}

class Scanner {
 public:
  explicit Scanner(std::vector<std::filesystem::path> include_dirs) : dirs_(std::move(include_dirs)) {}

  void queue(const std::filesystem::path& file) {
    std::filesystem::path name = file.lexically_normal();
    if (seen_.insert(name).second) pending_.push_back(name);
  }

  // The files in include order, each without comments.
  std::vector<std::pair<std::filesystem::path, std::string>> texts() {
    std::vector<std::pair<std::filesystem::path, std::string>> out;
    while (!pending_.empty()) {
      std::filesystem::path file = pending_.front();
      pending_.pop_front();
      auto text = read_file(file);
      if (!text) continue;
      out.emplace_back(file, without_comments(*text));
      scan_file(file, out.back().second);  // queues its includes
    }
    return out;
  }

  SourceScan run() {
    while (!pending_.empty()) {
      std::filesystem::path file = pending_.front();
      pending_.pop_front();
      if (auto text = read_file(file)) scan_file(file, without_comments(*text));
    }
    return std::move(scan_);
  }

 private:
  void scan_file(const std::filesystem::path& file, const std::string& text) {
    int number = 0;
    for (std::size_t start = 0; start <= text.size();) {
      std::size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      std::string_view line = std::string_view(text).substr(start, end - start);
      ++number;
      SourceLocation at{file, number};
      for (std::string_view id : identifiers_in(line)) scan_.identifiers.try_emplace(std::string(id), at);
      if (std::size_t first = line.find_first_not_of(" \t\r"); first != std::string_view::npos && line[first] == '#')
        directive(line.substr(first + 1), file, at);
      start = end + 1;
    }
  }

  void directive(std::string_view rest, const std::filesystem::path& file, const SourceLocation& at) {
    std::vector<std::string_view> words = identifiers_in(rest);
    if (words.empty()) return;
    const std::string_view name = words.front();
    if (name == "include") return include(rest, file);
    if ((name == "ifdef" || name == "ifndef") && words.size() > 1)
      scan_.tests.push_back({std::string(words[1]), "#" + std::string(name), at});
    if (name != "if" && name != "elif") return;
    for (std::size_t i = 1; i < words.size(); ++i) {
      if (words[i] == "defined") {
        if (i + 1 < words.size()) scan_.tests.push_back({std::string(words[++i]), "defined()", at});
        continue;
      }
      scan_.tests.push_back({std::string(words[i]), "#" + std::string(name), at});
    }
  }

  void include(std::string_view rest, const std::filesystem::path& file) {
    std::size_t open = rest.find_first_of("\"<");
    if (open == std::string_view::npos) return;
    std::size_t close = rest.find(rest[open] == '"' ? '"' : '>', open + 1);
    if (close == std::string_view::npos) return;
    std::filesystem::path header(std::string(rest.substr(open + 1, close - open - 1)));
    std::error_code ec;
    if (rest[open] == '"' && std::filesystem::is_regular_file(file.parent_path() / header, ec))
      return queue(file.parent_path() / header);
    for (const std::filesystem::path& dir : dirs_)
      if (std::filesystem::is_regular_file(dir / header, ec)) return queue(dir / header);
  }

  std::vector<std::filesystem::path> dirs_;
  std::set<std::filesystem::path> seen_;
  std::deque<std::filesystem::path> pending_;
  SourceScan scan_;
};

}  // namespace

std::optional<SourceLocation> input_declaration(const std::string& name,
                                                const std::vector<std::filesystem::path>& files,
                                                const std::vector<std::filesystem::path>& include_dirs) {
  Scanner scanner(include_dirs);
  for (const std::filesystem::path& file : files) scanner.queue(file);
  for (const auto& [file, text] : scanner.texts()) {
    int number = 0;
    for (std::size_t start = 0; start <= text.size();) {
      std::size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      ++number;
      std::vector<std::string_view> ids = identifiers_in(std::string_view(text).substr(start, end - start));
      if (std::find(ids.begin(), ids.end(), name) != ids.end() && std::find(ids.begin(), ids.end(), "in") != ids.end())
        return SourceLocation{file, number};
      start = end + 1;
    }
  }
  return std::nullopt;
}

SourceScan scan_sources(const std::vector<std::filesystem::path>& files,
                        const std::vector<std::filesystem::path>& include_dirs) {
  Scanner scanner(include_dirs);
  for (const std::filesystem::path& file : files) scanner.queue(file);
  return scanner.run();
}

}  // namespace shadergen

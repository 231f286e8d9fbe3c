// Replays fuzz inputs through a fuzz entry point without libFuzzer, so any compiler (GCC in
// CI) and the sanitizer build run the checked-in corpus as a test.
//
// Usage: <replay> FILE_OR_FOLDER...  Every regular file (folders: every file inside, sorted)
// is passed once to LLVMFuzzerTestOneInput. A crash or a violated property aborts the process
// after the file's name is printed; otherwise it prints how many inputs ran.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

// Absolute paths, collected before the first input runs: an entry point may change the
// working directory (the CLI fuzzer works inside a scratch folder).
std::vector<fs::path> collect_inputs(int argc, char** argv) {
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    fs::path arg = fs::absolute(argv[i]);
    if (!fs::is_directory(arg)) {
      inputs.push_back(arg);
      continue;
    }
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(arg))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    inputs.insert(inputs.end(), files.begin(), files.end());
  }
  return inputs;
}

bool read_file(const fs::path& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE_OR_FOLDER...\n", argv[0]);
    return 2;
  }
  std::vector<fs::path> inputs = collect_inputs(argc, argv);
  if (inputs.empty()) {
    std::fprintf(stderr, "replay: error: no input files\n");
    return 1;
  }
  for (const fs::path& path : inputs) {
    std::string bytes;
    if (!read_file(path, bytes)) {
      std::fprintf(stderr, "replay: error: cannot read %s\n", path.c_str());
      return 1;
    }
    // Printed first so a crash report is preceded by the input that caused it.
    std::fprintf(stderr, "replay: %s (%zu bytes)\n", path.filename().c_str(), bytes.size());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("replay: %zu inputs, no finding\n", inputs.size());
  return 0;
}

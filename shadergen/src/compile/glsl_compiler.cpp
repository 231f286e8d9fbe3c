#include "compile/glsl_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <memory>
#include <mutex>
#include <regex>
#include <sstream>

#include "base/file_io.h"
#include "base/sha256.h"
#include "base/untrusted_text.h"
#include "spec/defines.h"
#include "spec/kind_declarations.h"

namespace shadergen {
namespace {

// glslang needs one process-wide initialisation; FinalizeProcess is left to process exit
// because other threads may still be compiling when the first caller returns.
void initialise_glslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage to_glslang(Stage stage) {
  switch (stage) {
    case Stage::vertex: return EShLangVertex;
    case Stage::tess_control: return EShLangTessControl;
    case Stage::tess_evaluation: return EShLangTessEvaluation;
    case Stage::geometry: return EShLangGeometry;
    case Stage::fragment: return EShLangFragment;
    case Stage::compute: return EShLangCompute;
    case Stage::task: return EShLangTask;
    case Stage::mesh: return EShLangMesh;
    case Stage::ray_generation: return EShLangRayGen;
    case Stage::any_hit: return EShLangAnyHit;
    case Stage::closest_hit: return EShLangClosestHit;
    case Stage::miss: return EShLangMiss;
    case Stage::intersection: return EShLangIntersect;
    case Stage::callable: return EShLangCallable;
  }
  return EShLangFragment;
}

glslang::EShTargetClientVersion client_version(TargetEnv env) {
  switch (env) {
    case TargetEnv::vulkan1_0: return glslang::EShTargetVulkan_1_0;
    case TargetEnv::vulkan1_1: return glslang::EShTargetVulkan_1_1;
    case TargetEnv::vulkan1_2: return glslang::EShTargetVulkan_1_2;
    case TargetEnv::vulkan1_3: return glslang::EShTargetVulkan_1_3;
  }
  return glslang::EShTargetVulkan_1_2;
}

glslang::EShTargetLanguageVersion spirv_version(TargetEnv env) {
  switch (env) {
    case TargetEnv::vulkan1_0: return glslang::EShTargetSpv_1_0;
    case TargetEnv::vulkan1_1: return glslang::EShTargetSpv_1_3;
    case TargetEnv::vulkan1_2: return glslang::EShTargetSpv_1_5;
    case TargetEnv::vulkan1_3: return glslang::EShTargetSpv_1_6;
  }
  return glslang::EShTargetSpv_1_5;
}

// Resolves "local" includes against the including file's folder, then the include dirs;
// <system> includes against the include dirs only. Keeps each file's text alive until
// glslang releases it and remembers every file it opened.
class RecordingIncluder final : public glslang::TShader::Includer {
 public:
  RecordingIncluder(std::filesystem::path main_file, std::vector<std::filesystem::path> dirs)
      : main_file_(std::move(main_file)), dirs_(std::move(dirs)) {}

  IncludeResult* includeLocal(const char* header, const char* includer, std::size_t depth) override {
    if (depth > kMaxIncludeDepth) return too_deep();
    std::filesystem::path from = includer && *includer ? std::filesystem::path(includer) : main_file_;
    return open(from.parent_path() / header);
  }

  IncludeResult* includeSystem(const char* header, const char*, std::size_t depth) override {
    if (depth > kMaxIncludeDepth) return too_deep();
    for (const auto& dir : dirs_)
      if (IncludeResult* found = open(dir / header)) return found;
    return nullptr;
  }

  // glslang sets no limit of its own: a file that includes itself without a guard would
  // recurse until memory runs out. A result without a header name is reported by glslang as an
  // error at the #include line, with this text.
  static constexpr std::size_t kMaxIncludeDepth = 64;
  IncludeResult* too_deep() {
    static const std::string message =
        "#include nested more than " + std::to_string(kMaxIncludeDepth) + " deep: an include cycle?";
    return new IncludeResult("", message.data(), message.size(), nullptr);
  }

  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

  std::vector<std::filesystem::path> take_hits() { return std::move(hits_); }
  std::vector<InputRead> take_reads() { return std::move(reads_); }

 private:
  // A probe that finds nothing is recorded too: a file created there later would change
  // what this include resolves to.
  IncludeResult* open(const std::filesystem::path& candidate) {
    std::error_code ec;
    std::filesystem::path name = candidate.lexically_normal();
    auto text = std::filesystem::is_regular_file(candidate, ec) ? read_file(candidate)
                                                                : Result<std::string>(make_error("absent"));
    if (!text) {
      reads_.push_back({name, false, {}});
      return nullptr;
    }
    auto* owned = new std::string(std::move(text).value());
    hits_.push_back(name);
    reads_.push_back({name, true, sha256_hex(*owned)});
    return new IncludeResult(name.string(), owned->data(), owned->size(), owned);
  }

  std::filesystem::path main_file_;
  std::vector<std::filesystem::path> dirs_;
  std::vector<std::filesystem::path> hits_;
  std::vector<InputRead> reads_;
};

std::string make_preamble(const GlslSource& source) {
  // The include extension is switched on here so that shader files need not name it.
  std::string preamble = "#extension GL_GOOGLE_include_directive : require\n";
  for (const std::string& define : source.fixed_defines) preamble += define_line(define);
  for (const std::string& define : source.defines) preamble += define_line(define);
  return preamble + source.kind_macros;
}

// glslang names the token at fault first ("'x' : undeclared identifier"); with no token it
// writes "'' :  syntax error, ...": the empty quotes and the doubled space go.
Diagnostic tidied(Diagnostic d) {
  constexpr std::string_view kNoToken = "'' :";
  if (std::string_view(d.message).substr(0, kNoToken.size()) != kNoToken) return d;
  std::size_t start = d.message.find_first_not_of(' ', kNoToken.size());
  d.message = start == std::string::npos ? std::string() : d.message.substr(start);
  return d;
}

// glslang's log has lines like "ERROR: uber/lighting.frag:212: 'x' : undeclared identifier".
Diagnostics parse_log(const std::string& log, const std::string& fallback_file) {
  static const std::regex located(R"(^(ERROR|WARNING): (.+?):(\d+): (.*)$)");
  static const std::regex unlocated(R"(^(ERROR|WARNING): (.*)$)");
  Diagnostics out;
  std::istringstream lines(log);
  std::string line;
  bool in_error = false;  // the last message line was an error's
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_match(line, m, located)) {
      in_error = m[1] == "ERROR";
      // The shader's own bytes reach the message (an unexpected token): shown escaped.
      if (in_error) out.push_back(make_error(m[2], std::stoi(m[3]), printable(m[4].str())));
    } else if (std::regex_match(line, m, unlocated)) {
      std::string text = m[2];
      // Summary lines ("1 compilation errors.  No code generated.") add nothing.
      in_error = m[1] == "ERROR" && text.find("compilation errors") == std::string::npos;
      if (in_error) out.push_back(make_error(fallback_file, 0, printable(text)));
    } else if (in_error && !line.empty() && !out.empty()) {
      // A message's continuation: "Possible extensions include:" lists them on the lines after.
      std::string& message = out.back().message;
      while (!message.empty() && message.back() == ' ') message.pop_back();
      message += (message.empty() || message.back() == ':' ? " " : ", ") + printable(line);
    }
  }
  // After a real error glslang adds follow-on noise: "compilation terminated" and, because
  // it stopped inside an #ifdef, "missing #endif". Keep those only if nothing else was said.
  Diagnostics real;
  for (Diagnostic& d : out) {
    while (!d.message.empty() && d.message.back() == ' ') d.message.pop_back();
    bool noise = d.message == "'' : compilation terminated" || d.message == "'' : missing #endif";
    if (!noise) real.push_back(tidied(std::move(d)));
  }
  if (!real.empty()) return real;
  if (out.empty()) out.push_back(make_error(fallback_file, 0, "glslang failed without a message"));
  return out;
}

constexpr auto kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

// Everything a glslang::TShader borrows must outlive it, so it lives in one object.
struct ShaderJob {
  explicit ShaderJob(const GlslSource& source)
      : name(source.path.lexically_normal().string()),
        preamble(make_preamble(source)),
        includer(source.path, source.include_dirs),
        shader(std::make_unique<glslang::TShader>(to_glslang(source.stage))) {}

  Status load(const GlslSource& source) {
    auto loaded = read_file(source.path);
    if (!loaded) return std::move(loaded).take_errors();
    file_text = std::move(loaded).value();
    text = insert_declarations(file_text, source.kind_declarations);
    // glslang keeps these pointers (not copies) until it is done, so they are members.
    strings[0] = text.c_str();
    lengths[0] = static_cast<int>(text.size());
    names[0] = name.c_str();
    shader->setStringsWithLengthsAndNames(strings, lengths, names, 1);
    shader->setPreamble(preamble.c_str());
    EShLanguage stage = to_glslang(source.stage);
    shader->setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader->setEnvClient(glslang::EShClientVulkan, client_version(source.target));
    shader->setEnvTarget(glslang::EShTargetSpv, spirv_version(source.target));
    shader->setEntryPoint("main");
    return Ok{};
  }

  std::string name;
  std::string preamble;
  std::string file_text;  // the file as read (its hash is the input's)
  std::string text;       // what glslang reads: the file with the kind declarations
  const char* strings[1] = {};
  int lengths[1] = {};
  const char* names[1] = {};
  RecordingIncluder includer;
  std::unique_ptr<glslang::TShader> shader;
};

}  // namespace

Result<Preprocessed> preprocess(const GlslSource& source) {
  initialise_glslang();
  ShaderJob job(source);
  if (Status loaded = job.load(source); !loaded) return std::move(loaded).take_errors();
  Preprocessed out;
  if (!job.shader->preprocess(GetDefaultResources(), 450, ENoProfile, false, false, kMessages, &out.text, job.includer))
    return parse_log(job.shader->getInfoLog(), job.name);
  out.includes = job.includer.take_hits();
  out.reads.push_back({source.path.lexically_normal(), true, sha256_hex(job.file_text)});
  for (InputRead& read : job.includer.take_reads()) out.reads.push_back(std::move(read));
  return out;
}

Result<std::vector<std::uint32_t>> compile(const GlslSource& source) {
  initialise_glslang();
  ShaderJob job(source);
  if (Status loaded = job.load(source); !loaded) return std::move(loaded).take_errors();
  if (!job.shader->parse(GetDefaultResources(), 450, ENoProfile, false, false, kMessages, job.includer))
    return parse_log(job.shader->getInfoLog(), job.name);
  glslang::TProgram program;
  program.addShader(job.shader.get());
  if (!program.link(kMessages)) return parse_log(program.getInfoLog(), job.name);
  std::vector<unsigned int> words;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // SPIRV-Tools runs afterwards, with validation around it
  glslang::GlslangToSpv(*program.getIntermediate(to_glslang(source.stage)), words, &logger, &options);
  std::string messages = logger.getAllMessages();
  if (words.empty()) return make_error(job.name, 0, "SPIR-V generation failed: " + messages);
  return std::vector<std::uint32_t>(words.begin(), words.end());
}

}  // namespace shadergen

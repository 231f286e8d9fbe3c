#include "cache/curl_library.h"

#include <dlfcn.h>

#include <string>

namespace shadergen {
namespace {

// The SONAME libcurl has kept since 7.16 (2006), whichever TLS flavour Debian installed.
constexpr const char* kLibrary = "libcurl.so.4";

// Resolves `name` into `function`; false, with the reason in `error`, if it is missing.
template <class Function>
bool resolve(void* library, const char* soname, const char* name, Function& function, std::string& error) {
  void* symbol = dlsym(library, name);
  if (symbol == nullptr) {
    error = std::string(soname) + " has no " + name;
    return false;
  }
  function = reinterpret_cast<Function>(symbol);
  return true;
}

}  // namespace

Result<const CurlLibrary*> load_curl_library(const char* soname) {
  void* library = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* why = dlerror();
    return make_error(std::string("cannot load ") + soname + " for the remote cache: " + (why ? why : "dlopen failed"));
  }
  static CurlLibrary curl{};
  std::string error;
  auto resolve_into = [&](const char* name, auto& function) { return resolve(library, soname, name, function, error); };
  bool ok =
      resolve_into("curl_global_init", curl.global_init) && resolve_into("curl_easy_init", curl.easy_init) &&
      resolve_into("curl_easy_setopt", curl.easy_setopt) && resolve_into("curl_easy_perform", curl.easy_perform) &&
      resolve_into("curl_easy_getinfo", curl.easy_getinfo) && resolve_into("curl_easy_reset", curl.easy_reset) &&
      resolve_into("curl_easy_cleanup", curl.easy_cleanup) && resolve_into("curl_easy_strerror", curl.easy_strerror) &&
      resolve_into("curl_slist_append", curl.slist_append) && resolve_into("curl_slist_free_all", curl.slist_free_all);
  if (!ok) return make_error(error);
  // Not thread-safe in every libcurl version: once, here, before any request.
  if (CURLcode code = curl.global_init(CURL_GLOBAL_DEFAULT); code != CURLE_OK)
    return make_error(std::string("curl_global_init failed: ") + curl.easy_strerror(code));
  return &curl;
}

Result<const CurlLibrary*> curl_library() {
  static const Result<const CurlLibrary*> loaded = load_curl_library(kLibrary);
  return loaded;
}

}  // namespace shadergen

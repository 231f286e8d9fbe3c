#include "cache/curl_library.h"

#include <dlfcn.h>

#include <string>

namespace shadergen {
namespace {

// The SONAME libcurl has kept since 7.16 (2006), whichever TLS flavour Debian installed.
constexpr const char* kLibrary = "libcurl.so.4";

// Resolves `name` into `function`; false, with the reason in `error`, if it is missing.
template <class Function>
bool resolve(void* library, const char* name, Function& function, std::string& error) {
  void* symbol = dlsym(library, name);
  if (symbol == nullptr) {
    error = std::string(kLibrary) + " has no " + name;
    return false;
  }
  function = reinterpret_cast<Function>(symbol);
  return true;
}

Result<const CurlLibrary*> load() {
  void* library = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* why = dlerror();
    return make_error(std::string("cannot load ") + kLibrary +
                      " for the remote cache: " + (why ? why : "dlopen failed"));
  }
  static CurlLibrary curl{};
  std::string error;
  bool ok = resolve(library, "curl_global_init", curl.global_init, error) &&
            resolve(library, "curl_easy_init", curl.easy_init, error) &&
            resolve(library, "curl_easy_setopt", curl.easy_setopt, error) &&
            resolve(library, "curl_easy_perform", curl.easy_perform, error) &&
            resolve(library, "curl_easy_getinfo", curl.easy_getinfo, error) &&
            resolve(library, "curl_easy_reset", curl.easy_reset, error) &&
            resolve(library, "curl_easy_cleanup", curl.easy_cleanup, error) &&
            resolve(library, "curl_easy_strerror", curl.easy_strerror, error) &&
            resolve(library, "curl_slist_append", curl.slist_append, error) &&
            resolve(library, "curl_slist_free_all", curl.slist_free_all, error);
  if (!ok) return make_error(error);
  // Not thread-safe in every libcurl version: once, here, before any request.
  if (CURLcode code = curl.global_init(CURL_GLOBAL_DEFAULT); code != CURLE_OK)
    return make_error(std::string("curl_global_init failed: ") + curl.easy_strerror(code));
  return &curl;
}

}  // namespace

Result<const CurlLibrary*> curl_library() {
  static const Result<const CurlLibrary*> loaded = load();
  return loaded;
}

}  // namespace shadergen

// curl_library.h - the libcurl functions the remote cache's HTTP client calls, loaded with
// dlopen on first use instead of linked. libcurl and the thirty-odd libraries it pulls in
// (TLS, Kerberos, LDAP, ...) cost every shadergen process about 17 ms to load, a quarter of a
// warm build, and only a build with a remote cache sends a request.
#pragma once

#include <curl/curl.h>

#include "shadergen/diagnostic.h"

namespace shadergen {

struct CurlLibrary {
  CURLcode (*global_init)(long flags);
  CURL* (*easy_init)();
  CURLcode (*easy_setopt)(CURL* handle, CURLoption option, ...);
  CURLcode (*easy_perform)(CURL* handle);
  CURLcode (*easy_getinfo)(CURL* handle, CURLINFO info, ...);
  void (*easy_reset)(CURL* handle);
  void (*easy_cleanup)(CURL* handle);
  const char* (*easy_strerror)(CURLcode code);
  curl_slist* (*slist_append)(curl_slist* list, const char* text);
  void (*slist_free_all)(curl_slist* list);
};

// libcurl (SONAME libcurl.so.4) with every function above resolved and curl_global_init done,
// or an error naming the library and what dlopen or dlsym said. Loaded once, on the first call
// (thread-safe), and never unloaded; a failed load is not retried.
Result<const CurlLibrary*> curl_library();

// What curl_library() does, for the library `soname` and without keeping the result: the tests'
// way to see a failed load. Every successful call fills the same table, so call it only for a
// library that is not libcurl, or before any client exists.
Result<const CurlLibrary*> load_curl_library(const char* soname);

}  // namespace shadergen

// The HttpClient of a real build: libcurl's easy interface, one handle per concurrent request,
// handles reused so that a build's hundreds of small requests share a few connections. libcurl
// is loaded when the first client is made (cache/curl_library.h says why).
#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <vector>

#include "cache/curl_library.h"
#include "cache/http_client.h"

namespace shadergen {
namespace {

// Larger than any valid cache entry (cache.cpp caps the payload at 256 MiB); a longer body is
// garbage and is cut off instead of filling memory.
constexpr curl_off_t kMaxBody = curl_off_t{300} << 20;

std::size_t append_body(char* data, std::size_t size, std::size_t count, void* user) {
  auto* body = static_cast<std::string*>(user);
  std::size_t bytes = size * count;
  if (static_cast<curl_off_t>(body->size() + bytes) > kMaxBody) return 0;  // aborts the transfer
  body->append(data, bytes);
  return bytes;
}

std::size_t read_body(char* buffer, std::size_t size, std::size_t count, void* user) {
  auto* rest = static_cast<std::string_view*>(user);
  std::size_t bytes = std::min(size * count, rest->size());
  rest->copy(buffer, bytes);
  rest->remove_prefix(bytes);
  return bytes;
}

// libcurl itself reads no environment for TLS trust; these are the variables the curl tool and
// OpenSSL honour, so a private CA is configured for shadergen as for curl.
void set_ca_bundle(const CurlLibrary& curl, CURL* handle) {
  for (const char* variable : {"CURL_CA_BUNDLE", "SSL_CERT_FILE"})
    if (const char* file = std::getenv(variable); file && *file) {
      curl.easy_setopt(handle, CURLOPT_CAINFO, file);
      break;
    }
  if (const char* dir = std::getenv("SSL_CERT_DIR"); dir && *dir) curl.easy_setopt(handle, CURLOPT_CAPATH, dir);
}

class CurlHttpClient final : public HttpClient {
 public:
  // A client whose library did not load answers every request with that error, which the
  // remote cache reports like an unreachable server.
  CurlHttpClient(HttpTimeouts timeouts, Result<const CurlLibrary*> curl)
      : timeouts_(timeouts), curl_(std::move(curl)) {}
  ~CurlHttpClient() override {
    for (CURL* handle : idle_) (*curl_)->easy_cleanup(handle);
  }

  Result<HttpResponse> send(const HttpRequest& request) override {
    if (!curl_) return curl_.errors();
    const CurlLibrary& curl = **curl_;
    std::string_view rest = request.body;
    return perform(curl, request, [&](CURL* handle) {
      if (request.method == "HEAD") {
        curl.easy_setopt(handle, CURLOPT_NOBODY, 1L);
      } else if (request.method == "PUT") {
        curl.easy_setopt(handle, CURLOPT_UPLOAD, 1L);
        curl.easy_setopt(handle, CURLOPT_READFUNCTION, read_body);
        curl.easy_setopt(handle, CURLOPT_READDATA, &rest);
        curl.easy_setopt(handle, CURLOPT_INFILESIZE_LARGE, static_cast<curl_off_t>(request.body.size()));
      } else if (request.method != "GET") {
        curl.easy_setopt(handle, CURLOPT_CUSTOMREQUEST, std::string(request.method).c_str());
      }
    });
  }

 private:
  template <class Configure>
  Result<HttpResponse> perform(const CurlLibrary& curl, const HttpRequest& request, Configure configure) {
    CURL* handle = acquire(curl);
    if (!handle) return make_error("cannot create an HTTP request (curl_easy_init failed)");
    HttpResponse response;
    char error[CURL_ERROR_SIZE] = {};
    // No "Expect: 100-continue" round trip before each upload: entries are small.
    curl_slist* headers = curl.slist_append(nullptr, "Expect:");
    curl.easy_setopt(handle, CURLOPT_URL, request.url.c_str());
    curl.easy_setopt(handle, CURLOPT_HTTPHEADER, headers);
    curl.easy_setopt(handle, CURLOPT_NOSIGNAL, 1L);  // timeouts without SIGALRM: we are threaded
    curl.easy_setopt(handle, CURLOPT_CONNECTTIMEOUT_MS,
                     static_cast<long>(std::min(timeouts_.connect, request.timeout).count()));
    curl.easy_setopt(handle, CURLOPT_TIMEOUT_MS, static_cast<long>(std::min(timeouts_.total, request.timeout).count()));
    // Credentials need not be in the URL (where they would reach logs): ~/.netrc has them.
    curl.easy_setopt(handle, CURLOPT_NETRC, static_cast<long>(CURL_NETRC_OPTIONAL));
    set_ca_bundle(curl, handle);
    curl.easy_setopt(handle, CURLOPT_WRITEFUNCTION, append_body);
    curl.easy_setopt(handle, CURLOPT_WRITEDATA, &response.body);
    curl.easy_setopt(handle, CURLOPT_ERRORBUFFER, error);
    configure(handle);
    CURLcode code = curl.easy_perform(handle);
    curl.easy_getinfo(handle, CURLINFO_RESPONSE_CODE, &response.status);
    curl.slist_free_all(headers);
    release(curl, handle);
    if (code != CURLE_OK) return make_error(error[0] ? std::string(error) : curl.easy_strerror(code));
    return response;
  }

  // A reset handle keeps its connection cache: the next request to the server reuses it.
  CURL* acquire(const CurlLibrary& curl) {
    {
      std::lock_guard lock(mutex_);
      if (!idle_.empty()) {
        CURL* handle = idle_.back();
        idle_.pop_back();
        return handle;
      }
    }
    return curl.easy_init();
  }

  void release(const CurlLibrary& curl, CURL* handle) {
    curl.easy_reset(handle);
    std::lock_guard lock(mutex_);
    idle_.push_back(handle);
  }

  HttpTimeouts timeouts_;
  Result<const CurlLibrary*> curl_;
  std::mutex mutex_;
  std::vector<CURL*> idle_;
};

}  // namespace

std::unique_ptr<HttpClient> make_curl_http_client(HttpTimeouts timeouts) {
  return std::make_unique<CurlHttpClient>(timeouts, curl_library());
}

}  // namespace shadergen

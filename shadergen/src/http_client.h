// http_client.h - the two HTTP requests the remote cache makes, behind an interface so that
// its verification and degradation rules can be tested without a server.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <string_view>

#include "shadergen/diagnostic.h"

namespace shadergen {

// A completed exchange: any status the server sent, 404 and 500 included.
struct HttpResponse {
  long status = 0;
  std::string body;
};

// Thread-safe: the remote cache calls it from every compile thread at once. A request that got
// no response (refused, reset, timed out, bad URL) is an error whose message says why.
class HttpClient {
 public:
  virtual ~HttpClient() = default;
  virtual Result<HttpResponse> get(const std::string& url) = 0;
  virtual Result<HttpResponse> put(const std::string& url, std::string_view body) = 0;
};

// Every request is bounded: a server that accepts the connection and then stalls costs at most
// `total` per request, one that does not answer the connection at most `connect`.
struct HttpTimeouts {
  std::chrono::milliseconds connect{2000};
  std::chrono::milliseconds total{10000};
};

// libcurl, with connections kept alive between requests.
std::unique_ptr<HttpClient> make_curl_http_client(HttpTimeouts timeouts = {});

}  // namespace shadergen

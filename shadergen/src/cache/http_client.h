// http_client.h - the HTTP requests the remote cache makes (GET, HEAD, PUT, MKCOL), behind an
// interface so that its verification and degradation rules can be tested without a server.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <string_view>

#include "shadergen/diagnostic.h"

namespace shadergen {

// The client's own limits when nobody sets them (HttpTimeouts, below): their one definition.
inline constexpr std::chrono::milliseconds kDefaultHttpConnectTimeout{2000};
inline constexpr std::chrono::milliseconds kDefaultHttpTotalTimeout{10000};

// A completed exchange: any status the server sent, 404 and 500 included.
struct HttpResponse {
  long status = 0;
  std::string body;
};

struct HttpRequest {
  std::string_view method;  // "GET", "HEAD", "PUT" or "MKCOL"
  const std::string& url;
  std::string_view body;  // PUT only
  // The whole exchange, connection included, may take at most this long (the client's own
  // limits still apply): the remote cache shortens it as its time budget runs out.
  std::chrono::milliseconds timeout = kDefaultHttpTotalTimeout;
};

// Thread-safe: the remote cache calls it from every compile thread at once. A request that got
// no response (refused, reset, timed out, bad URL) is an error whose message says why.
class HttpClient {
 public:
  virtual ~HttpClient() = default;
  virtual Result<HttpResponse> send(const HttpRequest& request) = 0;
};

// Every request is bounded: a server that accepts the connection and then stalls costs at most
// `total` per request, one that does not answer the connection at most `connect`.
struct HttpTimeouts {
  std::chrono::milliseconds connect = kDefaultHttpConnectTimeout;
  std::chrono::milliseconds total = kDefaultHttpTotalTimeout;
};

// libcurl, with connections kept alive between requests. Credentials come from the URL or,
// when it has none, from ~/.netrc (libcurl's netrc lookup, $NETRC naming another file); TLS
// trusts the system CAs, or the bundle named by $CURL_CA_BUNDLE or $SSL_CERT_FILE.
std::unique_ptr<HttpClient> make_curl_http_client(HttpTimeouts timeouts = {});

}  // namespace shadergen

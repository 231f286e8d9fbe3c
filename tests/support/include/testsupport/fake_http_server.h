// fake_http_server.h - a small HTTP/1.1 server for the remote-cache tests' hostile cases and
// the remote benchmark's slow server: on 127.0.0.1 at a free port, in threads of the calling
// process, answering every request through a function the caller gives (any status, any body,
// after any delay: a slow server, junk, foreign entries, escape sequences). One request per
// connection ("Connection: close"); a thread per connection, so a slow answer does not hold up
// the others. The destructor stops accepting and joins every thread (each waits at most its own
// delay).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace testsupport {

struct FakeRequest {
  std::string method, path;                    // "GET", "/cache/ab/ab..."
  std::map<std::string, std::string> headers;  // names lower-cased
  std::string body;
};

struct FakeReply {
  int status = 404;
  std::string body;
  std::chrono::milliseconds delay{0};  // before the answer is sent
};

class FakeHttpServer {
 public:
  using Handler = std::function<FakeReply(const FakeRequest&)>;

  explicit FakeHttpServer(Handler handler);
  ~FakeHttpServer();
  FakeHttpServer(const FakeHttpServer&) = delete;
  FakeHttpServer& operator=(const FakeHttpServer&) = delete;

  bool running() const { return port_ != 0; }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/cache"; }
  std::uint16_t port() const { return port_; }
  // Every request so far, in arrival order.
  std::vector<FakeRequest> requests() const;

 private:
  void accept_loop();
  void serve(int fd);

  Handler handler_;
  int listener_ = -1;
  std::uint16_t port_ = 0;
  std::atomic<bool> stopping_{false};
  std::thread acceptor_;
  mutable std::mutex mutex_;
  std::vector<std::thread> connections_;
  std::vector<FakeRequest> requests_;
};

}  // namespace testsupport

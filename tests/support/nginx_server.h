// A private nginx for the remote-cache tests and benchmark: Debian's nginx, WebDAV PUT on, on
// 127.0.0.1 at a free port, its config, stored objects, logs, pid file and temporaries all under
// one folder the caller names. It runs in the foreground as one process (no master/worker
// pair), a child of the caller: killing that child kills the server, and the destructor does it
// even when a test fails halfway.
//
// Header-only, like child_process.h: each executable that uses it adds tests/support to its
// include path.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

#include "child_process.h"

namespace testsupport {

enum class NginxMode {
  webdav,  // GET and PUT under /cache/, PUT creating the folders it needs
  errors,  // every request answered 500 (a broken server behind a working socket)
};

// nginx on PATH, else Debian's /usr/sbin/nginx (not on a normal user's PATH); empty if neither.
inline std::filesystem::path find_nginx() {
  if (const char* path = std::getenv("PATH")) {
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':'))
      if (!dir.empty() && ::access((std::filesystem::path(dir) / "nginx").c_str(), X_OK) == 0)
        return std::filesystem::path(dir) / "nginx";
  }
  if (::access("/usr/sbin/nginx", X_OK) == 0) return "/usr/sbin/nginx";
  return {};
}

// A port on 127.0.0.1 that was free a moment ago: bound with port 0, read back, closed. Nobody
// listens on it until someone binds it again, so it also serves as "a closed port".
inline std::uint16_t unused_local_port() {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof address;
  std::uint16_t port = 0;
  if (fd >= 0 && ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size) == 0)
    port = ntohs(address.sin_port);
  if (fd >= 0) ::close(fd);
  return port;
}

inline bool accepts_connections(std::uint16_t port) {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return false;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(port);
  bool connected = ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(fd);
  return connected;
}

// True once `pid` has exited (a zombie not yet reaped), without reaping it.
inline bool exited(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_field, name, state;
  stat >> pid_field >> name >> state;
  return !stat || state == "Z";
}

class NginxServer {
 public:
  // Starts the server under `root` (created; its old contents stay). running() says whether
  // it came up, error() why not.
  explicit NginxServer(const std::filesystem::path& root, NginxMode mode = NginxMode::webdav)
      : root_(std::filesystem::absolute(root)) {
    std::filesystem::path nginx = find_nginx();
    if (nginx.empty()) {
      error_ =
          "nginx is not installed (not on PATH, not /usr/sbin/nginx): the remote-cache tests need "
          "Debian's nginx package; scripts/install-deps.sh installs it";
      return;
    }
    for (const char* dir : {"data/cache", "tmp", "logs"}) std::filesystem::create_directories(root_ / dir);
    // Another process may take the port between our probe and nginx's bind: try a few.
    for (int attempt = 0; attempt < 5 && !running(); ++attempt) start(nginx, mode);
  }
  ~NginxServer() { kill(); }
  NginxServer(const NginxServer&) = delete;
  NginxServer& operator=(const NginxServer&) = delete;

  bool running() const { return child_ != nullptr; }
  const std::string& error() const { return error_; }
  std::uint16_t port() const { return port_; }
  // The remote-cache URL: objects land in data_dir().
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/cache"; }
  std::filesystem::path data_dir() const { return root_ / "data" / "cache"; }
  std::filesystem::path access_log() const { return root_ / "logs" / "access.log"; }

  // SIGKILL, then reaped: from here on connections to the port are refused.
  void kill() {
    if (!child_) return;
    child_->send(SIGKILL);
    child_->wait();
    child_.reset();
  }

 private:
  void start(const std::filesystem::path& nginx, NginxMode mode) {
    port_ = unused_local_port();
    std::filesystem::path config = root_ / "nginx.conf";
    std::ofstream(config) << config_text(mode);
    auto child = std::make_unique<Child>(
        nginx, std::vector<std::string>{"-p", root_.string(), "-e", (root_ / "logs" / "error.log").string(), "-c",
                                        config.string()});
    if (!child->started()) {  // never signal pid -1: that would reach every process we may signal
      error_ = "cannot start " + nginx.string() + " (fork or pipe failed)";
      return;
    }
    for (int i = 0; i < 1000 && !exited(child->pid()); ++i) {
      if (accepts_connections(port_)) {
        child_ = std::move(child);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    child->send(SIGKILL);
    ChildOutcome outcome = child->wait();
    error_ = "nginx did not start on 127.0.0.1:" + std::to_string(port_) + ": " + outcome.err;
  }

  std::string config_text(NginxMode mode) const {
    const std::string r = root_.string();
    std::string location = mode == NginxMode::errors ? "      return 500;\n"
                                                     : "      dav_methods PUT;\n"
                                                       "      create_full_put_path on;\n"
                                                       "      client_max_body_size 0;\n";
    // Every path nginx would otherwise take from /var or /run is named here.
    return "daemon off;\nmaster_process off;\nerror_log " + r + "/logs/error.log warn;\npid " + r +
           "/nginx.pid;\nevents { worker_connections 256; }\nhttp {\n  access_log " + r +
           "/logs/access.log;\n  client_body_temp_path " + r + "/tmp/body;\n  proxy_temp_path " + r +
           "/tmp/proxy;\n  fastcgi_temp_path " + r + "/tmp/fastcgi;\n  uwsgi_temp_path " + r +
           "/tmp/uwsgi;\n  scgi_temp_path " + r +
           "/tmp/scgi;\n  server {\n    listen 127.0.0.1:" + std::to_string(port_) + ";\n    root " + r +
           "/data;\n    location /cache/ {\n" + location + "    }\n  }\n}\n";
  }

  std::filesystem::path root_;
  std::uint16_t port_ = 0;
  std::unique_ptr<Child> child_;
  std::string error_;
};

}  // namespace testsupport

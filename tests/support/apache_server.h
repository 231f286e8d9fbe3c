// A private Apache httpd for the remote-cache tests: Debian's apache2 with mod_dav (WebDAV PUT
// and MKCOL; a PUT into a missing collection is refused with 409, unlike nginx with
// create_full_put_path), on 127.0.0.1 at a free port, its config, stored objects, lock database,
// logs and pid file under one folder the caller names. It runs with -X: one process in the
// foreground, a child of the caller, killed by the destructor (no system service is touched).
//
// Run as root, Apache drops to the user "nobody" (it refuses to serve as root), so its folders
// are made writable by everyone.
//
// Header-only, like nginx_server.h (whose port helpers it uses).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include "child_process.h"
#include "nginx_server.h"

namespace testsupport {

inline std::filesystem::path find_apache() {
  for (const char* path : {"/usr/sbin/apache2", "/usr/sbin/httpd"})
    if (::access(path, X_OK) == 0) return path;
  return {};
}

class ApacheServer {
 public:
  explicit ApacheServer(const std::filesystem::path& root) : root_(std::filesystem::absolute(root)) {
    std::filesystem::path apache = find_apache();
    if (apache.empty()) {
      error_ =
          "apache2 is not installed (/usr/sbin/apache2): the remote-cache tests need Debian's apache2 "
          "package; scripts/install-deps.sh --tests installs it";
      return;
    }
    for (const char* dir : {"data/cache", "logs", "lock"}) {
      std::filesystem::create_directories(root_ / dir);
      std::filesystem::permissions(root_ / dir, std::filesystem::perms::all);
    }
    for (int attempt = 0; attempt < 5 && !running(); ++attempt) start(apache);
  }
  ~ApacheServer() { kill(); }
  ApacheServer(const ApacheServer&) = delete;
  ApacheServer& operator=(const ApacheServer&) = delete;

  bool running() const { return child_ != nullptr; }
  const std::string& error() const { return error_; }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/cache"; }
  std::filesystem::path data_dir() const { return root_ / "data" / "cache"; }
  std::filesystem::path access_log() const { return root_ / "logs" / "access.log"; }

  void kill() {
    if (!child_) return;
    child_->send(SIGKILL);
    child_->wait();
    child_.reset();
  }

 private:
  void start(const std::filesystem::path& apache) {
    port_ = unused_local_port();
    std::filesystem::path config = root_ / "apache2.conf";
    std::ofstream(config) << config_text();
    auto child = std::make_unique<Child>(apache, std::vector<std::string>{"-X", "-f", config.string()});
    if (!child->started()) {
      error_ = "cannot start " + apache.string() + " (fork or pipe failed)";
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
    error_ = "apache2 did not start on 127.0.0.1:" + std::to_string(port_) + ": " + outcome.err;
  }

  std::string config_text() const {
    const std::string r = root_.string(), modules = "/usr/lib/apache2/modules/";
    std::string text;
    for (const char* module : {"mpm_prefork", "authz_core", "dav", "dav_fs"})
      text += "LoadModule " + std::string(module) + "_module " + modules + "mod_" + module + ".so\n";
    if (::geteuid() == 0) text += "User nobody\nGroup nogroup\n";
    // Every path Apache would otherwise take from /etc, /var or /run is named here.
    return text + "ServerName 127.0.0.1\nListen 127.0.0.1:" + std::to_string(port_) + "\nPidFile " + r +
           "/apache2.pid\nMutex file:" + r + "/lock\nErrorLog " + r + "/logs/error.log\nLogFormat \"%r %>s\" plain\n" +
           "CustomLog " + r + "/logs/access.log plain\nDavLockDB " + r + "/lock/davlock\nDocumentRoot " + r +
           "/data\n<Directory " + r + "/data>\n  Require all granted\n</Directory>\n<Location /cache>\n  Dav On\n" +
           "</Location>\n";
  }

  std::filesystem::path root_;
  std::uint16_t port_ = 0;
  std::unique_ptr<Child> child_;
  std::string error_;
};

}  // namespace testsupport

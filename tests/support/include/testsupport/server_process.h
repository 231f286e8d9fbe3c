// server_process.h - what the private nginx and Apache of the tests and benchmarks share: a
// server program run in the foreground as one child process on 127.0.0.1 at a free port, with
// everything it writes (config, stored objects, logs) under one folder the caller names.
// Killing that child kills the server, and the destructor does it even when a test fails
// halfway; no system service is touched.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "testsupport/child_process.h"

namespace testsupport {

class ServerProcess {
 public:
  ~ServerProcess() { kill(); }
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  bool running() const { return child_ != nullptr; }
  // Why the server is not running ("<program> is not installed ...", "... did not start ...").
  const std::string& error() const { return error_; }
  std::uint16_t port() const { return port_; }
  // The remote-cache URL: objects land in data_dir().
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/cache"; }
  std::filesystem::path data_dir() const { return root_ / "data" / "cache"; }
  std::filesystem::path access_log() const { return root_ / "logs" / "access.log"; }

  // SIGKILL, then reaped: from here on connections to the port are refused.
  void kill();

 protected:
  // `root` is made absolute; nothing is started yet.
  explicit ServerProcess(const std::filesystem::path& root);

  const std::filesystem::path& root() const { return root_; }
  void set_error(std::string error) { error_ = std::move(error); }

  // The arguments that start the server on `port`; writes its config first.
  using Prepare = std::function<std::vector<std::string>(std::uint16_t port)>;

  // Starts `program` on a free port and waits until it accepts connections. Another process
  // may take the port between the probe and the server's bind, so it tries a few ports; on
  // failure error() holds the server's stderr.
  void start(const std::filesystem::path& program, const std::string& name, const Prepare& prepare);

 private:
  bool start_once(const std::filesystem::path& program, const std::string& name, const Prepare& prepare);

  std::filesystem::path root_;
  std::uint16_t port_ = 0;
  std::unique_ptr<Child> child_;
  std::string error_;
};

}  // namespace testsupport

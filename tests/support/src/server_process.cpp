#include "testsupport/server_process.h"

#include <signal.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "testsupport/local_port.h"

namespace testsupport {
namespace {

// True once `pid` has exited (a zombie not yet reaped), without reaping it.
bool exited(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_field, name, state;
  stat >> pid_field >> name >> state;
  return !stat || state == "Z";
}

}  // namespace

ServerProcess::ServerProcess(const std::filesystem::path& root) : root_(std::filesystem::absolute(root)) {}

void ServerProcess::kill() {
  if (!child_) return;
  child_->send(SIGKILL);
  child_->wait();
  child_.reset();
}

void ServerProcess::start(const std::filesystem::path& program, const std::string& name, const Prepare& prepare) {
  for (int attempt = 0; attempt < 5; ++attempt)
    if (start_once(program, name, prepare)) return;
}

bool ServerProcess::start_once(const std::filesystem::path& program, const std::string& name, const Prepare& prepare) {
  port_ = unused_local_port();
  auto child = std::make_unique<Child>(program, prepare(port_));
  if (!child->started()) {
    error_ = "cannot start " + program.string() + " (fork or pipe failed)";
    return false;
  }
  for (int i = 0; i < 1000 && !exited(child->pid()); ++i) {
    if (accepts_connections(port_)) {
      child_ = std::move(child);
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  child->send(SIGKILL);
  ChildOutcome outcome = child->wait();
  error_ = name + " did not start on 127.0.0.1:" + std::to_string(port_) + ": " + outcome.err;
  return false;
}

}  // namespace testsupport

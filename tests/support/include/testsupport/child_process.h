// child_process.h - the one way the tests and the benchmarks run a program (shadergen,
// tilelight, spirv-val, sha256sum, nginx, apache2, the tool script): started with fork/exec,
// never through a shell, so the caller can set resource limits, drop privileges and send
// signals to exactly that process; its stdout and stderr read through pipes. Pipes, not files:
// RLIMIT_FSIZE applies to every regular file a process writes, its captured stderr included,
// but not to pipes.
#pragma once

#include <sys/resource.h>
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace testsupport {

struct ChildSetup {
  rlim_t file_size_limit = RLIM_INFINITY;      // RLIMIT_FSIZE in bytes; SIGXFSZ is then ignored
  rlim_t address_space_limit = RLIM_INFINITY;  // RLIMIT_AS in bytes: allocations beyond it fail
  bool drop_to_nobody = false;                 // setgid/setuid 65534 before exec (tests run as root)
};

struct ChildOutcome {
  int exit_code = -1;  // -1 unless the child exited normally
  int signal = 0;      // the signal that killed it, 0 if none
  std::string out;
  std::string err;
  // What the child (not its own children) used, from wait4(): for the benchmarks.
  double cpu_seconds = 0.0;  // user + system
  long peak_rss_kib = 0;     // ru_maxrss
};

class Child {
 public:
  // Starts `program` (a bare name is looked up in PATH) with `args`, stdin from /dev/null.
  // started() says whether fork and the pipes worked; a program that cannot be executed exits
  // 127, and one whose setup (limits, privileges) failed exits 125.
  Child(const std::filesystem::path& program, const std::vector<std::string>& args, ChildSetup setup = {});
  // Kills (SIGKILL) and reaps a child that was not waited for.
  ~Child();
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool started() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }
  void send(int signal_number) const;

  // Blocks until stderr contains `text` or the child closed it; true when it appeared. The
  // deadline only guards against a hung child; no assertion depends on how long this took.
  bool wait_for_stderr(const std::string& text, std::chrono::seconds deadline = std::chrono::seconds(300));

  // Waits for the child to end and returns how it ended and all it wrote. Once only.
  ChildOutcome wait();

 private:
  void read_both(int out_fd, int err_fd);

  pid_t pid_ = -1;
  bool reaped_ = false;
  std::thread reader_;
  std::mutex mutex_;
  std::string out_, err_;
  bool closed_ = false;
};

}  // namespace testsupport

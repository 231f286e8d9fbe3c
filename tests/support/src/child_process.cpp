#include "testsupport/child_process.h"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

namespace testsupport {
namespace {

// In the forked child, before exec: only async-signal-safe calls from here on.
[[noreturn]] void exec_child(char* const argv[], int out_fd, int err_fd, const ChildSetup& setup) {
  ::dup2(out_fd, 1);
  ::dup2(err_fd, 2);
  int null_fd = ::open("/dev/null", O_RDONLY);
  if (null_fd >= 0) ::dup2(null_fd, 0);
  if (setup.file_size_limit != RLIM_INFINITY) {
    ::signal(SIGXFSZ, SIG_IGN);  // write() then fails with EFBIG instead of killing
    rlimit limit{setup.file_size_limit, setup.file_size_limit};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(125);
  }
  if (setup.address_space_limit != RLIM_INFINITY) {
    rlimit limit{setup.address_space_limit, setup.address_space_limit};
    if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(125);
  }
  if (setup.drop_to_nobody && (::setgroups(0, nullptr) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0))
    ::_exit(125);
  ::execvp(argv[0], argv);  // a bare name is looked up in PATH
  ::_exit(127);
}

}  // namespace

Child::Child(const std::filesystem::path& program, const std::vector<std::string>& args, ChildSetup setup) {
  // Everything the child needs is prepared before fork(): between fork and exec a child of
  // a multi-threaded process may only make async-signal-safe calls.
  std::vector<std::string> all{program.string()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  argv.reserve(all.size() + 1);
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  int out_pipe[2], err_pipe[2];
  if (::pipe2(out_pipe, O_CLOEXEC) != 0) return;
  if (::pipe2(err_pipe, O_CLOEXEC) != 0) {
    ::close(out_pipe[0]);
    ::close(out_pipe[1]);
    return;
  }
  pid_ = ::fork();
  if (pid_ == 0) exec_child(argv.data(), out_pipe[1], err_pipe[1], setup);
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  if (pid_ < 0) {
    ::close(out_pipe[0]);
    ::close(err_pipe[0]);
    return;
  }
  reader_ = std::thread([this, out = out_pipe[0], err = err_pipe[0]] { read_both(out, err); });
}

Child::~Child() {
  if (pid_ > 0 && !reaped_) {
    ::kill(pid_, SIGKILL);
    (void)wait();
  }
}

void Child::send(int signal_number) const {
  if (pid_ > 0) ::kill(pid_, signal_number);  // never pid -1: that would reach every process we may signal
}

bool Child::wait_for_stderr(const std::string& text, std::chrono::seconds deadline) {
  auto until = std::chrono::steady_clock::now() + deadline;
  while (std::chrono::steady_clock::now() < until) {
    {
      std::lock_guard lock(mutex_);
      if (err_.find(text) != std::string::npos) return true;
      if (closed_) return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

ChildOutcome Child::wait() {
  ChildOutcome outcome;
  if (pid_ <= 0) return outcome;
  int status = 0;
  struct rusage usage {};
  while (::wait4(pid_, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  reaped_ = true;
  outcome.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                        static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
  outcome.peak_rss_kib = usage.ru_maxrss;
  if (reader_.joinable()) reader_.join();
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  std::lock_guard lock(mutex_);
  outcome.out = out_;
  outcome.err = err_;
  return outcome;
}

void Child::read_both(int out_fd, int err_fd) {
  pollfd fds[2] = {{out_fd, POLLIN, 0}, {err_fd, POLLIN, 0}};
  int open_count = 2;
  char buffer[4096];
  while (open_count > 0) {
    if (::poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        std::lock_guard lock(mutex_);
        (i == 0 ? out_ : err_).append(buffer, static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_count;
      }
    }
  }
  std::lock_guard lock(mutex_);
  closed_ = true;
}

}  // namespace testsupport

#pragma once

// The fitfeel CLI started as a child process the test can signal: std::system (cli_runner.h)
// waits for its command and gives no process to send SIGINT to. Header-only, for this folder's
// tests.

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <linux/capability.h>

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

namespace fitfeel::test_support {

struct ChildProcess {
  pid_t pid = -1;
  std::filesystem::path out;  // its standard output
  std::filesystem::path err;  // its standard error
};

// Starts `program` with `arguments`, standard output and error into `out` and `err`, SIGINT and
// SIGTERM at their default action and no signal blocked (whatever the test runner left: a shell's
// `&` ignores SIGINT). With `without_read_override`, root's CAP_DAC_OVERRIDE and
// CAP_DAC_READ_SEARCH are dropped from the bounding set first, so that the program meets file
// permissions as anyone does; the child exits with 77 when they cannot be dropped.
inline ChildProcess StartChild(const std::filesystem::path& program,
                               const std::vector<std::string>& arguments,
                               const std::filesystem::path& out, const std::filesystem::path& err,
                               bool without_read_override = false) {
  // Everything the child needs is made before fork: between fork and exec only async-signal-safe
  // calls.
  std::vector<std::string> words = {program.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string out_path = out.string();
  const std::string err_path = err.string();
  ChildProcess child{::fork(), out, err};
  if (child.pid == 0) {
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    const int out_fd = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out_fd < 0 || err_fd < 0 || ::dup2(out_fd, 1) < 0 || ::dup2(err_fd, 2) < 0) ::_exit(126);
    if (without_read_override &&
        (::prctl(PR_CAPBSET_DROP, CAP_DAC_OVERRIDE, 0, 0, 0) != 0 ||
         ::prctl(PR_CAPBSET_DROP, CAP_DAC_READ_SEARCH, 0, 0, 0) != 0)) {
      ::_exit(77);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return child;
}

// Waits for the child and returns its status (waitpid's).
inline int WaitForChild(const ChildProcess& child) {
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

// Whether the child has ended (reaping it, `status` set) without waiting.
inline bool ChildEnded(const ChildProcess& child, int* status) {
  return ::waitpid(child.pid, status, WNOHANG) == child.pid;
}

}  // namespace fitfeel::test_support

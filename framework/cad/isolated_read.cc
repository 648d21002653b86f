#include "framework/cad/isolated_read.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "framework/cad/step_reader.h"
#include "framework/core/error.h"
#include "framework/core/interrupt.h"
#include "framework/core/path_check.h"

namespace fitfeel::cad {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kHeader = "ISO-10303-21;";
constexpr std::string_view kTrailer = "END-ISO-10303-21;";

[[noreturn]] void Refuse(const fs::path& file, const std::string& why) {
  throw UserError("import: '" + file.string() + "' " + why);
}

// The checks that need no reader: a file the reader would spend its time limit on, or that is
// not STEP text at all, is refused by what its size and its two ends show.
void CheckFile(const fs::path& file, const ReadLimits& limits) {
  const std::string why = WhyNotReadableFile(file);
  if (!why.empty()) Refuse(file, why);
  std::error_code error;
  const std::uintmax_t size = fs::file_size(file, error);
  if (error) Refuse(file, "cannot be sized: " + error.message());
  if (size == 0) Refuse(file, "is empty: a STEP file starts with ISO-10303-21;");
  if (size > limits.max_bytes) {
    Refuse(file, "is " + std::to_string(size) + " bytes, above the " +
                     std::to_string(limits.max_bytes) + " bytes the import reads");
  }
  std::ifstream in(file, std::ios::binary);
  std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(size, 256)), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  for (const char c : head) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte == 0 || (byte < 0x20 && c != '\n' && c != '\r' && c != '\t')) {
      Refuse(file, "is not a STEP file: it holds binary bytes where ISO-10303-21; belongs");
    }
  }
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  if (start == std::string::npos || head.compare(start, kHeader.size(), kHeader) != 0) {
    Refuse(file, "is not a STEP file: it does not start with ISO-10303-21;");
  }
  const std::uintmax_t tail_size = std::min<std::uintmax_t>(size, 4096);
  std::string tail(static_cast<std::size_t>(tail_size), '\0');
  in.seekg(static_cast<std::streamoff>(size - tail_size));
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  if (!in) Refuse(file, "cannot be read to its end");
  if (tail.find(kTrailer) == std::string::npos) {
    Refuse(file, "is truncated: it does not end with END-ISO-10303-21;");
  }
}

// In the child: only the reader's answer goes to the parent, "D" and the document or "E" and the
// reader's complaint. Its console output (transfer statistics) is dropped.
[[noreturn]] void ReadInChild(const fs::path& file, int out) {
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  if (const char* hook = std::getenv("FITFEEL_TEST_CAD_READER")) {
    if (std::strcmp(hook, "abort") == 0) std::abort();
    if (std::strcmp(hook, "hang") == 0) {
      for (;;) ::pause();
    }
  }
  std::string answer;
  try {
    answer = "D" + ToText(ReadStepHere(file));
  } catch (const std::exception& e) {
    answer = std::string("E") + e.what();
  } catch (...) {
    answer = "Ethe reader failed with an unknown exception";
  }
  std::size_t done = 0;
  while (done < answer.size()) {
    const ssize_t n = ::write(out, answer.data() + done, answer.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(3);
    done += static_cast<std::size_t>(n);
  }
  ::_exit(0);
}

int WaitFor(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

CadDocument ReadStep(const fs::path& file, const ReadLimits& limits) {
  CheckFile(file, limits);
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    throw std::system_error(errno, std::generic_category(), "import: pipe");
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::system_error(errno, std::generic_category(), "import: fork");
  }
  if (pid == 0) {
    ::close(fds[0]);
    ReadInChild(file, fds[1]);
  }
  ::close(fds[1]);
  std::string answer;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(limits.seconds));
  bool timed_out = false;
  char buffer[65536];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd wait{fds[0], POLLIN, 0};
    const int ready = ::poll(&wait, 1, static_cast<int>(std::min<long long>(left.count(), 200)));
    if (ready < 0 && errno != EINTR) break;
    if (InterruptSignal() != 0) {
      ::kill(pid, SIGKILL);
      ::close(fds[0]);
      WaitFor(pid);
      throw Interrupted("while reading '" + file.string() + "'");
    }
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  const int status = WaitFor(pid);
  if (timed_out) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", limits.seconds);
    Refuse(file, std::string("was not read within ") + seconds + " s; the STEP reader was stopped");
  }
  if (WIFSIGNALED(status)) {
    Refuse(file, std::string("crashed the STEP reader (") + strsignal(WTERMSIG(status)) +
                     "); the reader ran in a child process and the file is refused");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty()) {
    Refuse(file, "was not read: the STEP reader's process ended without an answer");
  }
  if (answer[0] == 'E') Refuse(file, "was not read: " + answer.substr(1));
  try {
    return FromText(answer.substr(1));
  } catch (const std::exception& e) {
    Refuse(file, std::string("was not read: ") + e.what());
  }
}

}  // namespace fitfeel::cad

#include "framework/core/interrupt.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace fitfeel {
namespace {

// Only lock-free atomics may be touched from a signal handler.
static_assert(std::atomic<bool>::is_always_lock_free);
static_assert(std::atomic<int>::is_always_lock_free);

std::atomic<bool> g_flag{false};
std::atomic<int> g_signal{0};
std::atomic<bool> g_cooperative{false};

// The lines an immediate stop prints, made before the handlers are installed: the handler only
// reads them.
struct Line {
  char text[512] = {};
  std::size_t size = 0;
};
Line g_int_line, g_term_line;

void Compose(Line* line, const std::string& command, const char* signal,
             const std::string& outcome) {
  const std::string text = command + ": interrupted by " + signal + "; " + outcome + "\n";
  line->size = std::min(text.size(), sizeof(line->text));
  std::memcpy(line->text, text.data(), line->size);
  line->text[line->size - 1] = '\n';  // a line cut short still ends
}

void Reraise(int signal) {
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  sigaction(signal, &action, nullptr);
  // Blocked while the handler runs: delivered, with the default action, as it returns.
  raise(signal);
}

extern "C" void OnInterrupt(int signal) {
  const int saved_errno = errno;
  int none = 0;
  if (!g_signal.compare_exchange_strong(none, signal)) {
    Reraise(signal);
  } else if (g_cooperative.load()) {
    g_flag.store(true);
  } else {
    const Line& line = signal == SIGINT ? g_int_line : g_term_line;
    const ssize_t written = ::write(STDERR_FILENO, line.text, line.size);
    static_cast<void>(written);  // nothing more can be done about a closed stderr here
    ::_exit(InterruptExitCode(signal));
  }
  errno = saved_errno;
}

void Install(int signal, struct sigaction* previous) {
  sigaction(signal, nullptr, previous);
  if (previous->sa_handler == SIG_IGN) return;
  struct sigaction action {};
  action.sa_handler = OnInterrupt;
  sigemptyset(&action.sa_mask);
  // One handler at a time: a SIGTERM during SIGINT's handler waits for it.
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  // Interrupted reads and writes resume: the work stops at its own boundaries, not inside I/O.
  action.sa_flags = SA_RESTART;
  sigaction(signal, &action, nullptr);
}

}  // namespace

InterruptScope::InterruptScope(const std::string& command, const std::string& outcome) {
  g_signal.store(0);
  g_flag.store(false);
  g_cooperative.store(false);
  Compose(&g_int_line, command, "SIGINT", outcome);
  Compose(&g_term_line, command, "SIGTERM", outcome);
  Install(SIGINT, &previous_int_);
  Install(SIGTERM, &previous_term_);
}

InterruptScope::~InterruptScope() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

void InterruptScope::Cooperate() { g_cooperative.store(true); }

const std::atomic<bool>& InterruptFlag() noexcept { return g_flag; }

int InterruptSignal() noexcept { return g_signal.load(); }

std::string SignalName(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

Interrupted::~Interrupted() = default;

}  // namespace fitfeel

#pragma once

#include <atomic>
#include <csignal>
#include <stdexcept>
#include <string>

#include "framework/core/export.h"

namespace fitfeel {

// SIGINT and SIGTERM for a command that writes files, in two phases:
//  - at once: while nothing is being written (loading, preparing, computing, serving), either
//    signal ends the process straight from the handler, printing "<command>: interrupted by
//    SIGINT; <outcome>" with exit code 128 + signal (write(2) and _exit(2): async-signal-safe).
//  - cooperative, after Cooperate(): once temporaries may exist, a signal only records itself (a
//    lock-free atomic store), the work polls InterruptFlag() at its boundaries (a scheduler at each
//    tick, a study between pairs), stops there, removes its temporaries and throws Interrupted.
// In either phase a second signal restores the default action and re-raises it: whoever insists
// is never kept waiting (temporaries left then are swept by the next command into the same
// folder, RemoveStaleTemporaries). A signal ignored when the scope began (`cmd &` in a script
// ignores SIGINT) stays ignored. One scope at a time.
class FITFEEL_API InterruptScope {
 public:
  // Clears any signal recorded before and installs the handlers. `command` opens the line an
  // immediate stop prints ("fitfeel run"), `outcome` ends it.
  explicit InterruptScope(const std::string& command,
                          const std::string& outcome = "no outputs written");
  // Restores the dispositions found; the recorded signal stays readable (InterruptSignal).
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  // From now on a signal is recorded for the work to poll, not acted on at once.
  void Cooperate();

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

// Set once SIGINT or SIGTERM arrived in the cooperative phase: what loops poll (relaxed loads are
// enough: the flag only ever goes from false to true).
FITFEEL_API const std::atomic<bool>& InterruptFlag() noexcept;
// The signal recorded (SIGINT or SIGTERM), 0 when none arrived.
FITFEEL_API int InterruptSignal() noexcept;
// "SIGINT", "SIGTERM", else "signal N".
FITFEEL_API std::string SignalName(int signal);
// The conventional exit code of a process stopped by `signal`: 128 + signal (130 for SIGINT,
// 143 for SIGTERM).
inline int InterruptExitCode(int signal) { return 128 + signal; }

// Thrown where work stopped for an interrupt, after its temporaries are removed. what() says how
// far it got and what was kept, to follow "fitfeel run: interrupted by SIGINT ", e.g. "after 1234
// of 5000 ticks; no outputs written".
class FITFEEL_API Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~Interrupted() override;
};

}  // namespace fitfeel

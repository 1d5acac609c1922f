#include "interrupt.h"

#include <signal.h>
#include <time.h>

namespace ballbench {
namespace {

volatile sig_atomic_t g_signal = 0;
volatile sig_atomic_t g_hurried = 0;
volatile sig_atomic_t g_second_kills = 1;
timespec g_first{};  // when the first signal came (then: when the second did)

// A second signal this soon after the first is the same request arriving twice (a signal sent to
// the process and to its process group, as `timeout` and shells do), not a user insisting.
constexpr double kSameRequestS = 0.5;

double seconds_since(const timespec& t) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return static_cast<double>(now.tv_sec - t.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec - t.tv_nsec);
}

// A second signal (a while after the first) means hurry: runs in child processes are killed at
// once and what is finished is written. A third means stop now: the default action, the process
// ends by that signal.
void on_signal(int sig) {
  if (g_signal != 0) {
    if (!g_second_kills || seconds_since(g_first) <= kSameRequestS) return;
    if (!g_hurried) {
      clock_gettime(CLOCK_MONOTONIC, &g_first);
      g_hurried = 1;
      return;
    }
    signal(sig, SIG_DFL);
    raise(sig);
    return;
  }
  clock_gettime(CLOCK_MONOTONIC, &g_first);
  g_signal = sig;
}

}  // namespace

void install_interrupt_handlers(bool second_kills) {
  g_second_kills = second_kills;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGHUP, &sa, nullptr);
}

int interrupt_signal() { return g_signal; }

bool interrupt_hurried() { return g_hurried != 0; }

const char* interrupt_name() {
  switch (g_signal) {
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "SIGINT";
  }
}

}  // namespace ballbench

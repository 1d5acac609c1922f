#include "interrupt.h"

#include <signal.h>

namespace ballbench {
namespace {

volatile sig_atomic_t g_signal = 0;
volatile sig_atomic_t g_second_kills = 1;

// A second signal means stop now: the default action (the process ends by that signal).
void on_signal(int sig) {
  if (g_signal != 0 && g_second_kills) {
    signal(sig, SIG_DFL);
    raise(sig);
    return;
  }
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
}

int interrupt_signal() { return g_signal; }

const char* interrupt_name() { return g_signal == SIGTERM ? "SIGTERM" : "SIGINT"; }

}  // namespace ballbench

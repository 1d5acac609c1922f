#pragma once
// SIGINT, SIGTERM and SIGHUP (a closed terminal or ssh session) as a request to stop, not a kill: a command that installs the handlers checks
// interrupt_signal() between steps and between runs, ends what it is doing, writes what it has
// computed (its rows so far, the interrupted one marked `interrupted`) and removes its temporary
// files. Child processes forked for isolated runs inherit the handlers, so an engine's run ends at
// a step boundary and still reports its metrics.
#include <string>

namespace ballbench {

// Installs the handlers (sigaction, no SA_RESTART: a blocking poll or wait returns with EINTR).
// `second_kills`: a second signal, more than half a second after the first, hurries (the runs in
// child processes are killed at once, what is finished is still written) and a third, as long
// after the second, ends the process at once (its default action), for a user who means it; an
// isolated run's child sets it false, as it may get the terminal's signal and the one its parent
// forwards.
void install_interrupt_handlers(bool second_kills = true);

// The signal that asked to stop (SIGINT, SIGTERM or SIGHUP), or 0.
int interrupt_signal();

// A second signal came: child processes still running are to be killed now, not waited for.
bool interrupt_hurried();

// "SIGINT", "SIGTERM" or "SIGHUP" for the signal that asked to stop.
const char* interrupt_name();

// Thrown by work that has nothing to keep when asked to stop (placing a scene's balls before any
// run): main says so in one line and exits with 128 + the signal.
struct Interrupted {
  std::string during;  // "placing 50000000 balls", for the message
};

}  // namespace ballbench

#pragma once
// How long a process has waited for a core: the time it was ready to run while other work held
// the cores (Linux's run_delay in /proc/PID/schedstat, in ns, of its main thread). A step time less
// this wait is what the step would have taken alone, so an engine in another process is costed
// the same on an idle machine and on a loaded one. Unlike the process's CPU time, it cannot make
// a step that waits on purpose (a sleep, a helper process doing the work) look cheap.
#include <sys/types.h>

#include <optional>

namespace ballbench {

class CoreWait {
 public:
  explicit CoreWait(pid_t pid);
  ~CoreWait();
  CoreWait(const CoreWait&) = delete;
  CoreWait& operator=(const CoreWait&) = delete;

  // Seconds it has waited since it started; nullopt where the OS does not say (not Linux, no
  // schedstat, or the process gone).
  std::optional<double> waited_s() const;
  bool available() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace ballbench

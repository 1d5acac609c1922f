#pragma once
// A command run as a child process with pipes on its stdin, stdout and stderr: what a process
// engine (PROTOCOL.md) runs in. Reads wait at most until a deadline, so a child that hangs is an
// error, not a hang; its stderr is kept (the last few kilobytes) for the error message. POSIX and
// Linux (prctl: the child is killed when the thread that started it dies).
#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <ctime>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ballbench {

// The child misbehaved: it exited, closed its output, sent no reply in time, or sent what the
// protocol does not allow. The message says which, with the child's last stderr lines.
class ChildProcessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts argv[0] (looked up on PATH) with `argv` in the folder `cwd` ("" = this process's).
  // Throws ChildProcessError if it cannot be started (the program is missing or not executable).
  ChildProcess(const std::vector<std::string>& argv, const std::string& cwd);
  // Closes its stdin (a conforming engine exits at end of input), waits a moment, then kills it.
  // In a forked copy of the process that started it, only the descriptors are closed.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // Everything written, or ChildProcessError (the child exited or stopped reading past `deadline`).
  void write(const std::string& bytes, Clock::time_point deadline);
  // One line without its '\n', at most `max_bytes` long (longer is garbage). `stop_on_interrupt`:
  // a stop request (interrupt.h) ends the wait by throwing Interrupted, for a wait before any run.
  std::string read_line(Clock::time_point deadline, size_t max_bytes, bool stop_on_interrupt = false);
  // Exactly `n` bytes into `out`; `what` names them in errors ("the state block"), which say how
  // many bytes were short.
  void read_bytes(void* out, size_t n, Clock::time_point deadline, const char* what = "state block");
  // True if the child has written anything not yet taken (checked without waiting): before a
  // request, a reply nobody asked for.
  bool has_unread_output();

  // True if this process started it (not a fork's inherited copy) and it has not failed.
  bool usable() const;
  // True if usable and started by the calling thread, which it dies with (prctl): a process kept
  // for the next run serves only the thread that started it, or another thread's end would kill
  // it in the middle of a run.
  bool serves_this_thread() const;
  // True if the child has exited (asked of the OS without waiting): a process kept for another
  // thread dies with that thread.
  bool has_exited();
  // Bounds on every wait of a run's steps (unbound(): none but each call's deadline): past
  // `wall_end`, once the child has spent `cpu_s` of CPU since the last write, or asked to stop
  // (interrupt.h: kInterruptGraceS more, none once hurried), the child is killed and the wait
  // throws StepStuck (engine.h).
  void bound(std::optional<Clock::time_point> wall_end, std::optional<double> cpu_s);
  void unbound();
  // "`node adapters/node/rapier.js`": how errors name it.
  const std::string& label() const { return label_; }
  pid_t pid() const { return pid_; }
  // The end of what the child wrote on stderr so far, trimmed, with line breaks as " | ".
  std::string stderr_tail();
  // An error naming the child, `what` happened, and how it ended (exit status or signal) if it
  // has, with its stderr: the one message every failure here carries.
  ChildProcessError failure(const std::string& what);

 private:
  // Reads whatever arrives next. `block_bytes`: a binary block of that many bytes is awaited, and
  // an end or a silence says how many of them are missing.
  void pump(Clock::time_point deadline, const char* waiting_for, size_t block_bytes = 0, bool stop_on_interrupt = false);
  void drain_stderr();
  // Throws StepStuck, the child killed, if a bound is passed; the wait until it could be (ms).
  int check_bounds(int wait_ms);
  double cpu_spent_s() const;  // the child's CPU time so far (s)
  std::string exit_description();

  std::string label_;
  pid_t pid_ = -1;
  pid_t owner_ = -1;  // the process that started it
  unsigned long owner_thread_ = 0;  // the thread that started it (a number never reused in this process)
  int in_ = -1, out_ = -1, err_ = -1;
  int exit_fd_ = -1;    // a pidfd of the child: readable once it has exited (-1: none)
  bool exit_seen_ = false;  // exit_fd_ said it exited
  bool failed_ = false, exited_ = false;
  int wait_status_ = 0;
  std::string inbox_;   // stdout read but not yet taken
  std::string stderr_;  // the last kStderrKeep bytes of stderr
  bool bounded_ = false;
  std::optional<Clock::time_point> wall_end_;
  std::optional<double> cpu_bound_s_;
  clockid_t cpu_clock_{};
  double cpu_at_write_s_ = 0;
  std::optional<Clock::time_point> interrupt_end_;  // asked to stop inside a step: killed then
};

}  // namespace ballbench

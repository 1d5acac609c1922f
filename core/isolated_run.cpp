#include "isolated_run.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <optional>
#include <set>
#include <thread>

#include <time.h>

#include <fmt/format.h>

#include "core_affinity.h"
#include "engine_group.h"
#include "input_error.h"
#include "interrupt.h"
#include "trajectory_csv.h"

// The child talks to the parent through a pipe in lines of text:
//   progress DONE TOTAL      now and then (run_engine's progress callback, every 1% of the steps)
//   group +PGID / -PGID      an engine process's group started / ended (note_engine_group)
//   trajectory_error WHY     its trajectory could not be written (the result still follows)
//   result JSON              the Result (to_json, on one line), last
//   input_error MESSAGE      run_engine threw InputError (bad settings): rethrown here
//   error MESSAGE            any other exception escaped run_engine
// then exits with status 0. Anything else (a signal, another exit status, silence past the time
// limit) is the engine's doing and becomes the run's result.

namespace ballbench {
namespace {

using Clock = std::chrono::steady_clock;
// Seconds an interrupted child has to finish its step and send its result before it is killed.
constexpr int kInterruptGrace = 10;

// A run under a cost limit checks it at step boundaries; a step that never ends (a dense solver on
// thousands of balls: over 10 min for one) is killed by the parent once the CPU time of the child
// and of its engines' processes since its last progress report (every 1% of the steps) passes the
// limit times this factor and this margin (the harness's work between reports counts too), read
// this often. CPU time, not the clock: another job on the cores does not bring the kill nearer.
constexpr double kStuckCostFactor = 2, kStuckCostMargin_s = 5;
constexpr int kCpuCheckMs = 250;

std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

// In a run's child process: its end of the pipe to the parent (note_engine_group); -1 elsewhere.
int g_parent_pipe = -1;

// write() until everything is out; a dead parent ends the child by SIGPIPE, which is fine.
void send(int fd, const std::string& text) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    p += n, left -= static_cast<size_t>(n);
  }
}

// run_engine() with the isolation's time limit at a step boundary and its trajectory file; what
// keeps the file from being written goes to `trajectory_error` (the run's result stands).
Result run_limited(const Scene& scene, const EngineEntry& entry, RunOptions options, const IsolationOptions& isolation,
                   std::string& trajectory_error) {
  std::optional<TrajectoryCsv> trajectory;
  if (!isolation.trajectory_path.empty())
    trajectory.emplace(isolation.trajectory_path, scene.features().rotation, isolation.trajectory_path + ".tmp"),
        options.trajectory = &*trajectory;
  options.deadline = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(std::min(isolation.timeout_s, 1e8)));
  Result r = run_engine(scene, entry, options);
  if (trajectory) {
    try {
      trajectory_error = trajectory->finish();
    } catch (const InputError& e) {
      trajectory_error = e.what();
    }
  }
  return r;
}

[[noreturn]] void child_main(int fd, const Scene& scene, const EngineEntry& entry, RunOptions options,
                             const IsolationOptions& isolation) {
  std::string message;
  g_parent_pipe = fd;
  try {
    options.progress = [fd](long done, long total) { send(fd, fmt::format("progress {} {}\n", done, total)); };
    // Its own time limit, at a step boundary, keeps the steps made; the parent's, a grace later,
    // ends a child stuck inside a step.
    std::string trajectory_error;
    const Result r = run_limited(scene, entry, options, isolation, trajectory_error);
    if (!trajectory_error.empty()) send(fd, "trajectory_error " + one_line(trajectory_error) + "\n");
    // Invalid UTF-8 in an engine's error text must not lose the result: replace it.
    message = "result " + to_json(r).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  } catch (const InputError& e) {
    message = "input_error " + one_line(e.what()) + "\n";
  } catch (const std::exception& e) {
    message = "error " + one_line(e.what()) + "\n";
  } catch (...) {
    message = "error an exception that is not a std::exception\n";
  }
  send(fd, message);
  // quick_exit, not exit: no atexit handlers, static destructors or stdio flushes of the parent's
  // state; its at_quick_exit handlers end the engine processes this child started.
  std::quick_exit(0);
}

// What the parent saw of the child.
struct ChildOutcome {
  bool timed_out = false;
  std::optional<double> over_cost_cpu_s;  // killed inside a step: its CPU time since the last report (s)
  bool interrupted = false;  // this process was asked to stop while the child ran
  bool reaped = false;
  int wait_status = 0;
  long last_done = 0;      // the last step the child reported done
  std::string kind, body;  // the final message ("result", "input_error", "error"), if any
  std::string trajectory_error;
};

class ChildWatcher {
 public:
  // `cpu_limit_s`: the child's CPU time between progress reports past which it is killed as over
  // cost (none: no limit).
  ChildWatcher(pid_t pid, int fd, double timeout_s, const std::function<void(long, long)>& progress,
               std::optional<double> cpu_limit_s)
      : pid_(pid), fd_(fd), progress_(progress),
        deadline_(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(std::min(timeout_s, 1e8)))),
        cpu_limit_s_(cpu_limit_s) {
    if (cpu_limit_s_ && ::clock_getcpuclockid(pid_, &cpu_clock_) != 0) cpu_limit_s_.reset();
    cpu_at_report_s_ = child_cpu_s();
  }

  ChildOutcome watch() {
    read_until_eof();
    if (!out_.timed_out && !out_.over_cost_cpu_s) reap_before_deadline();
    if (!out_.reaped) {
      ::kill(pid_, SIGKILL);
      while (::waitpid(pid_, &out_.wait_status, 0) < 0 && errno == EINTR) {
      }
      out_.reaped = true;
    }
    // A child that ended normally ended its engines' groups itself (quick_exit's handler).
    if (!(WIFEXITED(out_.wait_status) && WEXITSTATUS(out_.wait_status) == 0))
      for (const int group : engine_groups_) kill_engine_group(group);
    return out_;
  }

 private:
  int ms_left() const {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now()).count() + 1;
    // Poll again at least every minute, or as often as the CPU time is read.
    return static_cast<int>(std::clamp<long long>(left, 0, cpu_limit_s_ ? kCpuCheckMs : 60'000));
  }

  // The child's CPU time (s), and that of its engines' processes (an engine in another process
  // computes there, the child only waits for its reply); 0 for what cannot be read. An engine's
  // process leads its group, so the group's number is its pid. A process that ended leaves the sum,
  // which can only put a kill off, never bring it nearer.
  double child_cpu_s() const {
    if (!cpu_limit_s_) return 0;
    double s = cpu_seconds(cpu_clock_);
    for (const int group : engine_groups_)
      if (clockid_t c{}; ::clock_getcpuclockid(group, &c) == 0) s += cpu_seconds(c);
    return s;
  }
  static double cpu_seconds(clockid_t clock) {
    timespec t{};
    return ::clock_gettime(clock, &t) == 0 ? double(t.tv_sec) + 1e-9 * double(t.tv_nsec) : 0;
  }

  // The child's CPU time since its last report is past its limit: it is stuck in a step that costs
  // more than the whole run may.
  bool past_cpu_limit() {
    if (!cpu_limit_s_) return false;
    const double spent = child_cpu_s() - cpu_at_report_s_;
    if (spent <= *cpu_limit_s_) return false;
    out_.over_cost_cpu_s = spent;
    return true;
  }
  bool past_deadline() const { return Clock::now() >= deadline_; }

  // Asked to stop (interrupt.h): the child is asked too, once, by the same signal (it may have the
  // terminal's signal already; it ends at a step boundary and sends its result), and given a few
  // seconds for it. Asked again (interrupt_hurried): the child is killed at once.
  void forward_interrupt() {
    if (!interrupt_signal()) return;
    if (!out_.interrupted) {
      out_.interrupted = true;
      ::kill(pid_, interrupt_signal());
      deadline_ = std::min(deadline_, Clock::now() + std::chrono::seconds(kInterruptGrace));
    }
    if (interrupt_hurried()) deadline_ = std::min(deadline_, Clock::now());
  }

  void read_until_eof() {
    char buf[1 << 16];
    for (;;) {
      forward_interrupt();
      if (past_deadline()) {
        out_.timed_out = true;
        return;
      }
      if (past_cpu_limit()) return;  // killed in watch(), as after a deadline
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, ms_left());
      if (ready < 0 && errno != EINTR) return;  // cannot watch the pipe: fall back to waiting
      if (ready <= 0) continue;
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      if (n <= 0) return;  // end of file: the child exited or closed the pipe
      inbox_.append(buf, static_cast<size_t>(n));
      take_lines();
    }
  }

  void take_lines() {
    size_t start = 0;
    for (size_t end; (end = inbox_.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = inbox_.substr(start, end - start);
      const size_t space = line.find(' ');
      const std::string kind = line.substr(0, space), body = space == std::string::npos ? "" : line.substr(space + 1);
      if (kind == "group") {
        int group = 0;
        if (std::sscanf(body.c_str() + (body.empty() ? 0 : 1), "%d", &group) == 1 && group > 0) {
          if (body[0] == '+') engine_groups_.insert(group);
          else engine_groups_.erase(group);
        }
      } else if (kind == "trajectory_error") {
        out_.trajectory_error = body;
      } else if (kind == "progress") {
        long done = 0, total = 0;
        if (std::sscanf(body.c_str(), "%ld %ld", &done, &total) == 2) {
          out_.last_done = done;
          cpu_at_report_s_ = child_cpu_s();
          if (progress_) progress_(done, total);
        }
      } else {
        out_.kind = kind, out_.body = body;
      }
    }
    inbox_.erase(0, start);
  }

  // After end of file the child is exiting; give it until the deadline.
  void reap_before_deadline() {
    for (;;) {
      forward_interrupt();
      const pid_t w = ::waitpid(pid_, &out_.wait_status, WNOHANG);
      if (w == pid_) {
        out_.reaped = true;
        return;
      }
      if (w < 0 && errno != EINTR) return;
      if (past_deadline()) {
        out_.timed_out = true;
        return;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }

  pid_t pid_;
  int fd_;
  const std::function<void(long, long)>& progress_;
  Clock::time_point deadline_;
  std::string inbox_;
  ChildOutcome out_;
  std::set<int> engine_groups_;  // the child's engine process groups still live
  std::optional<double> cpu_limit_s_;
  clockid_t cpu_clock_{};
  double cpu_at_report_s_ = 0;  // the child's CPU time at its last progress report (or its start)
};

// How long after its time limit a child is killed: it stops itself at the first step boundary past
// the limit, so only one stuck inside a step (or an engine's reply) is still running then.
double stuck_grace_s(double timeout_s) { return std::max(2.0, 0.1 * timeout_s); }

Result outcome_to_result(const ChildOutcome& c, Result r, double timeout_s,
                         const std::optional<RunOptions::CostLimit>& cost_limit) {
  // The steps it reported done, whose figures went with the process (the result's steps_done is
  // what was measured: 0).
  const std::string after =
      c.last_done > 0 ? fmt::format(" after step {} of {} (the figures of those steps lost with it)", c.last_done, r.steps)
                      : "";
  // Interrupted: the child's own result (status "interrupted", its metrics so far) if it sent one.
  if (c.interrupted && !(c.kind == "result" && WIFEXITED(c.wait_status) && WEXITSTATUS(c.wait_status) == 0)) {
    r.status = RunStatus::interrupted;
    r.error = fmt::format("interrupted by {}{}; the engine's process sent no result", interrupt_name(), after);
    return r;
  }
  if (c.over_cost_cpu_s) {
    r.status = RunStatus::over_cost;
    r.error = fmt::format("its process spent {:.3g} s of CPU inside a step{}, over {:g} times its cost limit and {:g} "
                          "s more ({}): killed",
                          *c.over_cost_cpu_s, after, kStuckCostFactor, kStuckCostMargin_s,
                          cost_limit ? cost_limit->what : std::string("none"));
    return r;
  }
  if (c.timed_out) {
    r.status = RunStatus::timed_out;
    r.error = fmt::format("no result within the time limit of {} s{} and {:g} s more (stuck in a step): killed",
                          timeout_s, after, stuck_grace_s(timeout_s));
    return r;
  }
  const int st = c.wait_status;
  if (WIFSIGNALED(st)) {
    r.status = RunStatus::crashed;
    r.error = fmt::format("killed by {}{}", signal_description(WTERMSIG(st)), after);
    return r;
  }
  if (c.kind == "input_error") throw InputError(c.body);
  const int code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  if (code == 0 && c.kind == "result") {
    try {
      return result_from_json(nlohmann::json::parse(c.body));
    } catch (const nlohmann::json::exception& e) {
      r.status = RunStatus::failed;
      r.error = fmt::format("the run's result could not be read back: {}", e.what());
      return r;
    }
  }
  if (code == 0 && c.kind == "error") {
    r.status = RunStatus::failed;
    r.error = c.body;
    return r;
  }
  r.status = RunStatus::crashed;
  r.error = fmt::format("the engine's process exited with status {}{} without a result", code, after);
  return r;
}

}  // namespace

void note_engine_group(int group, bool live) {
  if (g_parent_pipe >= 0) send(g_parent_pipe, fmt::format("group {}{}\n", live ? '+' : '-', group));
}

std::string signal_description(int sig) {
  static const std::pair<int, const char*> names[] = {
      {SIGSEGV, "SIGSEGV"}, {SIGABRT, "SIGABRT"}, {SIGBUS, "SIGBUS"},   {SIGFPE, "SIGFPE"},
      {SIGILL, "SIGILL"},   {SIGKILL, "SIGKILL"}, {SIGTERM, "SIGTERM"}, {SIGINT, "SIGINT"},
      {SIGTRAP, "SIGTRAP"}, {SIGSYS, "SIGSYS"},   {SIGPIPE, "SIGPIPE"}, {SIGXCPU, "SIGXCPU"},
      {SIGXFSZ, "SIGXFSZ"}, {SIGHUP, "SIGHUP"},   {SIGQUIT, "SIGQUIT"}, {SIGALRM, "SIGALRM"},
  };
  std::string name = fmt::format("signal {}", sig);
  for (const auto& [n, text] : names)
    if (n == sig) name = text;
  std::string what = ::strsignal(sig);
  if (!what.empty()) what[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(what[0])));
  return fmt::format("{} ({})", name, what);
}

void close_inherited_files(int keep) {
  if (keep < 3) {
    ::close_range(3, ~0U, 0);
    return;
  }
  if (keep > 3) ::close_range(3, unsigned(keep) - 1, 0);
  ::close_range(unsigned(keep) + 1, ~0U, 0);
}

Result run_engine_isolated(const Scene& scene, const EngineEntry& entry, const RunOptions& options,
                           const IsolationOptions& isolation) {
  if (entry.info.own_process && !isolation.fresh_process) {
    // Isolated already: a crash there is the engine process's, which the run reports; a step stuck
    // past the limits a child would be killed at ends that process. Its process serves the next run.
    RunOptions bounded = options;
    const double grace = stuck_grace_s(isolation.timeout_s);
    if (isolation.timeout_s < 1e8)
      bounded.stuck.wall_end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(isolation.timeout_s + grace)),
      bounded.stuck.wall_what = fmt::format("the time limit of {} s and {:g} s more", isolation.timeout_s, grace);
    if (options.cost_limit)
      bounded.stuck.cpu_s = kStuckCostFactor * options.cost_limit->seconds + kStuckCostMargin_s,
      bounded.stuck.cpu_what = fmt::format("over {:g} times its cost limit and {:g} s more ({})", kStuckCostFactor,
                                           kStuckCostMargin_s, options.cost_limit->what);
    std::string trajectory_error;
    Result r = run_limited(scene, entry, bounded, isolation, trajectory_error);
    if (isolation.trajectory_error) *isolation.trajectory_error = trajectory_error;
    return r;
  }
  Result r = result_header(scene, entry, options);
  int fds[2];
  // Close-on-exec: an engine process started beside this run from another thread never holds it.
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    r.status = RunStatus::failed;
    r.error = fmt::format("cannot isolate the run: pipe: {}", std::strerror(errno));
    return r;
  }
  std::fflush(nullptr);  // or the child's copies of unwritten output could be written twice
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]), ::close(fds[1]);
    r.status = RunStatus::failed;
    r.error = fmt::format("cannot isolate the run: fork: {}", std::strerror(err));
    return r;
  }
  if (pid == 0) {
    // Dies with this process (a SIGKILL to it leaves no run behind, busy on a core).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);  // the parent died before the request took
    install_interrupt_handlers(false);
    close_inherited_files(fds[1]);
    const CorePin pin(isolation.core);  // until the child exits
    child_main(fds[1], scene, entry, options, isolation);
  }
  ::close(fds[1]);
  std::optional<double> cpu_limit_s;
  if (options.cost_limit) cpu_limit_s = kStuckCostFactor * options.cost_limit->seconds + kStuckCostMargin_s;
  const ChildOutcome outcome = ChildWatcher(pid, fds[0], isolation.timeout_s + stuck_grace_s(isolation.timeout_s),
                                            options.progress, cpu_limit_s)
                                   .watch();
  ::close(fds[0]);
  if (isolation.trajectory_error) *isolation.trajectory_error = outcome.trajectory_error;
  return outcome_to_result(outcome, std::move(r), isolation.timeout_s, options.cost_limit);
}

}  // namespace ballbench

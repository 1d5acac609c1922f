#include "child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "engine.h"
#include "engine_group.h"
#include "interrupt.h"
#include "isolated_run.h"

namespace ballbench {
namespace {

constexpr size_t kStderrKeep = 4096;  // bytes of the child's stderr kept for error messages
constexpr auto kExitGrace = std::chrono::milliseconds(500);  // for a child told to stop (stdin closed)
// A state block follows its reply line at once (PROTOCOL.md): this long without a byte of it, the
// block is short, whatever the reply time limit, so an engine that stays alive after a short block
// is named promptly. Far above a pipe's pause under load.
constexpr auto kBlockPause = std::chrono::seconds(5);
// How often a wait under a CPU bound, or asked to stop, looks again (ms).
constexpr int kCpuCheckMs = 250;
// Seconds a step asked to stop has to end before its process is killed (a forked run's child has
// as long).
constexpr int kInterruptGraceS = 10;

int ms_until(ChildProcess::Clock::time_point deadline) {
  const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - ChildProcess::Clock::now()).count() + 1;
  return static_cast<int>(std::clamp<long long>(left, 0, 60'000));
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

std::string join_argv(const std::vector<std::string>& argv) { return fmt::format("{}", fmt::join(argv, " ")); }

// The process groups of the children started and not yet ended, with the process that started
// each (a fork inherits the list, not the children). A run's child process ends by quick_exit
// (isolated_run.cpp), without destructors: its engines' groups, helpers included, end with it.
// Never destroyed: engines held by static objects (the registry's process pools) end at exit,
// after any function-local static would be gone.
std::vector<std::pair<pid_t, pid_t>>& live_groups() {
  static auto* groups = new std::vector<std::pair<pid_t, pid_t>>;  // (owner, group)
  return *groups;
}
// Threads start engines at once (a search's tries in parallel): the list is shared under a lock,
// held across every fork so that a forked run's child never inherits it locked mid-change.
std::mutex& live_groups_mutex() {
  static auto* m = [] {
    auto* made = new std::mutex;
    ::pthread_atfork([] { live_groups_mutex().lock(); }, [] { live_groups_mutex().unlock(); },
                     [] { live_groups_mutex().unlock(); });
    return made;
  }();
  return *m;
}

void kill_live_groups() {
  std::lock_guard lock(live_groups_mutex());
  for (const auto& [owner, group] : live_groups())
    if (owner == ::getpid()) kill_engine_group(group);
}

// A number for the calling thread that no other thread of this process gets (thread ids are
// reused once a thread ends).
unsigned long this_thread_number() {
  static std::atomic<unsigned long> next{1};
  thread_local const unsigned long number = next++;
  return number;
}

// This process's environment for the child, with kEngineGroupVariable's entry last: its value, the
// child's pid, is written by the child into `marker` (sized for any pid) before exec, without
// allocating, as a fork of a threaded process must.
std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  const std::string name = fmt::format("{}=", kEngineGroupVariable);
  for (char** e = environ; e && *e; ++e)
    if (std::string_view(*e).rfind(name, 0) != 0) env.emplace_back(*e);
  env.push_back(name + std::string(20, '\0'));
  return env;
}

// `pid` in decimal at `out`, NUL-terminated (async-signal-safe).
void write_pid(char* out, pid_t pid) {
  char digits[20];
  int n = 0;
  do digits[n++] = char('0' + pid % 10), pid /= 10;
  while (pid > 0);
  while (n > 0) *out++ = digits[--n];
  *out = '\0';
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::string& cwd)
    : label_(fmt::format("`{}`", join_argv(argv))) {
  if (argv.empty() || argv[0].empty()) throw ChildProcessError("process engine: empty command");
  int in[2], out[2], err[2], status[2];
  if (::pipe2(in, O_CLOEXEC) != 0) throw ChildProcessError(fmt::format("{}: pipe: {}", label_, std::strerror(errno)));
  if (::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0 || ::pipe2(status, O_CLOEXEC) != 0) {
    const int e = errno;
    for (int fd : {in[0], in[1]}) ::close(fd);
    throw ChildProcessError(fmt::format("{}: pipe: {}", label_, std::strerror(e)));
  }
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env = child_environment();
  std::vector<char*> envp;
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  char* marker = env.back().data() + std::string_view(kEngineGroupVariable).size() + 1;
  const pid_t parent = ::getpid();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1], status[0], status[1]}) ::close(fd);
    throw ChildProcessError(fmt::format("{}: fork: {}", label_, std::strerror(e)));
  }
  if (pid == 0) {
    // Dies with the thread that started it, so a killed or crashed harness leaves no engine behind.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    ::dup2(in[0], STDIN_FILENO), ::dup2(out[1], STDOUT_FILENO), ::dup2(err[1], STDERR_FILENO);
    // Nothing else of the harness's is inherited (another engine's pipes would keep it open).
    for (int fd = 3; fd < 1024; ++fd)
      if (fd != status[1]) ::close(fd);
    signal(SIGPIPE, SIG_DFL);
    // Its own process group: a Ctrl-C at the terminal reaches the harness, which stops its runs at
    // a step boundary, and not the engine, which must still answer until then (Node resets an
    // ignored SIGINT at start-up, so ignoring it would not do).
    ::setpgid(0, 0);
    // Everything it starts carries its group in the environment (engine_group.h).
    write_pid(marker, ::getpid());
    int e = 0;
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) e = errno;
    if (e == 0) ::execvpe(args[0], args.data(), envp.data()), e = errno;
    [[maybe_unused]] const ssize_t w = ::write(status[1], &e, sizeof e);
    ::_exit(127);
  }
  pid_ = pid, owner_ = parent, owner_thread_ = this_thread_number();
  ::close(in[0]), ::close(out[1]), ::close(err[1]), ::close(status[1]);
  in_ = in[1], out_ = out[0], err_ = err[0];
  // The status pipe closes at exec (end of file) or carries the errno of a failed chdir or exec.
  int e = 0;
  ssize_t got;
  while ((got = ::read(status[0], &e, sizeof e)) < 0 && errno == EINTR) {
  }
  ::close(status[0]);
  if (got == sizeof e) {
    while (::waitpid(pid_, &wait_status_, 0) < 0 && errno == EINTR) {
    }
    exited_ = true, failed_ = true;
    close_fd(in_), close_fd(out_), close_fd(err_);
    if (e == ENOENT && argv[0].find('/') == std::string::npos)
      throw ChildProcessError(fmt::format("{}: cannot start it: '{}' is not found on PATH", label_, argv[0]));
    throw ChildProcessError(fmt::format("{}: cannot start '{}'{}: {}", label_, argv[0],
                                        cwd.empty() ? "" : fmt::format(" in {}", cwd), std::strerror(e)));
  }
  ::fcntl(err_, F_SETFL, O_NONBLOCK);
  // Readable once the child has exited, so its end is seen at once even while a process it started
  // holds its output open (Linux 5.3; without it, the end of output or the time limit tells).
  exit_fd_ = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
  if (exit_fd_ >= 0) ::fcntl(exit_fd_, F_SETFD, FD_CLOEXEC);
  static const bool at_exit = std::at_quick_exit(kill_live_groups) == 0;
  (void)at_exit;
  {
    std::lock_guard lock(live_groups_mutex());
    live_groups().emplace_back(owner_, pid_);
  }
  note_engine_group(pid_, true);
}

ChildProcess::~ChildProcess() {
  if (owner_ != ::getpid()) {  // a fork's copy: the child belongs to the process that started it
    close_fd(in_), close_fd(out_), close_fd(err_), close_fd(exit_fd_);
    return;
  }
  close_fd(in_);
  if (pid_ > 0 && !exited_) {
    const auto until = Clock::now() + kExitGrace;
    while (::waitpid(pid_, &wait_status_, WNOHANG) == 0 && Clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (::waitpid(pid_, &wait_status_, WNOHANG) == 0) {
      ::kill(pid_, SIGKILL);
      while (::waitpid(pid_, &wait_status_, 0) < 0 && errno == EINTR) {
      }
    }
  }
  // What the engine started (a helper that kept its output open, in a session of its own or not)
  // ends with it.
  if (pid_ > 0) kill_engine_group(pid_);
  {
    std::lock_guard lock(live_groups_mutex());
    std::erase(live_groups(), std::pair{owner_, pid_});
  }
  if (pid_ > 0) note_engine_group(pid_, false);
  close_fd(out_), close_fd(err_), close_fd(exit_fd_);
}

bool ChildProcess::usable() const { return owner_ == ::getpid() && !failed_ && !exited_; }

bool ChildProcess::serves_this_thread() const { return usable() && owner_thread_ == this_thread_number(); }

void ChildProcess::bound(std::optional<Clock::time_point> wall_end, std::optional<double> cpu_s) {
  bounded_ = true, wall_end_ = wall_end;
  cpu_bound_s_.reset();
  if (cpu_s && ::clock_getcpuclockid(pid_, &cpu_clock_) == 0) cpu_bound_s_ = cpu_s, cpu_at_write_s_ = cpu_spent_s();
}

void ChildProcess::unbound() { bounded_ = false, wall_end_.reset(), cpu_bound_s_.reset(), interrupt_end_.reset(); }

double ChildProcess::cpu_spent_s() const {
  timespec ts{};
  if (::clock_gettime(cpu_clock_, &ts) != 0) return 0;
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

int ChildProcess::check_bounds(int wait_ms) {
  if (!bounded_) return wait_ms;
  const auto stuck = [&](StepStuck::By by, const std::string& what, double cpu = 0) {
    ::kill(pid_, SIGKILL);
    kill_engine_group(pid_);
    failed_ = true;
    return StepStuck(fmt::format("{}: {}: killed", label_, what), by, cpu);
  };
  if (interrupt_signal()) {  // a grace to end the step, as a forked run's child has
    if (interrupt_hurried()) throw stuck(StepStuck::By::interrupt, "asked again to stop, inside a step");
    if (!interrupt_end_) interrupt_end_ = Clock::now() + std::chrono::seconds(kInterruptGraceS);
    if (Clock::now() >= *interrupt_end_)
      throw stuck(StepStuck::By::interrupt, fmt::format("asked to stop, and still in its step {} s later", kInterruptGraceS));
    wait_ms = std::min(wait_ms, kCpuCheckMs);
  }
  if (cpu_bound_s_) {
    if (const double spent = cpu_spent_s() - cpu_at_write_s_; spent > *cpu_bound_s_)
      throw stuck(StepStuck::By::cpu, fmt::format("{:.3g} s of CPU on one request, past its bound of {:g} s", spent,
                                                  *cpu_bound_s_),
                  spent);
    wait_ms = std::min(wait_ms, kCpuCheckMs);
  }
  if (wall_end_ && Clock::now() >= *wall_end_) throw stuck(StepStuck::By::time_limit, "no reply by the run's time limit");
  return wall_end_ ? std::min(wait_ms, ms_until(*wall_end_)) : wait_ms;
}

bool ChildProcess::has_exited() {
  if (!exited_ && owner_ == ::getpid() && pid_ > 0 && ::waitpid(pid_, &wait_status_, WNOHANG) == pid_) exited_ = true;
  return exited_;
}

void ChildProcess::write(const std::string& bytes, Clock::time_point deadline) {
  // A child that exited raises SIGPIPE on the write, which would end the harness: it is blocked
  // for this thread and a pending one taken back, so the write fails with EPIPE instead.
  sigset_t pipe_set, old;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
  if (cpu_bound_s_) cpu_at_write_s_ = cpu_spent_s();
  const char* p = bytes.data();
  size_t left = bytes.size();
  int error = 0;
  while (left > 0 && error == 0) {
    pollfd fds[2] = {{in_, POLLOUT, 0}, {err_, POLLIN, 0}};
    const int ready = ::poll(fds, 2, ms_until(deadline));
    if (ready < 0 && errno != EINTR) error = errno;
    if (fds[1].revents) drain_stderr();
    if (ready == 0 && Clock::now() >= deadline) error = ETIMEDOUT;
    if (ready <= 0 || !(fds[0].revents & (POLLOUT | POLLERR | POLLHUP))) continue;
    const ssize_t n = ::write(in_, p, std::min<size_t>(left, 1 << 16));
    if (n < 0 && errno != EINTR && errno != EAGAIN) error = errno;
    if (n > 0) p += n, left -= static_cast<size_t>(n);
  }
  timespec zero{0, 0};
  while (sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  if (error == ETIMEDOUT) throw failure("stopped reading its input (no request taken within the time limit)");
  if (error != 0) throw failure(fmt::format("cannot be written to ({})", std::strerror(error)));
}

void ChildProcess::pump(Clock::time_point deadline, const char* waiting_for, size_t block_bytes, bool stop_on_interrupt) {
  const auto short_by = [&] {
    return fmt::format("a {} {} bytes short (of {})", waiting_for, block_bytes - std::min(block_bytes, inbox_.size()),
                       block_bytes);
  };
  // A block's bytes may pause kBlockPause at most; a reply line may take the whole time limit.
  const auto pause_end = block_bytes > 0 ? std::min(deadline, Clock::now() + kBlockPause) : deadline;
  for (;;) {
    if (stop_on_interrupt && interrupt_signal())
      throw Interrupted{fmt::format("waiting for a {} from engine process {}", waiting_for, label_)};
    if (Clock::now() >= pause_end) {
      if (block_bytes > 0)
        throw failure(fmt::format("sent {}, and no more {}", short_by(),
                                  pause_end < deadline ? fmt::format("for {} s (a block follows its reply line at once)",
                                                                     kBlockPause.count())
                                                       : std::string("within the time limit")));
      throw failure(fmt::format("sent no {} within the time limit", waiting_for));
    }
    const int wait_ms = check_bounds(ms_until(pause_end));
    pollfd fds[3] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}, {exit_seen_ ? -1 : exit_fd_, POLLIN, 0}};
    const int ready = ::poll(fds, 3, wait_ms);
    if (ready < 0 && errno != EINTR) throw failure(fmt::format("cannot be read ({})", std::strerror(errno)));
    if (ready <= 0) continue;
    if (fds[1].revents) drain_stderr();
    if (fds[2].revents && !fds[0].revents) {
      // It exited with nothing more to read, its output perhaps held open by a process it started.
      exit_seen_ = true;
      pollfd more{out_, POLLIN, 0};
      if (::poll(&more, 1, 0) > 0) continue;
      while (!exited_ && ::waitpid(pid_, &wait_status_, 0) < 0 && errno == EINTR) {
      }
      exited_ = true;
      drain_stderr();
      if (block_bytes > 0 && !inbox_.empty()) throw failure(fmt::format("exited after {}", short_by()));
      throw failure(fmt::format("exited before sending a {}", waiting_for));
    }
    if (!fds[0].revents) continue;
    char buf[1 << 16];
    const ssize_t n = ::read(out_, buf, sizeof buf);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) {
      // End of its output: it exited or is exiting. A moment for its last stderr and its status.
      const auto until = Clock::now() + kExitGrace;
      while (!exited_ && Clock::now() < until) {
        drain_stderr();
        if (::waitpid(pid_, &wait_status_, WNOHANG) == pid_) exited_ = true;
        else std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
      drain_stderr();
      if (block_bytes > 0 && !inbox_.empty()) throw failure(fmt::format("closed its output after {}", short_by()));
      throw failure(fmt::format("closed its output before sending a {}", waiting_for));
    }
    inbox_.append(buf, static_cast<size_t>(n));
    return;
  }
}

std::string ChildProcess::read_line(Clock::time_point deadline, size_t max_bytes, bool stop_on_interrupt) {
  size_t end;
  while ((end = inbox_.find('\n')) == std::string::npos) {
    if (inbox_.size() > max_bytes)
      throw failure(fmt::format("sent garbage: a reply line longer than {} bytes, starting '{}'", max_bytes,
                                inbox_.substr(0, 60)));
    pump(deadline, "reply", 0, stop_on_interrupt);
  }
  std::string line = inbox_.substr(0, end);
  inbox_.erase(0, end + 1);
  return line;
}

void ChildProcess::read_bytes(void* out, size_t n, Clock::time_point deadline, const char* what) {
  while (inbox_.size() < n) pump(deadline, what, n);
  std::memcpy(out, inbox_.data(), n);
  inbox_.erase(0, n);
}

bool ChildProcess::has_unread_output() {
  if (!inbox_.empty()) return true;
  if (out_ < 0) return false;
  pollfd p{out_, POLLIN, 0};
  if (::poll(&p, 1, 0) <= 0 || !(p.revents & POLLIN)) return false;
  char buf[1 << 12];
  const ssize_t n = ::read(out_, buf, sizeof buf);
  if (n > 0) inbox_.append(buf, static_cast<size_t>(n));
  return n > 0;
}

void ChildProcess::drain_stderr() {
  char buf[4096];
  while (err_ >= 0) {
    const ssize_t n = ::read(err_, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return;  // nothing more for now (non-blocking)
    if (n == 0) {       // the child closed its stderr: stop polling it, or poll would spin on the hang-up
      close_fd(err_);
      return;
    }
    stderr_.append(buf, static_cast<size_t>(n));
    if (stderr_.size() > 2 * kStderrKeep) stderr_.erase(0, stderr_.size() - kStderrKeep);
  }
}

std::string ChildProcess::stderr_tail() {
  drain_stderr();
  std::string s = stderr_.size() > kStderrKeep ? stderr_.substr(stderr_.size() - kStderrKeep) : stderr_;
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.erase(0, 1);
  std::string out;
  for (char c : s) {
    if (c == '\n') out += " | ";
    else if (c != '\r') out += c;
  }
  return out;
}

std::string ChildProcess::exit_description() {
  if (!exited_ && pid_ > 0 && ::waitpid(pid_, &wait_status_, WNOHANG) == pid_) exited_ = true;
  if (!exited_) return "";
  if (WIFSIGNALED(wait_status_)) return fmt::format(" (killed by {})", signal_description(WTERMSIG(wait_status_)));
  if (WIFEXITED(wait_status_)) return fmt::format(" (exited with status {})", WEXITSTATUS(wait_status_));
  return "";
}

ChildProcessError ChildProcess::failure(const std::string& what) {
  failed_ = true;
  const std::string how = exit_description();
  const std::string err = stderr_tail();
  return ChildProcessError(
      fmt::format("engine process {} {}{}{}", label_, what, how, err.empty() ? "" : "; its stderr: " + err));
}

}  // namespace ballbench

#pragma once
// The harness's side of the engine process protocol (PROTOCOL.md): requests as JSON lines, replies
// as JSON lines, states as a block of little-endian doubles after their reply. Each call waits for
// its reply at most the connection's time limit; a reply that breaks the protocol is an error
// naming what was wrong, never a guess.
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "child_process.h"
#include "core_wait.h"
#include "engine.h"
#include "scene.h"
#include "state.h"

namespace ballbench {

// The version the harness speaks; it also takes engines that answer with an older one it lists
// in PROTOCOL.md (version 1: every capability left out defaults to true, friction included).
inline constexpr int kProtocolVersion = 3;
inline constexpr int kOldestProtocolVersion = 1;

// What the handshake says about the engine.
struct Handshake {
  EngineInfo info;
  std::vector<std::string> settings_keys;  // every key its settings accept
  int protocol = kProtocolVersion;         // the version the engine answered with
};

// The capabilities an engine has that its handshake leaves out, for a protocol version.
Capabilities default_capabilities(int protocol);

class ProtocolClient {
 public:
  ProtocolClient(const std::vector<std::string>& argv, const std::string& cwd, double timeout_s);

  // Sends hello without waiting, so several engines start up at once; hello_reply() takes it.
  void send_hello();
  // `stop_on_interrupt`: a stop request ends the wait (Interrupted), for a handshake before any run.
  Handshake hello_reply(bool stop_on_interrupt = false);

  // A new world from `scene`, replacing any world before; returns the effective settings the
  // engine reports. A reply with kind "settings" is the user's error: InputError.
  nlohmann::json load_scene(const Scene& scene, const std::string& profile, const nlohmann::json& settings);
  // A step's time: the engine's own clock around its step call (s), and that time less the
  // share of the round trip its process waited for a core (CoreWait): the step as taken alone.
  struct StepTime {
    double own_s = 0, alone_s = 0;
  };
  // One step of dt; `out` gets the state after it (scene order).
  StepTime step(double dt, State& out);
  void read(State& out);

  // Protocol 3's `steps`: several steps of dt in one request, each step's state and time back, so
  // the pipe's round trip is paid once for them all. The steps before a failure are kept: `done`
  // of them arrived and were checked, and `failure` holds why the next did not.
  bool batches() const { return protocol_ >= 3; }
  struct Batch {
    std::vector<State> states;  // after each step, in order (the first `done`)
    std::vector<StepTime> times;
    int done = 0;
    std::exception_ptr failure;  // set when fewer than the steps asked for arrived
  };
  void steps(double dt, int count, Batch& out);
  // The bytes of one state's block for the scene loaded, with the fields the harness needs.
  size_t state_bytes() const { return size_t(n_) * (rotation_ ? 7 : 5) * sizeof(double); }

  bool usable() const { return child_.usable(); }
  bool serves_this_thread() const { return child_.serves_this_thread(); }
  bool has_exited() { return child_.has_exited(); }
  // The longest wait for a reply from now on (s).
  void set_reply_timeout(double seconds) { timeout_s_ = seconds; }
  void bound(std::optional<ChildProcess::Clock::time_point> wall_end, std::optional<double> cpu_s) {
    child_.bound(wall_end, cpu_s);
  }
  void unbound() { child_.unbound(); }
  int protocol() const { return protocol_; }
  // False where the OS does not say how long the process waited for a core: alone_s is own_s.
  bool measures_wait() const { return wait_.available(); }
  const std::string& label() const { return child_.label(); }

 private:
  nlohmann::json request(const nlohmann::json& message, const char* op);
  nlohmann::json reply(const char* op, bool stop_on_interrupt = false);
  // A state reply's header: its columns and the time of each of its `states` blocks.
  struct StateLayout {
    long n = 0;
    std::vector<double> t;
    long id = 0, x = 0, y = 0, vx = 0, vy = 0, w = -1, angle = -1;  // columns (-1: none)
    size_t fields = 0;
  };
  StateLayout state_layout(const nlohmann::json& reply, const char* op, size_t states);
  void read_block(const StateLayout& layout, size_t k, State& out, const char* op);
  void read_state(const nlohmann::json& reply, State& out, const char* op);
  // The engine's own time for the step just counted, checked against the round trip it lies in.
  double checked_step_time(const nlohmann::json& value, double round_trip);
  // The share of the last round trip its process waited for a core.
  double wait_share(double round_trip) const;

  void check_time(double t, const char* op);

  ChildProcess child_;
  CoreWait wait_;
  double waited_s_ = 0;       // wait_'s reading at the last reply
  double wait_since_s_ = 0;   // how much of it came since the reply before
  double timeout_s_;
  int protocol_ = kProtocolVersion;
  bool float_precision_ = false;  // the handshake says the engine computes in float
  long steps_ = 0;                // steps since the scene was loaded
  double t_ = 0;                  // their dts summed: the simulated time its state must carry
  int n_ = 0;  // balls in the scene loaded
  bool rotation_ = false;  // the scene loaded rotates: states carry w and angle
  std::vector<double> block_;  // the last state's doubles
  std::vector<char> seen_;     // the ids it held
};

}  // namespace ballbench

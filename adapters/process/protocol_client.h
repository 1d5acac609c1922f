#pragma once
// The harness's side of the engine process protocol (PROTOCOL.md): requests as JSON lines, replies
// as JSON lines, states as a block of little-endian doubles after their reply. Each call waits for
// its reply at most the connection's time limit; a reply that breaks the protocol is an error
// naming what was wrong, never a guess.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "child_process.h"
#include "engine.h"
#include "scene.h"
#include "state.h"

namespace ballbench {

inline constexpr int kProtocolVersion = 1;

// What the handshake says about the engine.
struct Handshake {
  EngineInfo info;
  std::vector<std::string> settings_keys;  // every key its settings accept
};

class ProtocolClient {
 public:
  ProtocolClient(const std::vector<std::string>& argv, const std::string& cwd, double timeout_s);

  // Sends hello without waiting, so several engines start up at once; hello_reply() takes it.
  void send_hello();
  Handshake hello_reply();

  // A new world from `scene`, replacing any world before; returns the effective settings the
  // engine reports. A reply with kind "settings" is the user's error: InputError.
  nlohmann::json load_scene(const Scene& scene, const std::string& profile, const nlohmann::json& settings);
  // One step of dt; `out` gets the state after it (scene order). Returns the engine's own step time (s).
  double step(double dt, State& out);
  void read(State& out);

  bool usable() const { return child_.usable(); }
  const std::string& label() const { return child_.label(); }

 private:
  nlohmann::json request(const nlohmann::json& message, const char* op);
  nlohmann::json reply(const char* op);
  void read_state(const nlohmann::json& header, State& out, const char* op);

  ChildProcess child_;
  double timeout_s_;
  int n_ = 0;  // balls in the scene loaded
  bool rotation_ = false;  // the scene loaded rotates: states carry w and angle
  std::vector<double> block_;  // the last state's doubles
};

}  // namespace ballbench

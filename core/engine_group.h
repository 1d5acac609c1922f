#pragma once
// An engine process and everything it starts. Its process group holds what it starts plainly; a
// helper that starts a session of its own leaves the group, so every process an engine starts
// also carries kEngineGroupVariable=<the engine's pid> in its environment, which it passes on.
namespace ballbench {

inline constexpr const char* kEngineGroupVariable = "BALLBENCH_ENGINE_GROUP";

// SIGKILL to process group `group` and to every process of this user whose environment names it
// as its engine group (read from /proc), whatever its session.
void kill_engine_group(int group);

}  // namespace ballbench

#pragma once
// A scene with its balls in a given state, as a scene file (scenarios/README.md) that reads back
// as the same scene: `ballbench settle` writes a settled pile this way, and `match` the state a
// found configuration is timed from. toml++ writes it, every number in the digits that read back
// as the same double.
#include <string>

#include "scene.h"
#include "state.h"

namespace ballbench {

struct SceneSnapshot {
  std::string text;    // the TOML
  int pushed_in = 0;   // balls whose centre was moved back inside the box (they sank into a wall)
  double pushed_by = 0;  // the farthest such move, over the ball's radius
};

// `scene` with every ball explicit at `state`'s positions, velocities and spins, renamed `name`,
// running `duration` seconds; its other fields (step, gravity, restitution, friction, inertia,
// container, metrics, settings) kept. Balls start as they are, so the file allows overlap, and it
// states the source scene's spec in its [accuracy] table (allowing overlap would drop the overlap
// term of its class). A ball that sank into a wall is put back touching it, and counted.
SceneSnapshot scene_at_state(const Scene& scene, const State& state, const std::string& name, double duration);

}  // namespace ballbench

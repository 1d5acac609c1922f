#pragma once
// A hand-made run for the tests of what reads results (the report, the spec's verdict): `engine`
// on `scene` from scenarios/, ok, n balls over `steps` steps of 0.01 s, every metric a run measures
// with nothing happening. Each test sets what it is about on top.
#include <string>
#include <utility>

#include "metrics/meter_set.h"
#include "result.h"

namespace ballbench {

inline Result made_run(std::string engine, std::string scene, int n = 20, long steps = 100) {
  Result r;
  r.engine = std::move(engine);
  r.engine_version = "1";
  r.profile = "default";
  r.scene = std::move(scene);
  r.scene_source = "/x/scenarios/" + r.scene + ".toml";
  r.n = n, r.dt = 0.01, r.steps = r.steps_done = steps;
  r.metrics = resting_values();
  return r;
}

}  // namespace ballbench

#pragma once
// The work-precision sweep behind `ballbench sweep` and the report: which points to run for each
// engine, and running them (isolated, so a crash marks one point and the sweep goes on).
#include <string>
#include <vector>

#include "engine.h"
#include "run_engines.h"
#include "scene.h"
#include "shard.h"
#include "sweep_result.h"

namespace ballbench::cli {

struct SweepOptions {
  std::string profile = "all";                  // as for `run --profile`
  std::vector<double> dt_factors{2, 1, 0.5, 0.25};  // the step-size series, times the scene's dt
  double horizon = 0.2;                         // error taken at this simulated time (s)
  int repeats = 3;                              // timing runs per point
  bool knobs = true;                            // also each engine's SweepKnobs (EngineInfo)
  Isolation isolation{true, 120};
  const EngineEntry* reference = nullptr;       // the error is measured against it (required)
  bool quiet = false;                           // no progress on stderr
  Shard shard;                                  // the share of the plan's points to run (shard.h)
};

// One point to run: an engine, a profile, a step size and the settings set on top of the profile.
struct SweepPlanItem {
  const EngineEntry* engine;
  std::string profile, knob;
  nlohmann::json value, overrides;
  double dt;
  long steps;
};

// The points of a sweep, in run order: per engine and profile, the dt series, then each knob value
// that differs from the profile's own at the scene's dt.
std::vector<SweepPlanItem> plan_sweep(const Scene& scene, const std::vector<const EngineEntry*>& engines,
                                      const SweepOptions& options);

// The plan as recorded in every shard's result: what identifies one sweep.
nlohmann::json plan_record(const Scene& scene, const std::vector<SweepPlanItem>& plan, const SweepOptions& options);

SweepResult run_sweep(const Scene& scene, const std::vector<const EngineEntry*>& engines, const SweepOptions& options,
                      const nlohmann::json& context);

// Each engine's Pareto front, fastest first, as a table on stdout.
void print_pareto(const SweepResult& s);

}  // namespace ballbench::cli

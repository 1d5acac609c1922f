#pragma once
// Equal accuracy (`ballbench match`): for each engine and profile, the cheapest configuration that
// meets one accuracy spec (accuracy_spec.h) on a scene. The step size is searched geometrically
// (dt / 2^k, the scene's duration kept): first the profile as it is, coarse to fine until it meets
// the spec; then each of the engine's own accuracy knobs (EngineInfo::sweep_knobs, one at a time on
// top of the profile) from two halvings coarser than that, refined while it can still be cheaper
// than the best found: a step half as long costs at least kHalvingCostFloor times as much per scene
// step.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_spec.h"
#include "match_result.h"
#include "engine.h"
#include "run_engines.h"
#include "run_status.h"
#include "scene.h"
#include "shard.h"

namespace ballbench::cli {

// Halving the step doubles the steps per scene step; an engine's step rarely gets cheaper by more
// than a quarter when it is shorter (fewer contacts to find, solver sweeps ending early), so a
// configuration whose cost times this is already above the best found is not tried finer.
inline constexpr double kHalvingCostFloor = 1.5;

// A knob's configuration is preferred to the profile as it is only when it costs less than this
// fraction of it: one run's timings differ by some 5 - 10% on a shared machine.
inline constexpr double kKnobCostMargin = 0.85;

struct MatchOptions {
  std::string profile = "all";  // as for `run --profile`
  AccuracySpec spec;
  std::vector<std::string> spec_texts;  // the --spec terms over the scene's own, for the reproducing commands
  int max_halvings = 6;         // dt / 2^k for k = 0 .. this
  double budget_s = 600;        // wall time for one engine and profile's search (s)
  int repeats = 2;              // timing runs of the found configuration beside its measuring run
  bool knobs = true;            // also each engine's sweep knobs
  Isolation isolation{true, 600};
  const EngineEntry* reference = nullptr;            // for spec terms against the reference
  const EngineEntry* converged_reference = nullptr;  // where the reference refuses the scene
  bool quiet = false;
  Shard shard;                  // shards deal out the (engine, profile) searches
};

MatchResult run_match(const Scene& scene, const std::vector<const EngineEntry*>& engines, const MatchOptions& options,
                      const nlohmann::json& context);

// The table: one row per engine and profile, then our solver's ratio to the cheapest external
// engine that met the spec (against `target`, a ratio, where given), then each row's reproducing
// command.
void print_match(const MatchResult& m, std::optional<double> target = std::nullopt);

}  // namespace ballbench::cli

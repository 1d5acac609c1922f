#pragma once
// Equal accuracy (`ballbench match`): for each engine and profile, the cheapest configuration that
// meets one accuracy spec (accuracy_spec.h) on a scene. The step size is searched geometrically
// (dt / 2^k, the scene's duration kept): first the profile as it is, coarse to fine until it meets
// the spec; then each of the engine's own accuracy knobs (EngineInfo::sweep_knobs, one at a time on
// top of the profile) from two halvings coarser than that, refined while it can still be cheaper
// than the best found: a step half as long costs at least kHalvingCostFloor times as much per scene
// step.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_spec.h"
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

struct MatchOptions {
  std::string profile = "all";  // as for `run --profile`
  AccuracySpec spec;
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

// One configuration tried: a profile, a knob on top of it (or none) and a step size.
struct MatchTry {
  std::string engine, profile;
  std::string knob;              // "" for the profile as it is
  nlohmann::json value;          // the knob's value
  int halvings = 0;              // dt = scene dt / 2^halvings
  double dt = 0;
  RunStatus status = RunStatus::ok;  // the run's
  std::string error;
  bool met = false;
  std::string why_not;           // the failing terms, or the run's status
  nlohmann::json figures;        // every spec term's figure
  // Cost per ball per scene step (ns): the engine's own step time (self-timed by an engine in
  // another process), and for such an engine the harness's time with the pipe beside it.
  double cost_ns = 0;
  std::optional<double> cost_pipe_ns;
  double wall_s = 0;             // the run's wall time, harness included (s)
  nlohmann::json settings;       // the engine's effective settings
};

// Each search's outcome: the cheapest configuration that met the spec, or the best one tried.
struct MatchOutcome {
  std::string engine, profile;
  std::string role;      // the engine's (role_name): ours is compared with the external engines
  bool reached = false;
  int found = -1;        // index into MatchResult::tries of the cheapest that met
  int best = -1;         // the try nearest the spec that did not meet it (its worst term's ratio to its bound)
  int tries = 0;
  double finest_dt = 0;  // the finest step tried (s)
  std::vector<double> cost_repeats;  // the found configuration's cost in each timing run (ns)
  double cost_ns = 0;    // their median
  std::optional<double> cost_pipe_ns;
  std::string stopped;   // why the search ended without a result ("budget", "max halvings"), or ""
  std::string command;   // the `ballbench run` that reproduces the found (or best) point
};

struct MatchResult {
  std::string scene, scene_source, scene_class;
  int n = 0;
  double dt = 0;  // the scene's
  AccuracySpec spec;
  nlohmann::json context;
  std::string interrupted;
  int shard_index = 1, shard_count = 1;
  std::vector<MatchTry> tries;
  std::vector<MatchOutcome> outcomes;
};

MatchResult run_match(const Scene& scene, const std::vector<const EngineEntry*>& engines, const MatchOptions& options,
                      const nlohmann::json& context);

// The table: one row per engine and profile, then our solver's ratio to the cheapest external
// engine that met the spec, then each row's reproducing command.
void print_match(const MatchResult& m);

nlohmann::json to_json(const MatchResult& m);
MatchResult match_from_json(const nlohmann::json& j);
// JSON (the whole result) and CSV (every try), each written atomically.
void write_match_files(const MatchResult& m, const std::string& json_path, const std::string& csv_path);
MatchResult read_match_file(const std::string& path);
// Shards of one match (same scene, spec and shard count, each once): one result.
MatchResult merge_match_shards(const std::vector<MatchResult>& shards, const std::vector<std::string>& names);

}  // namespace ballbench::cli

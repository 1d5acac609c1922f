#pragma once
// A work-precision sweep (`ballbench sweep`): for each engine, points that vary one accuracy knob
// at a time, each with its step time (median of repeated runs, with spread) and its error against
// the reference at a fixed horizon. Written as JSON and CSV; the report reads the JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_status.h"

namespace ballbench {

struct SweepPoint {
  std::string engine, profile;
  std::string knob;                 // "dt", or the settings key varied on top of the profile
  nlohmann::json value;             // the knob's value at this point
  double dt = 0;                    // (s)
  long steps = 0;                   // to the horizon
  nlohmann::json settings;          // the engine's effective settings (every knob, defaults included)
  RunStatus status = RunStatus::ok;  // of the run measured against the reference (Result::status)
  // That run's states were read (Result::measured): without them the error and counts below are no
  // measurement, and the JSON and CSV hold null (an empty cell) for each.
  bool measured = true;
  std::string error;
  std::vector<double> ns_per_ball_step;  // one per timing repeat (engine step time only)
  std::vector<double> engine_s;     // one per timing repeat: engine time to the horizon (s)
  double pos_rms = 0;               // position RMS error against the reference at the horizon (m)
  double vel_rms = 0;               // the same for velocities (m/s)
  double energy_rel = 0;            // max |E - E_ref| / E_ref(0) over the run
  int tunnelling = 0, sticking = 0; // wall + pair events (metrics/tunnelling.h, metrics/sticking.h)
  bool pareto = false;              // on its engine's Pareto front (engine time vs pos_rms)
  long plan_index = 0;              // its place in the sweep's plan (shards hold some of the places)

  double ns_median() const;
  double engine_s_median() const;
};

struct SweepResult {
  std::string scene;
  int n = 0;
  double horizon = 0;        // simulated time at which the error is taken (s)
  std::string reference;     // engine the error is measured against
  int repeats = 0;           // timing runs per point
  nlohmann::json context;    // machine, compiler, command, date
  std::string interrupted;   // "SIGINT"/"SIGTERM" if the sweep was stopped: its points are those run so far
  // What the whole sweep runs (scene, horizon, reference, repeats, every point's engine, profile,
  // knob and value), whichever shard this is; shards of one sweep have the same plan.
  nlohmann::json plan;
  int shard_index = 1, shard_count = 1;  // this file holds the points of shard index of count (1/1: all)
  std::vector<SweepPoint> points;
};

// Shards of one sweep, one SweepResult each (their file names, for messages): the points of all of
// them in plan order, Pareto fronts marked over all; context of the first, with every shard's as
// context.shards. Throws InputError naming the file if the shards are of different plans, if one
// is given twice or missing, or if one was interrupted.
SweepResult merge_sweep_shards(const std::vector<SweepResult>& shards, const std::vector<std::string>& names);

double median(std::vector<double> v);

// Marks each engine's Pareto front: the ok points that no other ok point of the same engine (any
// profile) beats beyond the timing noise: one beats another when its position error is no larger and
// its engine time no longer (its slowest repeat not above the other's fastest), and it is either
// more accurate or faster beyond the noise (its slowest repeat below the other's fastest). Two
// points whose repeats overlap are equally fast: timings inside the noise rank nothing.

void mark_pareto(std::vector<SweepPoint>& points);

nlohmann::json to_json(const SweepResult& s);
SweepResult sweep_from_json(const nlohmann::json& j);
std::string sweep_csv(const SweepResult& s);

// The sweep's CSV beside its JSON: "s.json" -> "s.csv", any other name -> NAME.csv.
std::string sweep_csv_path(const std::string& json_path);

void write_sweep_files(const SweepResult& s, const std::string& json_path, const std::string& csv_path);
SweepResult read_sweep_file(const std::string& path);

}  // namespace ballbench

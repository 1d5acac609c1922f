#pragma once
// The stability frontier (`ballbench stress`): per engine, profile and knob, how far the knob could
// be raised (by doublings) before a run failed, and why the next level failed. Written as JSON;
// the report reads it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ballbench {

struct FrontierRow {
  std::string engine, profile, knob;
  double base = 0;          // the knob's value in the scene (dt in s, count in balls; speed and mass ratio: 1)
  double factor = 0;        // largest factor that passed; 0: not even the scene itself
  int levels_passed = 0;    // doublings survived: factor = 2^(levels_passed - 1)
  std::string failed_next;  // why the next level failed; "" if every level passed
};

// The engine refused the scene itself (its first run was `unsupported`): it has no frontier.
inline bool refused(const FrontierRow& r) { return r.factor == 0 && r.failed_next.starts_with("unsupported"); }

struct FrontierResult {
  std::string scene;
  int n = 0;
  long steps = 0;           // per run
  int levels = 0;           // doublings tried per knob
  double energy_tolerance = 0;
  nlohmann::json context;   // machine, compiler, command, date
  std::string interrupted;  // "SIGINT"/"SIGTERM" if stress was stopped: its rows are those run so far
  std::vector<FrontierRow> rows;
};

nlohmann::json to_json(const FrontierResult& f);
FrontierResult frontier_from_json(const nlohmann::json& j);
void write_frontier_file(const std::string& path, const FrontierResult& f);
FrontierResult read_frontier_file(const std::string& path);

}  // namespace ballbench

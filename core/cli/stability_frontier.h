#pragma once
// The stability frontier behind `ballbench stress` and the report: for each engine, raise one knob
// at a time (dt, initial speed, mass ratio, ball count) by doublings until a run fails.
#include <string>
#include <vector>

#include "engine.h"
#include "frontier_result.h"
#include "run_engines.h"
#include "scene.h"

namespace ballbench::cli {

inline const std::vector<std::string> kStressKnobs{"dt", "speed", "mass-ratio", "count"};

struct StressOptions {
  std::string profile;            // as for `run --profile`
  std::vector<std::string> knobs = kStressKnobs;
  long steps = 200;               // per run
  int levels = 6;                 // doublings tried per knob
  double energy_tolerance = 0.1;  // fraction, see stress_failure
  Isolation isolation{true, 120};
  const EngineEntry* reference = nullptr;  // energy is judged against it when set
  bool quiet = false;
};

// The scene with one knob raised by `factor` (count: the box scene tiled `factor` times).
Scene stressed(const Scene& base, const std::string& knob, double factor);

// Why a run failed the stress criteria (not ok, tunnelling, energy off the reference or grown by
// more than the tolerance), or "" if it passed.
std::string stress_failure(const Result& r, double energy_tolerance);

// Throws InputError for an unknown knob, or `count` on a scene without a box.
void check_stress_knobs(const Scene& base, const std::vector<std::string>& knobs);

FrontierResult run_frontier(const Scene& base, const std::vector<const EngineEntry*>& engines,
                            const StressOptions& options, const nlohmann::json& context);

void print_frontier(const FrontierResult& f);

}  // namespace ballbench::cli

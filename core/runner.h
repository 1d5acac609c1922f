#pragma once
// Runs one engine on one scene: builds it, steps it, times the steps, samples states into metrics.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "engine.h"
#include "metrics/metrics.h"
#include "result.h"
#include "scene.h"

namespace ballbench {

class TrajectoryCsv;

struct RunOptions {
  long steps = -1;               // < 0: the scene's duration / dt
  std::string profile;           // settings profile; "" = the engine's first
  nlohmann::json overrides = nlohmann::json::object();  // settings on top of the scene's table
  MetricsConfig metrics;
  TrajectoryCsv* trajectory = nullptr;
  // Called now and then with (steps done, steps total), for progress on long runs.
  std::function<void(long, long)> progress;
};

// Never throws for what an engine does (an exception from it marks the result "failed"); throws
// InputError for bad settings.
Result run_engine(const Scene& scene, const EngineEntry& entry, const RunOptions& options);

// The engine's settings overrides: the scene's [settings.NAME] table, then `overrides` on top.
nlohmann::json merged_settings(const Scene& scene, const std::string& engine, const nlohmann::json& overrides);

}  // namespace ballbench

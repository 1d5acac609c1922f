#pragma once
// Runs the restitution calibration (calibration_result.h) for engines and their profiles, each
// run in a child process (isolated_run.h), so an engine that crashes marks its own points.
#include <vector>

#include "calibration_result.h"
#include "engine.h"
#include "run_engines.h"

namespace ballbench::cli {

struct CalibrationOptions {
  std::vector<double> requested{0.5, 0.9};
  std::vector<double> speeds{0.1, 1, 10};  // m/s
  Isolation isolation{true, 60};
};

CalibrationResult run_calibration(const std::vector<const EngineEntry*>& engines, const CalibrationOptions& options,
                                  const nlohmann::json& context);

}  // namespace ballbench::cli

#pragma once
// Restitution calibration (`ballbench report`'s calibration part): the restitution each engine and
// profile delivers against the one a scene asks for, on one ball meeting a wall and on two equal
// balls head-on, at a few impact speeds (where an engine's bounce threshold shows). The effective
// value is measured from the states, as every metric is: e = sqrt(E_after / E_before), the kinetic
// energy in the frame where the total momentum is zero (no gravity, so nothing else moves it).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_status.h"

namespace ballbench {

struct CalibrationPoint {
  std::string engine, profile;
  std::string contact;     // "ball-wall" or "ball-ball"
  double requested = 0;    // the scene's restitution
  double speed = 0;        // impact (approach) speed (m/s)
  double effective = 0;    // measured; meaningful only when measured()
  RunStatus status = RunStatus::ok;  // of the run (Result::status)
  bool tunnelled = false;            // the run was ok but passed through the contact instead of bouncing
  std::string error;

  bool measured() const { return status == RunStatus::ok && !tunnelled; }
};

// The point's status as JSON and the report write it: "tunnelled", or the run's status.
const char* calibration_status_text(const CalibrationPoint& p);

struct CalibrationResult {
  std::vector<double> requested, speeds;  // the grid measured
  nlohmann::json context;                 // machine, compiler, command, date
  std::vector<CalibrationPoint> points;
};

nlohmann::json to_json(const CalibrationResult& c);
CalibrationResult calibration_from_json(const nlohmann::json& j);
void write_calibration_file(const std::string& path, const CalibrationResult& c);
CalibrationResult read_calibration_file(const std::string& path);

}  // namespace ballbench

#pragma once
// Restitution calibration (`ballbench report`'s calibration part): the restitution each engine and
// profile delivers against the one a scene asks for, on one ball meeting a wall and on two equal
// balls head-on, at a few impact speeds (where an engine's bounce threshold shows). The effective
// value is measured from the states, as every metric is: e = sqrt(E_after / E_before), the kinetic
// energy in the frame where the total momentum is zero (no gravity, so nothing else moves it).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ballbench {

struct CalibrationPoint {
  std::string engine, profile;
  std::string contact;     // "ball-wall" or "ball-ball"
  double requested = 0;    // the scene's restitution
  double speed = 0;        // impact (approach) speed (m/s)
  double effective = 0;    // measured; meaningful only when status is "ok"
  std::string status = "ok";  // of the run (Result::status), or "tunnelled" when the contact was passed through
  std::string error;
};

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

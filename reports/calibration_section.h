#pragma once
// The report's restitution calibration (results/calibration.json).
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

std::string calibration_section(const CalibrationResult& c);

}  // namespace ballbench

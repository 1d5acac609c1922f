#pragma once
// The report's work-against-precision section of one scene (results/sweep-SCENE.json, `ballbench sweep`).
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

std::string sweep_section(const SweepResult& sw, const std::vector<Figure>& figures);

}  // namespace ballbench

#pragma once
// The report's benchmark sections (results/bench.json, results/harness.json): scaling with the ball count,
// the pipe's cost for engines in another process, and the harness's overhead.
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

std::string scaling_section(const ReportInputs& in, const std::vector<Figure>& figures);

}  // namespace ballbench

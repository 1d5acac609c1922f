#pragma once
// Work-precision fronts from the equal-accuracy searches (results/match-SCENE.json): every
// configuration an engine tried, its cost against its error, log-log, the spec marked; one figure
// per scene and one across the scenes for the report's summary.
#include <vector>

#include "report_writer.h"

namespace ballbench {

// Writes the fronts' data, scripts and PNGs into the working folder (the report's figures/).
std::vector<Figure> front_figures(const ReportInputs& in);

}  // namespace ballbench

#pragma once
// One scene's comparison at its own step (results/SCENE.json): every engine and profile's figures in a
// table (the columns that rank engines there), its verdicts, viewer, ensemble and figures, and the
// other columns below.
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

// The scenes with runs, in the suite's order (run.json's "scenes"), then any others in file order.
std::vector<std::string> table_scenes(const ReportInputs& in);

// A scene's line of what it is: "300 balls, dt = 0.01 s, 500 steps (`scenarios/pile.toml`); walls, gravity, ...".
std::string scene_line(const ReportInputs& in, const std::string& scene);

std::string scene_section(const ReportInputs& in, const std::string& scene, const std::vector<Figure>& figures);

}  // namespace ballbench

#pragma once
// Results (JSON files) -> REPORT.md. It reads result files only: every number in the report can be
// traced to a file in the results folder.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "result.h"

namespace ballbench {

struct ReportInputs {
  nlohmann::json run;                // results/run.json: machine, compiler, command, date
  std::vector<Result> results;       // every results/*.json but run.json, in file order
};

// A figure drawn for the report (figures.h).
struct Figure {
  std::string scene;
  std::string file;     // relative to the report's folder: figures/NAME.png
  std::string caption;
};

// Reads a results folder written by `ballbench report`.
ReportInputs read_report_inputs(const std::string& results_dir);

std::string render_report(const ReportInputs& in, const std::vector<Figure>& figures = {});

}  // namespace ballbench

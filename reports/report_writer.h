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

// Reads a results folder written by `ballbench report`.
ReportInputs read_report_inputs(const std::string& results_dir);

std::string render_report(const ReportInputs& in);

}  // namespace ballbench

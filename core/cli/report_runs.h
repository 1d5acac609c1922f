#pragma once
// Runs one part of a report (core/report_part.h) into its results file(s), or finds it complete in
// them from a report that stopped later on (a report run again resumes there).
#include <string>
#include <vector>

#include "engine.h"
#include "report_part.h"
#include "report_suite.h"
#include "run_engines.h"
#include "try_store.h"

namespace ballbench::cli {

// What every part of one report shares.
struct ReportRun {
  ReportSuite suite;
  std::string results_dir;
  std::vector<const EngineEntry*> engines;  // the scene tables', calibration's and benchmarks'
  std::vector<const EngineEntry*> swept;    // the sweeps' and frontiers': costly engines only if the suite says
  std::vector<const EngineEntry*> matched;  // the matches': those, and the suite's match_costly_engines
  Isolation isolation;
  const TryStore* store = nullptr;
  std::string bench_binary;  // the step benchmark; the harness benchmark beside it
  bool quiet = false;
  std::vector<std::string>* left_out = nullptr;  // what the report could not run, said in it
};

// The engines each kind of part runs, from the report's list and the suite.
void choose_engines(ReportRun& run, const std::vector<const EngineEntry*>& engines);

// Whether the part's results are already complete in the results folder (a report that stopped
// later on left them).
bool part_complete(const ReportRun& run, const ReportPart& part);

// Runs the part and writes its results file(s); its progress and the part's end on stderr.
void run_part(const ReportRun& run, const ReportPart& part);

// The step benchmark built beside this executable (build/<preset>/bench/), or "".
std::string default_bench_binary(const std::string& name);

}  // namespace ballbench::cli

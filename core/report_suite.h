#pragma once
// What `ballbench report` runs, read from scenarios/suites/report.toml (its comments say what each
// key does): the scenes of each part of the report, the benchmark selections and the budgets.
#include <string>
#include <vector>

namespace ballbench {

// An equal-accuracy search too costly for the suite (an hour at 10^4 balls), measured before by
// `ballbench match` and committed: the report shows it with its own date and build.
struct MeasuredMatch {
  std::string scene;  // the scene it searched (its file's)
  std::string path;   // its JSON file, as the suites file names it, resolved against that file's folder
};

struct ReportSuite {
  std::string name;                         // "quick", "full"
  std::vector<std::string> scenes;          // a comparison table each, every engine and profile
  std::vector<std::string> unreferenced;    // of those, run without a reference
  std::vector<std::string> match_scenes;    // equal accuracy and its work-precision fronts
  int match_max_halvings = 6;               // the finest step a search tries: dt / 2^this
  double match_budget = 400;                // one engine and profile's search, in runs of the scene at dt (MatchOptions::budget_runs)
  double match_ceiling = 0;                 // a try stops past this multiple of our solver's cost (MatchOptions::ceiling; 0: none)
  std::vector<std::string> sweep_scenes;    // work against precision
  std::vector<std::string> stress_scenes;   // stability frontier
  int stress_levels = 5;
  int seeds = 1;                            // placements of each scene with random placement
  std::vector<std::string> bench_filters;   // Google Benchmark --benchmark_filter, one process each
  double bench_min_time = 0.05;             // s per benchmark
  double bench_budget_s = 10;               // s a benchmark may run before it stops as failed
  std::string harness_filter;               // of bench/ballbench_harness_benchmark
  double timeout_s = 600;                   // per engine run
  bool costly_engines = false;              // sweeps, frontiers and matches include EngineInfo::costly_runs engines
  std::vector<std::string> match_costly_engines;  // costly engines the matches include anyway
  std::vector<MeasuredMatch> measured_matches;     // searches carried into the report, not run by it
};

// The suite `name` of the suites file (default: scenarios/suites/report.toml in the scenarios
// folder); an unknown suite, key or scene name is one line naming the file, line and field.
ReportSuite load_report_suite(const std::string& name, const std::string& path = "");

std::string report_suites_file();

}  // namespace ballbench

#pragma once
// Results (JSON files) -> REPORT.md and its pages. It reads result files only: every number in the
// report can be traced to a file in the results folder.
#include <map>
#include <set>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_results.h"
#include "calibration_result.h"
#include "conform_result.h"
#include "engine.h"
#include "frontier_result.h"
#include "match_result.h"
#include "result.h"
#include "sweep_result.h"

namespace ballbench {

struct ReportInputs {
  nlohmann::json run;                // results/run.json: machine, compiler, command, date
  std::vector<Result> results;       // every other results/*.json, in file order: the scene's own placement
  std::vector<Result> placements;    // the same files' runs of further placements (seed_offset > 0)
  std::vector<MatchResult> matches;  // results/match-*.json (`ballbench match`), in the suite's order, then measured-*.json
  // The scenes whose search was measured before and carried in (results/measured-*.json): shown with
  // their own date and build, not this report's.
  std::set<std::string> measured;
  std::map<std::string, std::string> result_files;  // scene -> its results file, relative to the report
  std::vector<SweepResult> sweeps;   // results/sweep-*.json (`ballbench sweep`)
  std::vector<FrontierResult> frontiers;  // results/stress-*.json (`ballbench stress --json`)
  std::optional<BenchResults> bench; // results/bench.json (bench/ballbench_step_benchmark)
  std::optional<BenchResults> harness;  // results/harness.json (bench/ballbench_harness_benchmark)
  std::optional<CalibrationResult> calibration;  // results/calibration.json
  std::optional<ConformResult> conform;          // results/conform.json
  // Engine name -> role (the registry's engine_roles(), given by the caller); a name not in it is
  // external.
  std::map<std::string, EngineRole> roles;
};

EngineRole role_of(const ReportInputs& in, const std::string& engine);

// What a figure of the report shows: per scene its energy over time, a picture of its end, its
// animation, its trajectory viewer, its work against precision, its stability frontier and its
// work-precision front; every scene's fronts in one; the engines' scaling.
enum class FigureKind { energy, picture, animation, viewer, work_precision, frontier, front, fronts, scaling };

// A figure drawn for the report (figures.h).
struct Figure {
  FigureKind kind = FigureKind::energy;
  std::string scene;    // "" for scaling
  std::string file;     // relative to the report's folder: figures/NAME.png (an animation: NAME.gif; the viewer:
                        // SCENE-viewer.html)
  std::string caption;
};

// Reads a results folder written by `ballbench report`.
ReportInputs read_report_inputs(const std::string& results_dir);

// One page of the report: REPORT.md (the answer, on one screen) or a page of evidence under pages/.
struct ReportPage {
  std::string path;  // relative to the report's folder
  std::string title;
  std::string text;  // Markdown
};

// Scene pages are scenes/SCENE.md; the other pages of evidence are under pages/.
inline constexpr const char* kScenePagePrefix = "scenes/";
std::string scene_page_path(const std::string& scene);

// The folders the report renders into beside REPORT.md (its results/ are written by the runs): each
// is the report's own, emptied by --fresh and pruned of pages no longer rendered.
inline constexpr const char* kRenderedFolders[] = {"figures", "pages", "scenes"};

// Every page, REPORT.md first, its links resolved (page_links.h).
std::vector<ReportPage> render_report(const ReportInputs& in, const std::vector<Figure>& figures = {});

}  // namespace ballbench

#include "report_writer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "data_file.h"
#include "input_error.h"
#include "report_part.h"

namespace ballbench {

EngineRole role_of(const ReportInputs& in, const std::string& engine) {
  const auto it = in.roles.find(engine);
  return it == in.roles.end() ? EngineRole::external : it->second;
}

ReportInputs read_report_inputs(const std::string& results_dir) {
  ReportInputs in;
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(results_dir, ec))
    if (e.path().extension() == ".json") files.push_back(e.path());
  if (ec) throw InputError(fmt::format("{}: cannot read the results folder: {}", results_dir, ec.message()));
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    if (name == "run.json") {
      in.run = parse_json_file(f.string(), "a report's run record");
      if (!in.run.is_object())
        throw InputError(fmt::format("{}: not a report's run record (a JSON object): write it again with "
                                     "`ballbench report`",
                                     f.string()));
    } else if (name == "bench.json") {
      in.bench = read_bench_file(f.string());
    } else if (name == "harness.json") {
      in.harness = read_bench_file(f.string());
    } else if (name == "conform.json") {
      in.conform = read_conform_file(f.string());
    } else if (name == "calibration.json") {
      in.calibration = read_calibration_file(f.string());
    } else if (name.starts_with("match-")) {
      in.matches.push_back(read_match_file(f.string()));
    } else if (name.starts_with("sweep-")) {
      in.sweeps.push_back(read_sweep_file(f.string()));
      mark_pareto(in.sweeps.back().points);  // by today's rule, whatever rule wrote the file
    } else if (name.starts_with("stress-")) {
      in.frontiers.push_back(read_frontier_file(f.string()));
    } else {
      for (auto& r : read_results_file(f.string())) {
        in.result_files.emplace(r.scene, "results/" + name);
        (r.seed_offset == 0 ? in.results : in.placements).push_back(std::move(r));
      }
    }
  }
  // The equal-accuracy scenes in the suite's order (run.json's parts), then any others by name.
  const auto parts = in.run.is_object() ? in.run.value("parts", std::vector<std::string>{}) : std::vector<std::string>{};
  const auto rank = [&](const MatchResult& m) {
    return std::find(parts.begin(), parts.end(), part_word({PartKind::match, m.scene})) - parts.begin();
  };
  std::stable_sort(in.matches.begin(), in.matches.end(),
                   [&](const MatchResult& a, const MatchResult& b) { return rank(a) < rank(b); });
  if (in.run.is_null())
    throw InputError(fmt::format("{}: no run.json, so no report's results to render (run `ballbench report` "
                                 "without --render-only first)",
                                 results_dir));
  return in;
}

}  // namespace ballbench

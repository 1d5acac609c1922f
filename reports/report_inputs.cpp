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
#include "json_value.h"
#include "report_part.h"

namespace ballbench {

EngineRole role_of(const ReportInputs& in, const std::string& engine) {
  const auto it = in.roles.find(engine);
  return it == in.roles.end() ? EngineRole::external : it->second;
}

namespace {

// What a part records of where it came from: the build that made it and, for a part of one scene,
// that scene's content ("" where a file written before they were recorded has none).
struct PartOrigin {
  std::string part;  // "results/match-pile.json", for the message
  std::string build, scene, digest;
};

std::vector<PartOrigin> origins(const ReportInputs& in) {
  std::vector<PartOrigin> out;
  const auto from_context = [&](const std::string& part, const nlohmann::json& context, const std::string& scene) {
    out.push_back({part, json_string_field(context, "build"), scene, json_string_field(context, "scene_digest")});
  };
  for (const Result& r : in.results) {
    const auto file = in.result_files.find(r.scene);
    out.push_back({file == in.result_files.end() ? r.scene : file->second, r.build, r.scene, r.scene_digest});
  }
  for (const MatchResult& m : in.matches) {
    const bool measured = in.measured.contains(m.scene);
    from_context(fmt::format("results/{}", part_file({measured ? PartKind::measured : PartKind::match, m.scene})),
                 m.context, m.scene);
    out.back().digest = m.scene_digest;
    if (measured) out.back().build.clear();  // carried in with its own build, and said so
  }
  for (const SweepResult& s : in.sweeps) {
    const std::string scene = s.plan.value("scene", "");
    from_context(fmt::format("results/{}", part_file({PartKind::sweep, scene})), s.context, scene);
    out.back().digest = s.plan.value("scene_digest", "");
  }
  for (const FrontierResult& f : in.frontiers) from_context("results/" + part_file({PartKind::stress, f.scene}), f.context, f.scene);
  if (in.conform) from_context("results/" + part_file({PartKind::conform, ""}), in.conform->context, "");
  if (in.calibration) from_context("results/" + part_file({PartKind::calibration, ""}), in.calibration->context, "");
  out.push_back({"results/run.json", json_string_field(in.run, "build"), "", ""});
  if (in.run.is_object() && in.run.contains("scene_digests") && in.run["scene_digests"].is_object())
    for (const auto& [scene, digest] : in.run["scene_digests"].items())
      if (digest.is_string()) out.push_back({"results/run.json", "", scene, digest.get<std::string>()});
  return out;
}

// A report is one build's measurement of one content of each scene, searched once: results of two
// builds (but for a search measured before, which says its own), of two contents of a scene, or a
// search of a scene run and carried in, are never rendered as one report.
void check_one_origin(const ReportInputs& in, const std::string& results_dir) {
  for (const std::string& scene : in.measured)
    if (std::count_if(in.matches.begin(), in.matches.end(), [&](const MatchResult& m) { return m.scene == scene; }) > 1)
      throw InputError(fmt::format("{}: holds {} and {} of one scene: run `ballbench report --fresh`", results_dir,
                                   part_file({PartKind::match, scene}), part_file({PartKind::measured, scene})));
  const std::vector<PartOrigin> all = origins(in);
  const PartOrigin* first_build = nullptr;
  std::map<std::string, const PartOrigin*> first_digest;  // scene -> the first part naming its content
  for (const PartOrigin& o : all) {
    if (!o.build.empty()) {
      if (!first_build) first_build = &o;
      else if (o.build != first_build->build)
        throw InputError(fmt::format("{}: {} was made by build {}, {} by build {}: a report renders one build's "
                                     "results (`ballbench report` runs the parts of another build again)",
                                     results_dir, o.part, o.build, first_build->part, first_build->build));
    }
    if (o.scene.empty() || o.digest.empty()) continue;
    const auto [it, fresh] = first_digest.emplace(o.scene, &o);
    if (!fresh && it->second->digest != o.digest)
      throw InputError(fmt::format("{}: {} and {} hold other contents of scene {} (digests {} and {}): `ballbench "
                                   "report` runs the parts of the other content again",
                                   results_dir, it->second->part, o.part, o.scene, it->second->digest, o.digest));
  }
}

}  // namespace

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
    } else if (name.starts_with("measured-")) {
      in.matches.push_back(read_match_file(f.string()));
      in.measured.insert(in.matches.back().scene);
    } else if (name.starts_with("sweep-")) {
      in.sweeps.push_back(read_sweep_file(f.string()));
      mark_pareto(in.sweeps.back().points);  // by today's rule, whatever rule wrote the file
    } else if (name.starts_with("stress-")) {
      in.frontiers.push_back(read_frontier_file(f.string()));
    } else {
      std::vector<Result> runs = read_results_file(f.string());
      if (runs.empty())  // a scene's table with no run would vanish from the report unsaid
        throw InputError(fmt::format("{}: holds no run: run its part again (`ballbench report` resumes it)", f.string()));
      for (auto& r : runs) {
        in.result_files.emplace(r.scene, "results/" + name);
        (r.seed_offset == 0 ? in.results : in.placements).push_back(std::move(r));
      }
    }
  }
  // The equal-accuracy scenes in the suite's order (run.json's parts), then any others by name.
  const auto parts = in.run.is_object() ? in.run.value("parts", std::vector<std::string>{}) : std::vector<std::string>{};
  const auto rank = [&](const MatchResult& m) {
    const PartKind kind = in.measured.contains(m.scene) ? PartKind::measured : PartKind::match;
    return std::find(parts.begin(), parts.end(), part_word({kind, m.scene})) - parts.begin();
  };
  std::stable_sort(in.matches.begin(), in.matches.end(),
                   [&](const MatchResult& a, const MatchResult& b) { return rank(a) < rank(b); });
  if (in.run.is_null())
    throw InputError(fmt::format("{}: no run.json, so no report's results to render (run `ballbench report` "
                                 "without --render-only first)",
                                 results_dir));
  check_one_origin(in, results_dir);
  return in;
}

}  // namespace ballbench

// `ballbench sweep`: work against precision. For each engine, vary its accuracy knobs one at a time
// (the step size for every engine; solver iterations, sub-steps, CCD, profiles as each engine lists
// them in EngineInfo::sweep_knobs), time every point (median of repeated runs) and measure its error
// against `exact` at a fixed horizon; write JSON and CSV and print each engine's Pareto front.
#include <algorithm>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "data_file.h"
#include "input_error.h"
#include "process/process_engine.h"
#include "interrupt.h"
#include "progress.h"
#include "registry.h"
#include "scene_loader.h"
#include "sweep.h"
#include "validators.h"

namespace ballbench::cli {
namespace {

struct SweepArgs {
  std::string scene, engines, json, csv, shard;
  std::vector<double> dt_factors;
  bool no_knobs = false;
  SweepOptions options;
};

void sweep(SweepArgs& a) {
  install_interrupt_handlers();  // first: a stop request during the handshakes too
  Progress::quiet = a.options.quiet;
  const Scene scene = load_scene(a.scene);
  limit_handshake_seconds(a.options.isolation.timeout_s);  // --timeout bounds the engines' handshakes too
  const auto engines = parse_engine_list(a.engines);
  check_profile(engines, a.options.profile);
  if (!a.dt_factors.empty()) a.options.dt_factors = a.dt_factors;
  a.options.knobs = !a.no_knobs;
  a.options.reference = reference_engine();
  if (!a.shard.empty()) a.options.shard = parse_shard(a.shard);
  if (a.json.empty()) a.json = shard_file_name("sweep-" + scene.name, a.options.shard);
  if (a.csv.empty()) a.csv = sweep_csv_path(a.json);
  check_json_and_csv(scene, a.json, a.csv, "the sweep's");
  const SweepResult s = run_sweep(scene, engines, a.options, run_context());
  write_sweep_files(s, a.json, a.csv);
  if (s.shard_count == 1) print_pareto(s);  // a shard's fronts are of its points only
  fmt::print("wrote {} and {}\n", a.json, a.csv);
  exit_if_interrupted(fmt::format("{} point(s) written to {} and {}, the point in progress marked interrupted",
                                  s.points.size(), a.json, a.csv));
  // Not one point measured (every one failed, crashed or timed out): the sweep has no result.
  const auto status_is = [&](RunStatus status) {
    return [status](const SweepPoint& p) { return p.status == status; };
  };
  if (!s.points.empty() && std::none_of(s.points.begin(), s.points.end(), status_is(RunStatus::ok)) &&
      !std::all_of(s.points.begin(), s.points.end(), status_is(RunStatus::unsupported))) {
    fmt::print(stderr, "ballbench: sweep: none of the {} point(s) ran to a result (see the lines above)\n", s.points.size());
    throw CheckFailed{1};
  }
}

}  // namespace

void add_sweep(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand(
      "sweep", "work against precision: vary each engine's accuracy knobs, time each point, error against exact");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, or all")->required();
  cmd->add_option("--profile", a->options.profile, "settings profile, comma-separated profiles, or all (default: all)");
  cmd->add_option("--horizon", a->options.horizon,
                  "simulated time at which the position error is taken (s, default 0.2; a whole number of steps "
                  "at every dt)")
      ->check(kPositiveNumber);
  cmd->add_option("--dt-factors", a->dt_factors, "the step sizes tried, as factors of the scene's dt (default 2,1,0.5,0.25)")
      ->delimiter(',')
      ->check(kPositiveNumber);
  cmd->add_flag("--no-knobs", a->no_knobs, "vary the step size only, not the engines' own knobs");
  cmd->add_option("--repeats", a->options.repeats, "timing runs per point; the median is reported (default 3)")
      ->check(whole_in_range(1, 1000));
  cmd->add_option("--json", a->json, "JSON output (default sweep-SCENE.json)")->check(kOutputFile);
  cmd->add_option("--csv", a->csv, "CSV output (default: the JSON path with .csv)")->check(kOutputFile);
  cmd->add_option("--timeout", a->options.isolation.timeout_s, "seconds each run may take (default 120)")
      ->check(kPositiveNumber);
  cmd->add_option("--shard", a->shard,
                  "run only shard I of N of the sweep's points (I/N, e.g. 2/3; join the shards' JSON files with "
                  "`ballbench merge`); default: all");
  add_quiet(cmd, a->options.quiet);
  cmd->callback([a] { sweep(*a); });
}

}  // namespace ballbench::cli

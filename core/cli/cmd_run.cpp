// `ballbench run`: engines on one scene, a table on stdout, optional JSON and trajectory CSV.
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "commands.h"
#include "input_error.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"
#include "trajectory_csv.h"

namespace ballbench::cli {
namespace {

struct RunArgs {
  std::string scene, engines, json, trajectory, profile;
  std::optional<double> dt, duration;
  std::optional<long> steps;
  std::vector<std::string> sets;
  bool quiet = false;
};

void run(const RunArgs& a) {
  Scene scene = load_scene(a.scene);
  const auto engines = parse_engine_list(a.engines);
  if (a.dt) scene.dt = *a.dt;
  if (a.duration) scene.duration = *a.duration;
  if (scene.duration / scene.dt > 1e9) throw InputError("--dt/--duration: more than 1e9 steps");
  check_profile(engines, a.profile);
  RunOptions options;
  options.steps = a.steps ? *a.steps : -1;
  for (const auto& s : a.sets) add_setting(options.overrides, s);
  for (const auto& [name, v] : options.overrides.items()) find_engine(name);  // a typo in --set
  std::optional<TrajectoryCsv> trajectory;
  if (!a.trajectory.empty()) trajectory.emplace(a.trajectory), options.trajectory = &*trajectory;
  const auto results = run_all(scene, engines, a.profile, options, a.quiet);
  if (trajectory) trajectory->close();
  print_table(results);
  if (!a.json.empty()) write_results_file(a.json, results);
}

}  // namespace

void add_run(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "run engines on one scene and print their metrics");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, or all")->required();
  cmd->add_option("--dt", a->dt, "step size in seconds (overrides the scene's)")->check(CLI::PositiveNumber);
  auto* steps = cmd->add_option("--steps", a->steps, "number of steps")->check(CLI::NonNegativeNumber);
  cmd->add_option("--duration", a->duration, "simulated seconds (overrides the scene's)")
      ->check(CLI::PositiveNumber)
      ->excludes(steps);
  cmd->add_option("--json", a->json, "write one JSON object per engine run (an array) to FILE");
  cmd->add_option("--trajectory", a->trajectory, "write every ball's state at every step as CSV to FILE");
  cmd->add_option("--profile", a->profile,
                  "settings profile (see `ballbench list`): a name, or all; engines without it run their default");
  cmd->add_option("--set", a->sets, "engine setting ENGINE.KEY=VALUE (repeatable)");
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->callback([a] { run(*a); });
}

}  // namespace ballbench::cli

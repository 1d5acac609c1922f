// `ballbench run`: engines on one scene, a table on stdout, optional JSON and trajectory CSV.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "commands.h"
#include "validators.h"
#include "input_error.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"

namespace ballbench::cli {
namespace {

struct RunArgs {
  std::string scene, engines, json, trajectory, profile;
  std::optional<double> dt, duration;
  std::optional<long> steps;
  std::vector<std::string> sets;
  bool quiet = false;
  bool no_reference = false;
  int sample_every = 1;
  Isolation isolation;
};

// A [settings.NAME] table naming no engine would be silently ignored: a typo must be an error.
void check_scene_settings(const Scene& scene) {
  std::vector<std::string> names;
  for (const auto& e : engine_registry()) names.push_back(e.info.name);
  for (const auto& [name, table] : scene.engine_settings.items())
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw InputError(fmt::format("{}: settings.{}: unknown engine '{}'{} (known: {})", scene.source, name, name,
                                   did_you_mean(name, names), fmt::join(names, ", ")));
}

void run(const RunArgs& a) {
  Scene scene = load_scene(a.scene);
  check_scene_settings(scene);
  const auto engines = parse_engine_list(a.engines);
  if (a.dt) scene.dt = *a.dt;
  if (a.duration) scene.duration = *a.duration;
  if (scene.duration / scene.dt > 1e9) throw InputError("--dt/--duration: more than 1e9 steps");
  if (!a.steps && scene.steps() < 1)
    throw InputError(fmt::format("--dt/--duration: duration {} s is under half a step of {} s: no step to run",
                                 scene.duration, scene.dt));
  check_profile(engines, a.profile);
  RunOptions options;
  options.steps = a.steps ? *a.steps : -1;
  for (const auto& s : a.sets) add_setting(options.overrides, s);
  for (const auto& [name, v] : options.overrides.items()) find_engine(name);  // a typo in --set
  if (!a.no_reference) options.reference = reference_engine();
  options.metrics.sample_every = a.sample_every;
  const auto results = run_all(scene, engines, a.profile, options, a.quiet, a.isolation, a.trajectory);
  print_table(results);
  if (!a.json.empty()) write_results_file(a.json, results);
}

}  // namespace

void add_run(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "run engines on one scene and print their metrics");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, or all")->required();
  cmd->add_option("--dt", a->dt, "step size in seconds (overrides the scene's)")->check(kPositiveNumber);
  auto* steps = cmd->add_option("--steps", a->steps, "number of steps")->check(kPositiveCount);
  cmd->add_option("--duration", a->duration, "simulated seconds (overrides the scene's)")
      ->check(kPositiveNumber)
      ->excludes(steps);
  cmd->add_option("--json", a->json, "write one JSON object per engine run (an array) to FILE");
  cmd->add_option("--trajectory", a->trajectory, "write every ball's state at every step as CSV to FILE");
  cmd->add_option("--profile", a->profile,
                  "settings profile (see `ballbench list`): a name, or all; engines without it run their default");
  cmd->add_option("--set", a->sets, "engine setting ENGINE.KEY=VALUE (repeatable)");
  cmd->add_option("--sample-every", a->sample_every,
                  "sampled metrics (energy, momentum, overlaps, sticking, error, checksums) see every K-th step "
                  "(default 1); tunnelling sees every step")
      ->check(kPositiveCount);
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->add_flag("--no-reference", a->no_reference,
                "do not run `exact` alongside to measure the error against it (it runs by default)");
  auto* timeout = cmd->add_option("--timeout", a->isolation.timeout_s,
                                  "seconds each engine run may take before it is killed and marked \"timed out\" "
                                  "(default 600)")
                      ->check(kPositiveNumber);
  cmd->add_flag_function(
         "--no-isolation", [a](std::int64_t) { a->isolation.enabled = false; },
         "run engines in this process, not each in a child process (a crash then ends the whole run)")
      ->excludes(timeout);
  cmd->callback([a] { run(*a); });
}

}  // namespace ballbench::cli

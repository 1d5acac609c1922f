// `ballbench stress`: for each engine, raise one knob at a time (dt, initial speed, mass ratio,
// ball count) by factors of 2 until a run fails, and print the stability frontier: the largest
// value that still passed, and why the next one failed.
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "data_file.h"
#include "interrupt.h"
#include "process/process_engine.h"
#include "progress.h"
#include "registry.h"
#include "scene_loader.h"
#include "stability_frontier.h"
#include "validators.h"

namespace ballbench::cli {
namespace {

struct StressArgs {
  std::string scene, engines, json;
  std::vector<std::string> knobs;
  bool no_isolation = false;
  StressOptions options;
};

void stress(StressArgs& a) {
  install_interrupt_handlers();  // first: a stop request during the handshakes too
  Progress::quiet = a.options.quiet;
  const Scene base = load_scene(a.scene);
  limit_handshake_seconds(a.options.isolation.timeout_s);  // --timeout bounds the engines' handshakes too
  const auto engines = parse_engine_list(a.engines);
  check_profile(engines, a.options.profile);
  if (!a.knobs.empty()) a.options.knobs = a.knobs;
  a.options.reference = reference_engine();
  a.options.isolation.enabled = !a.no_isolation;
  if (!a.json.empty()) {  // before the runs, which take minutes
    std::vector<PathUse> uses = noted_input_files();
    if (std::filesystem::exists(base.source)) uses.push_back({"--scene", base.source, false});
    uses.push_back({"--json", a.json, true});
    check_path_clashes(uses);
    check_writable(a.json, "the frontiers", true);
  }
  const FrontierResult f = run_frontier(base, engines, a.options, run_context());
  print_frontier(f);
  if (!a.json.empty()) write_frontier_file(a.json, f);
  exit_if_interrupted(fmt::format("{} frontier(s) printed{}, the one in progress failed as interrupted", f.rows.size(),
                                  a.json.empty() ? "" : " and written to " + a.json));
}

}  // namespace

void add_stress(CLI::App& app) {
  auto a = std::make_shared<StressArgs>();
  auto* cmd = app.add_subcommand("stress", "raise one knob at a time until each engine fails: the stability frontier");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, or all")->required();
  cmd->add_option("--profile", a->options.profile, "settings profile, or all");
  cmd->add_option("--knobs", a->knobs, "comma-separated: dt, speed, mass-ratio, count (default: all four)")
      ->delimiter(',');
  cmd->add_option("--steps", a->options.steps, "steps per run (default 200, at most 1e9)")->check(kStepCount);
  cmd->add_option("--levels", a->options.levels, "doublings tried per knob (default 6: up to 32 x)")
      ->check(whole_in_range(1, 20));
  cmd->add_option("--energy-tolerance", a->options.energy_tolerance,
                  "a run fails when its energy is off the reference (or grew) by more than this fraction (default 0.1)")
      ->check(kPositiveNumber);
  cmd->add_option("--json", a->json, "write the frontiers as JSON to FILE")->check(kOutputFile);
  auto* timeout = cmd->add_option("--timeout", a->options.isolation.timeout_s,
                                  "seconds each run may take before it is killed and fails (default 120)")
                      ->check(kPositiveNumber);
  cmd->add_flag("--no-isolation", a->no_isolation, "run engines in this process (a crash then ends the whole run)")
      ->excludes(timeout);
  add_quiet(cmd, a->options.quiet);
  cmd->callback([a] { stress(*a); });
}

}  // namespace ballbench::cli

// `ballbench run`: engines on one scene, a table on stdout, optional JSON and trajectory CSV.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.h"
#include "data_file.h"
#include "input_error.h"
#include "process/process_engine.h"
#include "interrupt.h"
#include "match_result.h"
#include "progress.h"
#include "registry.h"
#include "conform_run.h"
#include "run_engines.h"
#include "try_store.h"
#include "scene_loader.h"
#include "spec_option.h"
#include "spec_verdict.h"
#include "validators.h"

namespace ballbench::cli {
namespace {

struct RunArgs {
  std::string scene, engines, json, trajectory, profile;
  std::optional<double> dt, duration;
  std::vector<std::string> spec;
  std::optional<long> steps;
  std::vector<std::string> sets;
  bool quiet = false;
  bool no_reference = false;
  int sample_every = 1;
  int seeds = 1;
  int frames = 0;
  double trajectory_limit_gb = 10;
  Isolation isolation;
};

}  // namespace

// Each named engine is built on a one-ball copy of the scene, which reads (so checks) its settings
// as a run would.
void check_settings(const Scene& scene, const nlohmann::json& overrides) {
  const std::vector<std::string> names = engine_names();
  std::vector<const EngineEntry*> named;
  const auto known = [&](const std::string& name, const std::string& where) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw InputError(fmt::format("{}: unknown engine '{}'{} (known: {})", where, name, did_you_mean(name, names),
                                   fmt::join(names, ", ")));
    const EngineEntry* e = &find_engine(name);
    if (std::find(named.begin(), named.end(), e) == named.end()) named.push_back(e);
  };
  for (const auto& [name, table] : scene.engine_settings.items()) known(name, fmt::format("{}: settings.{}", scene.source, name));
  for (const auto& [name, table] : overrides.items()) known(name, fmt::format("--set {}.KEY", name));
  Scene probe = scene;
  const int keep = std::min(scene.n(), 1);
  probe.radius.conservativeResize(keep), probe.mass.conservativeResize(keep);
  probe.initial.pos.conservativeResize(keep, 2), probe.initial.vel.conservativeResize(keep, 2);
  // Builds the engine with these settings; a settings error goes to `named_by` (which throws),
  // anything else is not a settings problem and is left for the run itself to report.
  const auto build = [&](const EngineEntry& e, const nlohmann::json& settings, const auto& named_by) {
    try {
      e.create(probe, e.info.profiles.front(), settings);
    } catch (const InputError& err) {
      named_by(std::string(err.what()));
    } catch (const std::exception&) {
    }
  };
  for (const EngineEntry* e : named) {
    const std::string& name = e->info.name;
    // The scene's own table first, so that a problem there is named by its FILE:LINE. Every
    // settings error reads "settings.ENGINE.KEY: why" (SettingsReader and the engines' own checks).
    if (scene.engine_settings.contains(name))
      build(*e, merged_settings(scene, name, nlohmann::json::object()), [&](const std::string& text) {
        const std::string prefix = "settings." + name + ".";
        const size_t colon = text.find(':');
        if (text.rfind(prefix, 0) == 0 && colon != std::string::npos) {
          const auto line = scene.setting_lines.find(name + "." + text.substr(prefix.size(), colon - prefix.size()));
          if (line != scene.setting_lines.end()) throw InputError(fmt::format("{}:{}: {}", scene.source, line->second, text));
        }
        throw InputError(fmt::format("{}: {}", scene.source, text));
      });
    build(*e, merged_settings(scene, name, overrides.value(name, nlohmann::json::object())),
          [](const std::string& text) { throw InputError(text); });
  }
}

namespace {

// The output files are checked before anything runs (a run may take hours): writable, and neither
// an input (the scene file, an engines file) nor each other, however spelled.
void check_outputs(const Scene& scene, const RunArgs& a) {
  std::vector<PathUse> uses = noted_input_files();
  if (!scene.source.empty() && std::filesystem::exists(scene.source)) uses.push_back({"--scene", scene.source, false});
  if (!a.json.empty()) uses.push_back({"--json", a.json, true});
  if (!a.trajectory.empty()) uses.push_back({"--trajectory", a.trajectory, true});
  check_path_clashes(uses);
  // The results file's folders are created (as its writer does); the trajectory's are not.
  for (const auto& [flag, path, what, parents] :
       {std::tuple{"--json", a.json, "the results", true}, {"--trajectory", a.trajectory, "the trajectory", false}}) {
    if (path.empty()) continue;
    try {
      check_writable(path, what, parents);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{} {}", flag, e.what()));
    }
  }
}

// A trajectory holds one CSV row per ball per step per run: estimated before anything runs and
// refused beyond --trajectory-limit-gb, with the estimate, instead of filling the disk.
void check_trajectory_size(const Scene& scene, const std::vector<const EngineEntry*>& engines, const RunArgs& a) {
  if (a.trajectory.empty()) return;
  // Measured: 500-ball pile, home-seed and home; w and angle add two more numbers like x and y.
  const double kBytesPerRow = scene.features().rotation ? 150 : 110;
  const size_t runs = run_count(engines, a.profile);
  const double steps = static_cast<double>(a.steps ? *a.steps : scene.steps());
  const double rows = (steps + 1) * scene.n() * static_cast<double>(runs), gb = rows * kBytesPerRow / 1e9;
  if (gb > a.trajectory_limit_gb)
    throw InputError(fmt::format("--trajectory {}: about {:.3g} GB ({:.3g} rows: {} runs x {} steps x {} balls), above "
                                 "--trajectory-limit-gb {} (raise it, or write fewer steps)",
                                 a.trajectory, gb, rows, runs, steps, scene.n(), a.trajectory_limit_gb));
}

// The run's options from the command line, each checked against the scene and the engines first.
RunOptions run_options(const Scene& scene, const std::vector<const EngineEntry*>& engines, const RunArgs& a) {
  check_profile(engines, a.profile);
  RunOptions options;
  options.steps = a.steps ? *a.steps : -1;
  for (const auto& s : a.sets) add_setting(options.overrides, s);
  check_settings(scene, options.overrides);
  // A setting for an engine this run does not run would be ignored: say so instead.
  for (const auto& [engine, table] : options.overrides.items())
    if (std::none_of(engines.begin(), engines.end(), [&](const EngineEntry* e) { return e->info.name == engine; }))
      throw InputError(fmt::format("--set {}.{}: {} is not among --engine ({}), so the setting would change nothing",
                                   engine, table.empty() ? std::string("KEY") : table.begin().key(), engine, a.engines));
  check_outputs(scene, a);
  check_trajectory_size(scene, engines, a);
  if (!a.no_reference) use_reference(options);
  options.metrics.sample_every = a.sample_every;
  options.frames = a.frames;
  if (a.frames > 0 && scene.n() > 1000)
    throw InputError(fmt::format("--frames {}: frames are kept for scenes of at most 1000 balls; {} has {}", a.frames,
                                 scene.source, scene.n()));
  if (a.seeds > 1 && !scene.random_placement)
    throw InputError(fmt::format("--seeds {}: {} has no random placement ([random] or [lattice]) to draw again",
                                 a.seeds, scene.source));
  if (a.seeds > 1 && !a.trajectory.empty())
    throw InputError("--trajectory with --seeds: give one placement (a trajectory holds one run per engine and profile)");
  return options;
}

// Each row against the spec the scene asks for (its class's, its [accuracy] table, --spec over
// them), judged as `match` judges a try: a configuration match found meets it here with the line it
// printed.
void print_spec_verdicts(const AccuracySpec& spec, const std::vector<Result>& results) {
  fmt::print("spec: {}\n", spec.text());
  for (const Result& r : results) {
    const SpecVerdict v = judge(spec, r);
    std::vector<std::string> figures;
    for (const SpecTermDef& d : spec_terms())
      if (spec[d.term]) figures.push_back(fmt::format("{} {}", d.key, figure_text(v.figures.value(d.key, nlohmann::json()))));
    fmt::print("  {}: {}\n", run_label(r),
               v.met ? fmt::format("met ({})", fmt::join(figures, ", ")) : "not met: " + v.why_not);
  }
}

void run(const RunArgs& a) {
  install_interrupt_handlers();
  Progress::quiet = a.quiet;
  Scene scene = load_scene(a.scene);
  limit_handshake_seconds(a.isolation.timeout_s);  // --timeout bounds the engines' handshakes too
  const auto engines = parse_engine_list(a.engines);
  const AccuracySpec spec = ask_scene_for(scene, a.spec);
  if (a.dt) scene.dt = *a.dt;
  if (a.duration) scene.duration = *a.duration;
  if (scene.duration / scene.dt > 1e9) throw InputError("--dt/--duration: more than 1e9 steps");
  if (!a.steps && scene.steps() < 1)
    throw InputError(fmt::format("--dt/--duration: duration {} s is under half a step of {} s: no step to run",
                                 scene.duration, scene.dt));
  const RunOptions options = run_options(scene, engines, a);
  std::string trajectory_error;
  std::vector<Result> results =
      run_all(scene, engines, a.profile, options, a.quiet, a.isolation, a.trajectory, &trajectory_error);
  // Further placements: the same scene with its random seeds offset by 1 .. K-1.
  run_further_placements(results, scene, a.seeds,
                         [&](int k) {
                           Scene placed = load_scene(a.scene, k);
                           placed.dt = scene.dt, placed.duration = scene.duration, placed.accuracy = scene.accuracy;
                           return placed;
                         },
                         engines, a.profile, options, a.quiet, a.isolation);
  std::string ours;  // our solver's first run, if it ran: what the others are compared with
  for (const Result& r : results)
    if (ours.empty() && find_engine(r.engine).info.role == EngineRole::ours) ours = run_label(r);
  if (a.seeds > 1) print_ensemble(results, a.seeds, ours);
  else print_table(results), print_spec_verdicts(spec, results);
  print_claim_checks(TryStore(TryStore::default_dir(), false), engines, a.profile);
  if (!a.json.empty()) write_results_file(a.json, results);
  // The table and the JSON stand; the trajectory that could not be written is said in one line.
  if (!trajectory_error.empty()) {
    fmt::print(stderr, "ballbench: error: {} ({} complete)\n", trajectory_error,
               a.json.empty() ? "the table is" : "the table and " + a.json + " are");
    throw CheckFailed{interrupt_signal() ? 128 + interrupt_signal() : 1};
  }
  exit_if_interrupted(fmt::format("{} row(s) written{}, the run in progress marked interrupted", results.size(),
                                  a.json.empty() ? "" : fmt::format(" to the table and {}", a.json)));
  // Exit 1 when a row did not run to a result: failed, diverged, crashed or timed out. A row the
  // engine cannot run (unsupported) says so with its reason and is not a failure of the command.
  if (std::any_of(results.begin(), results.end(),
                  [](const Result& r) { return r.status != RunStatus::ok && r.status != RunStatus::unsupported; }))
    throw CheckFailed{1};
}

}  // namespace

void add_run(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "run engines on one scene and print their metrics");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, or all")->required();
  cmd->add_option("--dt", a->dt, "step size in seconds (overrides the scene's)")->check(kPositiveNumber);
  cmd->add_option("--spec", a->spec,
                  "the accuracy the scene asks for, KEY=VALUE terms over its own, comma-separated (as for match); "
                  "home's default profile builds itself for it")
      ->delimiter(',');
  auto* steps = cmd->add_option("--steps", a->steps, "number of steps (at most 1e9)")->check(kStepCount);
  cmd->add_option("--duration", a->duration, "simulated seconds (overrides the scene's)")
      ->check(kPositiveNumber)
      ->excludes(steps);
  cmd->add_option("--json", a->json, "write one JSON object per engine run (an array) to FILE")->check(kOutputFile);
  cmd->add_option("--trajectory", a->trajectory, "write every ball's state at every step as CSV to FILE")
      ->check(kOutputFile);
  cmd->add_option("--trajectory-limit-gb", a->trajectory_limit_gb,
                  "refuse a --trajectory estimated larger than this many GB (default 10)")
      ->check(kPositiveNumber);
  cmd->add_option("--profile", a->profile,
                  "settings profile (see `ballbench list`): a name, comma-separated names, or all; engines without any run their default");
  cmd->add_option("--set", a->sets, "engine setting ENGINE.KEY=VALUE (repeatable)");
  cmd->add_option("--sample-every", a->sample_every,
                  "sampled metrics (energy, momentum, overlaps, sticking, error, checksums) see every K-th step "
                  "(default 1); tunnelling sees every step")
      ->check(kPositiveCount);
  cmd->add_option("--seeds", a->seeds,
                  "run K random placements (the scene's seeds offset by 0 .. K-1) and print each metric's mean with "
                  "its 95% bootstrap interval (default 1)")
      ->check(kPositiveCount);
  cmd->add_option("--frames", a->frames,
                  "keep about N evenly spaced frames of every ball's position in the JSON (scenes of at most 1000 "
                  "balls), for `ballbench view`")
      ->check(kPositiveCount);
  add_quiet(cmd, a->quiet);
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

// `ballbench match`: equal accuracy. For a scene and an accuracy spec (the scene's, changed by
// --spec), each engine and profile's cheapest configuration that meets the spec (match.h); one
// table, our solver's ratio to the cheapest external engine, and JSON and CSV of every try.
#include <algorithm>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "core_affinity.h"
#include "commands.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "match.h"
#include "process/process_engine.h"
#include "progress.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"
#include "spec_option.h"
#include "sweep_result.h"
#include "conform_run.h"
#include "try_store.h"
#include "validators.h"

namespace ballbench::cli {
namespace {

struct MatchArgs {
  MatchArgs() { options.jobs = core_count(); }
  std::string scene, engines, json, csv, shard;
  std::vector<std::string> spec;
  bool no_knobs = false, fresh = false;
  std::string store = TryStore::default_dir();
  std::optional<double> target, ceiling;
  MatchOptions options;
};

// The ceiling a match has when none is asked for: MatchOptions::kDefaultCeiling where our solver's
// default profile is searched (the ceiling is a multiple of its cost), else none.
double default_ceiling(const std::vector<const EngineEntry*>& engines, const std::string& profile) {
  for (const EngineEntry* e : engines)
    if (e->info.role == EngineRole::ours) {
      const auto searched = profiles_for(*e, profile);
      if (std::find(searched.begin(), searched.end(), e->info.profiles.front()) != searched.end())
        return MatchOptions::kDefaultCeiling;
    }
  return 0;
}

void match(MatchArgs& a) {
  install_interrupt_handlers();  // first: a stop request during the handshakes too
  Progress::quiet = a.options.quiet;
  Scene scene = load_scene(a.scene);
  limit_handshake_seconds(a.options.isolation.timeout_s);  // --timeout bounds the engines' handshakes too
  const auto engines = parse_engine_list(a.engines);
  check_profile(engines, a.options.profile);
  a.options.spec = ask_scene_for(scene, a.spec);
  check_measurable(scene, a.options.spec);  // the scene's own spec too: a match judges every try by it
  a.options.spec_texts = a.spec;
  a.options.knobs = !a.no_knobs;
  a.options.reference = reference_engine();
  a.options.converged_reference = converged_reference_engine();
  a.options.ceiling = a.ceiling.value_or(default_ceiling(engines, a.options.profile));
  if (!a.shard.empty()) a.options.shard = parse_shard(a.shard);
  if (a.json.empty()) a.json = shard_file_name("match-" + scene.name, a.options.shard);
  if (a.csv.empty()) a.csv = sweep_csv_path(a.json);
  check_json_and_csv(scene, a.json, a.csv, "the match's");
  const TryStore store(a.store, a.fresh);
  a.options.store = &store;
  const MatchResult m = run_match(scene, engines, a.options, run_context());
  write_match_files(m, a.json, a.csv);
  print_match(m, a.target);
  print_claim_checks(TryStore(a.store.empty() ? TryStore::default_dir() : a.store, false), engines, a.options.profile);
  fmt::print("wrote {} and {}\n", a.json, a.csv);
  exit_if_interrupted(fmt::format("{} tries written to {} and {}", m.tries.size(), a.json, a.csv));
}

}  // namespace

void add_match(CLI::App& app) {
  auto a = std::make_shared<MatchArgs>();
  auto* cmd = app.add_subcommand(
      "match", "equal accuracy: each engine's cheapest configuration (step size, its own knobs) that meets a spec");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, or all")->required();
  cmd->add_option("--profile", a->options.profile, "settings profile, comma-separated profiles, or all (default: all)");
  cmd->add_option("--spec", a->spec,
                  "spec terms over the scene's own, KEY=VALUE, comma-separated (overlap, tunnelling, sticking, "
                  "rest_speed, energy_drift, energy_error, horizon, rolling; VALUE none drops a term); the scene "
                  "asks every engine for it (home's default profile builds itself for it)")
      ->delimiter(',');
  cmd->add_option("--max-halvings", a->options.max_halvings, "finest step tried: dt / 2^this (default 6)")
      ->check(whole_in_range(0, 20));
  cmd->add_option("--budget", a->options.budget_runs,
                  "work for each engine and profile's search, in runs of the whole scene at its own step dt (n x steps "
                  "ball steps each; a try at dt/2^k costs 2^k, one stopped where it missed its share, one stopped at a "
                  "cost limit nothing): the same tries on any "
                  "machine, loaded or not (default 400)")
      ->check(kPositiveNumber);
  cmd->add_option("--ceiling", a->ceiling,
                  fmt::format("a multiple of our solver's cost (home's default profile, searched first): an engine "
                              "that costs more is reported as over the ceiling instead of searched to its end, every "
                              "try stopping at {:g} times it (default {:g} when home is among --engine; none: every "
                              "search to its end)",
                              kClearlyCostlier, MatchOptions::kDefaultCeiling))
      ->transform(kPositiveNumberOrNone);
  cmd->add_option("--within", a->options.within,
                  fmt::format("a multiple of the cheapest configuration that met so far for an engine of the same "
                              "role (ours, external): a try stops once its CPU time passes {:g} times it, and an engine "
                              "whose cost timed alone is past it is reported as outpaced instead of searched to its "
                              "finest step (default {:g}; none: no such bound)",
                              kClearlyCostlier, MatchOptions::kDefaultWithin))
      ->transform(kMultipleOrNone);
  cmd->add_option("--repeats", a->options.repeats,
                  "timing runs alone of each found configuration, over a tenth of its run (or the first part of it "
                  "that held 0.2 s of its time) from the state it saved at its middle, or over its whole run where "
                  "that held at most 0.2 s, each the mean of its passes "
                  "once the engine is warm, more until they hold 0.25 s of its time (at most 8 times as many), each "
                  "round on the next core; the fastest is reported (default 3; 0: its own run's time)")
      ->check(whole_in_range(0, 100));
  cmd->add_option("--jobs", a->options.jobs,
                  "searches at once (default: the cores); the configurations found are timed alone afterwards")
      ->check(whole_in_range(1, 256));
  cmd->add_option("--target", a->target,
                  "a ratio our solver's cost should beat the cheapest external engine's by; the output says whether "
                  "it did and by how much it fell short")
      ->check(kPositiveNumber);
  cmd->add_flag("--no-knobs", a->no_knobs, "search the step size only, not the engines' own knobs");
  cmd->add_option("--store", a->store,
                  "the results store: tries and timings measured before, by the scene's content, engine and version, "
                  "profile, configuration, step, spec and build, are read from it instead of run again (default "
                  "$XDG_CACHE_HOME/ballbench/tries or ~/.cache/ballbench/tries; \"\" for none)");
  cmd->add_flag("--fresh", a->fresh, "measure every try again (the store is written, not read)");
  cmd->add_option("--json", a->json, "JSON output (default match-SCENE.json)");
  cmd->add_option("--csv", a->csv, "CSV of every try (default: the JSON path with .csv)");
  cmd->add_option("--timeout", a->options.isolation.timeout_s, "seconds one run may take (default 600)")
      ->check(kPositiveNumber);
  cmd->add_option("--shard", a->shard,
                  "search only shard I of N of the engine and profile pairs (I/N; join the shards' JSON files "
                  "with `ballbench merge`)");
  add_quiet(cmd, a->options.quiet);
  cmd->callback([a] { match(*a); });
}

}  // namespace ballbench::cli

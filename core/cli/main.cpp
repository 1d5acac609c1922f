// `ballbench`: list, run, report. Every error the user can cause ends here as one line on stderr
// and exit status 2; nothing deeper exits the process.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "input_error.h"
#include "machine_info.h"
#include "progress.h"
#include "registry.h"
#include "report_writer.h"
#include "result.h"
#include "runner.h"
#include "scene_loader.h"
#include "trajectory_csv.h"

namespace ballbench {
namespace {

// "--set home.contact_iterations=4" -> overrides["home"]["contact_iterations"] = 4. The value is
// read as JSON (numbers, true/false) and falls back to a plain string.
void add_setting(nlohmann::json& overrides, const std::string& item) {
  const auto dot = item.find('.'), eq = item.find('=');
  if (dot == std::string::npos || eq == std::string::npos || dot > eq || dot == 0 || eq == dot + 1)
    throw InputError(fmt::format("--set '{}': expected ENGINE.KEY=VALUE", item));
  const std::string value = item.substr(eq + 1);
  nlohmann::json parsed = nlohmann::json::parse(value, nullptr, false);
  if (parsed.is_discarded() || parsed.is_object() || parsed.is_array()) parsed = value;
  overrides[item.substr(0, dot)][item.substr(dot + 1, eq - dot - 1)] = parsed;
}

std::string opt_drift(const Result& r) {
  return r.metrics.energy.max_rel_drift ? fmt::format("{:.3g}", *r.metrics.energy.max_rel_drift) : "n/a";
}

void print_table(const std::vector<Result>& results) {
  fmt::print("{:<18} {:<10} {:>6} {:>8} {:>11} {:>11} {:>9} {:>9} {:>9} {:>9} {:>10} {:>12}\n", "engine", "status", "n",
             "steps", "E drift", "P drift", "tun.wall", "tun.pair", "stk.wall", "stk.pair", "pen.max", "ns/ball-step");
  for (const auto& r : results) {
    const auto& m = r.metrics;
    fmt::print("{:<18} {:<10} {:>6} {:>8} {:>11} {:>11.3g} {:>9} {:>9} {:>9} {:>9} {:>10.3g} {:>12.1f}\n",
               run_label(r), r.status, r.n, r.steps_done, opt_drift(r), m.momentum.max_abs_drift, m.tunnelling_wall,
               m.tunnelling_pair, m.sticking_wall, m.sticking_pair, m.penetration_max, r.ns_per_ball_step);
  }
  for (const auto& r : results)
    if (!r.error.empty()) fmt::print("{}: {}\n", run_label(r), r.error);
}

// The profiles to run for one engine: "" = its default; "all" = every profile it has; a name =
// that profile if the engine has it, else its default (so `--profile tuned` can name every
// external engine's tuned profile while our solvers, which have one profile, run theirs).
std::vector<std::string> profiles_for(const EngineEntry& e, const std::string& profile) {
  const auto& mine = e.info.profiles;
  if (profile == "all") return mine;
  if (!profile.empty() && std::find(mine.begin(), mine.end(), profile) != mine.end()) return {profile};
  return {mine.front()};
}

void check_profile(const std::vector<const EngineEntry*>& engines, const std::string& profile) {
  if (profile.empty() || profile == "all") return;
  std::vector<std::string> known;
  for (const auto* e : engines)
    for (const auto& p : e->info.profiles) {
      if (p == profile) return;
      if (std::find(known.begin(), known.end(), p) == known.end()) known.push_back(p);
    }
  throw InputError(fmt::format("--profile: no selected engine has a profile '{}' (they have: {}, or all)", profile,
                               fmt::join(known, ", ")));
}

std::vector<Result> run_all(const Scene& scene, const std::vector<const EngineEntry*>& engines,
                            const std::string& profile, const RunOptions& base, bool quiet) {
  std::vector<Result> results;
  for (const EngineEntry* e : engines)
    for (const std::string& p : profiles_for(*e, profile)) {
      RunOptions options = base;
      Progress progress(fmt::format("{} ({}) on {}", e->info.name, p, scene.name));
      if (!quiet) options.progress = [&](long done, long total) { progress.update(double(done) / total); };
      options.profile = p;
      options.overrides = base.overrides.value(e->info.name, nlohmann::json::object());
      results.push_back(run_engine(scene, *e, options));
    }
  return results;
}

int cmd_list() {
  fmt::print("scenes (built-in, in {}):\n", scenario_dir());
  for (const auto& name : builtin_scene_names()) {
    try {
      const Scene s = load_scene(name);
      fmt::print("  {:<16} {:>7} balls, dt {}, {} steps\n", name, s.n(), s.dt, s.steps());
    } catch (const InputError& e) {
      fmt::print("  {:<16} (invalid: {})\n", name, e.what());
    }
  }
  fmt::print("engines:\n");
  for (const auto& e : engine_registry())
    fmt::print("  {:<12} {:<14} profiles: {:<14} {}\n", e.info.name, e.info.version,
               fmt::format("{}", fmt::join(e.info.profiles, ",")), e.info.summary);
  return 0;
}

nlohmann::json run_context(const std::string& command) {
  const MachineInfo m = machine_info();
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return {{"cpu", m.cpu}, {"cores", m.cores}, {"os", m.os}, {"compiler", m.compiler},
          {"build_type", m.build_type}, {"flags", m.flags}, {"command", command}, {"date", date}};
}

}  // namespace
}  // namespace ballbench

int main(int argc, char** argv) {
  using namespace ballbench;
  CLI::App app{"ballbench: compare 2D ball physics engines on identical scenes"};
  app.require_subcommand(1);

  app.add_subcommand("list", "print the built-in scenes and the engines with their versions");

  auto* run = app.add_subcommand("run", "run engines on one scene and print their metrics");
  std::string scene_arg, engine_arg, json_path, trajectory_path, profile;
  std::optional<double> dt, duration;
  std::optional<long> steps;
  std::vector<std::string> sets;
  bool quiet = false;
  run->add_option("--scene", scene_arg, "built-in scene name or path to a .toml scene file")->required();
  run->add_option("--engine", engine_arg, "engine name, comma-separated names, or all")->required();
  run->add_option("--dt", dt, "step size in seconds (overrides the scene's)")->check(CLI::PositiveNumber);
  auto* steps_opt = run->add_option("--steps", steps, "number of steps")->check(CLI::NonNegativeNumber);
  run->add_option("--duration", duration, "simulated seconds (overrides the scene's)")
      ->check(CLI::PositiveNumber)
      ->excludes(steps_opt);
  run->add_option("--json", json_path, "write one JSON object per engine (an array) to FILE");
  run->add_option("--trajectory", trajectory_path, "write every ball's state at every step as CSV to FILE");
  run->add_option("--profile", profile,
                  "settings profile (see `ballbench list`): a name, or all; engines without it run their default");
  run->add_option("--set", sets, "engine setting ENGINE.KEY=VALUE (repeatable)");
  run->add_flag("--quiet", quiet, "no progress on stderr");

  auto* report = app.add_subcommand("report", "run the standard comparison and write REPORT.md");
  std::string out_dir = "reports";
  bool render_only = false;
  report->add_option("--out", out_dir, "folder for REPORT.md and results/ (default: reports)");
  report->add_flag("--render-only", render_only, "only rebuild REPORT.md from the results already in OUT/results");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ballbench: error: %s (see ballbench --help)\n", e.what());
    return 2;
  }

  try {
    if (app.got_subcommand("list")) return cmd_list();

    if (app.got_subcommand("run")) {
      Scene scene = load_scene(scene_arg);
      const auto engines = parse_engine_list(engine_arg);
      if (dt) scene.dt = *dt;
      if (duration) scene.duration = *duration;
      if (scene.duration / scene.dt > 1e9) throw InputError("--dt/--duration: more than 1e9 steps");
      RunOptions options;
      options.steps = steps ? *steps : -1;
      check_profile(engines, profile);
      for (const auto& s : sets) add_setting(options.overrides, s);
      for (const auto& [name, v] : options.overrides.items()) find_engine(name);  // typo check
      std::optional<TrajectoryCsv> trajectory;
      if (!trajectory_path.empty()) trajectory.emplace(trajectory_path), options.trajectory = &*trajectory;
      const auto results = run_all(scene, engines, profile, options, quiet);
      if (trajectory) trajectory->close();
      print_table(results);
      if (!json_path.empty()) write_results_file(json_path, results);
      return 0;
    }

    if (app.got_subcommand("report")) {
      const std::string results_dir = out_dir + "/results";
      if (!render_only) {
        std::filesystem::create_directories(results_dir);
        const std::vector<std::string> scenes = {"seed-box", "seed-bowl"};
        for (const auto& name : scenes) {
          const Scene scene = load_scene(name);
          RunOptions options;
          write_results_file(fmt::format("{}/{}.json", results_dir, name),
                             run_all(scene, parse_engine_list("all"), "all", options, false));
          fmt::print(stderr, "ran {}\n", name);
        }
        std::ofstream(results_dir + "/run.json") << run_context("scripts/report").dump(2) << '\n';
      }
      const std::string md = render_report(read_report_inputs(results_dir));
      const std::string path = out_dir + "/REPORT.md";
      std::ofstream(path + ".tmp") << md;
      std::filesystem::rename(path + ".tmp", path);
      fmt::print("wrote {}\n", path);
      return 0;
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "ballbench: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ballbench: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}

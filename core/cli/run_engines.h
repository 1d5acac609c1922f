#pragma once
// Running several engines (and their profiles) on one scene, and printing the result table:
// shared by the subcommands.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine.h"
#include "result.h"
#include "runner.h"
#include "scene.h"

namespace ballbench::cli {

// The profiles to run for one engine: "" = its default; "all" = every profile it has; a name, or
// comma-separated names = those of them the engine has, else its default (so `--profile tuned`
// names every external engine's tuned profile while our solvers run their default, and
// `--profile default,stock` runs our solvers' default and the external engines' stock).
std::vector<std::string> profiles_for(const EngineEntry& e, const std::string& profile);

// The runs run_all makes of one scene: every engine x profiles_for(engine, profile).
size_t run_count(const std::vector<const EngineEntry*>& engines, const std::string& profile);

// Throws InputError if no engine in `engines` has `profile`.
void check_profile(const std::vector<const EngineEntry*>& engines, const std::string& profile);

// How run_all runs each engine: by default in a child process with a time limit
// (core/isolated_run.h), so a crash or hang marks one row and the others complete; with
// `enabled = false` (--no-isolation) in this process, where a crash ends everything (useful in a
// debugger).
struct Isolation {
  bool enabled = true;
  double timeout_s = 600;  // per run (s)
  // Runs at once (run_all without a trajectory), each in its own child: an engine's CPU time, its
  // cost, barely moves with a run beside it on the other core (core/runner.h).
  int jobs = 1;
};

// Every engine x profile on `scene`; `base.overrides` holds settings per engine name. If
// `trajectory_path` is not empty, every run's trajectory goes to that CSV (one header line, runs
// in order; a run that crashed or timed out has no rows). `base.trajectory` must be null.
// Interrupted (SIGINT, SIGTERM, SIGHUP), it ends with the run in progress marked "interrupted", or, if
// the signal came between runs, a row marked so for the run that was next. A run whose engine
// refuses its settings (InputError) is a failed row. With `trajectory_error`, a trajectory that
// cannot be written is not thrown: the runs go on and it gets the one-line reason ("" if none).
std::vector<Result> run_all(const Scene& scene, const std::vector<const EngineEntry*>& engines,
                            const std::string& profile, const RunOptions& base, bool quiet,
                            const Isolation& isolation = {}, const std::string& trajectory_path = "",
                            std::string* trajectory_error = nullptr);

// Placements 1 .. seeds - 1 of a scene (`place(k)` draws placement k) appended to `results`, which
// holds the runs of placement 0 (`first`). An interrupt ends them with a row marked "interrupted",
// as in run_all; one that comes between placements marks the next placement's first run, before
// drawing it (drawing is not a run, and would be lost).
void run_further_placements(std::vector<Result>& results, const Scene& first, int seeds,
                            const std::function<Scene(int)>& place, const std::vector<const EngineEntry*>& engines,
                            const std::string& profile, const RunOptions& base, bool quiet,
                            const Isolation& isolation);

// A long command's JSON and CSV outputs, checked before it runs (it takes minutes): writable, and
// neither the scene, an input, nor each other (data_file.h's check_path_clashes). `what` names
// them in messages: "the sweep's".
void check_json_and_csv(const Scene& scene, const std::string& json, const std::string& csv, const std::string& what);

// The command line as typed (main stores it), for the record of what produced a result.
void set_command_line(int argc, char** argv);

// Machine, compiler, build type and flags, the command line and the date: written beside results.
nlohmann::json run_context();

void print_table(const std::vector<Result>& results);

// The results of `seeds` placements (ensemble.h): per engine and profile, each metric's mean with
// its 95% bootstrap interval, and whether it differs significantly from the run labelled `ours`.
void print_ensemble(const std::vector<Result>& results, int seeds, const std::string& ours);

// "--set home.contact_iterations=4" -> overrides["home"]["contact_iterations"] = 4. The value is
// read as JSON (numbers, true/false) and falls back to a plain string.
void add_setting(nlohmann::json& overrides, const std::string& item);

}  // namespace ballbench::cli

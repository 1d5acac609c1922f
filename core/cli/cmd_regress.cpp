// `ballbench regress`: our deterministic solvers on a fixed suite of short scenes, compared with a
// committed baseline (tests/regress/baseline.json) metric by metric, each within a tolerance, and
// by trajectory checksum. Every difference is one line; any difference exits with status 1.
// `--update` rewrites the baseline: do it on purpose, after an intended change to a solver.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "progress.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "json_value.h"
#include "machine_info.h"
#include "metrics/catalog.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"
#include "validators.h"

namespace ballbench::cli {
namespace {

// The suite: our double-precision solvers, which are deterministic (same build, scene and settings
// give the same bits), on seed-box (whole), seed-bowl (its first 10 s) and the small scenes in
// tests/regress/scenes/ (their own duration). Under a second in a release build, so it runs with
// every test.
const char* const kEngines[] = {"home", "exact"};
struct SuiteScene {
  std::string scene;  // built-in name or path
  long steps;         // < 0: the scene's duration / dt
};
std::vector<SuiteScene> suite() {
  std::vector<SuiteScene> out{{"seed-box", 3000}, {"seed-bowl", 1000}};
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(std::string(BALLBENCH_REGRESS_DIR) + "/scenes", ec))
    if (e.path().extension() == ".toml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) out.push_back({f, -1});
  return out;
}

// Default tolerances, written into a new baseline; a baseline's own "tolerances" are the ones used
// (so they can be changed there) and survive --update. A metric passes if
// |now - baseline| <= abs + rel |baseline|. Each metric's own is in the catalog
// (core/metrics/catalog.h: counts exact, real-valued metrics relative 1e-9 with an absolute floor
// of 1e-12); the run's outcome (steps done, the step it diverged at) must match exactly. Our
// solvers compute in double with -ffp-contract=off, so the same source gives the same bits on every
// x86-64 build we make (checked: g++ -O2, and -O0 and -O1 with ASan and UBSan, give identical
// checksums), while any change of algorithm or constant moves these metrics by far more (home's
// contact_iterations 50 -> 4 moves energy.final on seed-bowl by 0.6%). The checksums of the final
// state and of the whole trajectory (Result::checksum_*) must match exactly.
nlohmann::json default_tolerances() {
  const auto as_json = [](const Tolerance& t) { return nlohmann::json{{"rel", t.rel}, {"abs", t.abs}}; };
  nlohmann::json out = {{"steps_done", as_json({})}, {"diverged_step", as_json({})}};
  for (const MetricDef& m : metric_catalog())
    if (m.regress) out[m.key] = as_json(*m.regress);
  return out;
}

const char* kAbout =
    "ballbench regress baseline: our deterministic solvers on the suite in core/cli/cmd_regress.cpp. "
    "A metric passes if |now - baseline| <= abs + rel * |baseline| (tolerances below: counts exact, "
    "real-valued metrics relative 1e-9, see the comment in cmd_regress.cpp); status, settings, "
    "engine_version and both checksums must match exactly. Regenerate on purpose with "
    "`ballbench regress --update` after an intended solver change.";

// One run as the baseline stores it. Null for a metric the run does not have (energy drift when
// the initial energy is zero, diverged_step of a run that did not diverge).
nlohmann::json record(const Result& r) {
  nlohmann::json metrics = {{"steps_done", r.steps_done},
                            {"diverged_step", r.diverged() ? nlohmann::json(r.diverged_step) : nlohmann::json(nullptr)}};
  for (const MetricDef& m : metric_catalog())
    if (m.regress) metrics[m.key] = m.get(r);
  return {{"scene", r.scene},
          {"engine", r.engine},
          {"engine_version", r.engine_version},
          {"steps", r.steps},
          {"status", run_status_text(r.status)},
          {"error", r.error},
          {"checksum", {{"final", r.checksum_final}, {"trajectory", r.checksum_trajectory}}},
          {"metrics", metrics},
          {"settings", r.settings}};
}


// The differences between one baseline record and one new one, as lines.
void compare(const nlohmann::json& base, const nlohmann::json& now, const nlohmann::json& tolerances,
             std::vector<std::string>& lines) {
  const std::string who = fmt::format("{} {}", json_text(now["scene"]), json_text(now["engine"]));
  auto differs = [&](const std::string& what, const nlohmann::json& b, const nlohmann::json& n, const std::string& note) {
    lines.push_back(fmt::format("{} {}: baseline {}, now {}{}", who, what, json_text(b), json_text(n), note));
  };
  for (const char* key : {"engine_version", "steps", "status"})
    if (base.value(key, nlohmann::json()) != now[key]) differs(key, base.value(key, nlohmann::json()), now[key], "");
  for (const auto& [key, n] : now["metrics"].items()) {
    const nlohmann::json b = base.contains("metrics") ? base["metrics"].value(key, nlohmann::json()) : nlohmann::json();
    const nlohmann::json tol = tolerances.value(key, nlohmann::json{{"rel", 0.0}, {"abs", 0.0}});
    const double rel = tol.value("rel", 0.0), abs = tol.value("abs", 0.0);
    const std::string note = rel == 0 && abs == 0 ? " (must match exactly)" : fmt::format(" (tolerance: rel {}, abs {})", rel, abs);
    if (b.is_number() && n.is_number()) {
      const double bv = b.get<double>(), nv = n.get<double>();
      if (!(std::abs(nv - bv) <= abs + rel * std::abs(bv))) differs(key, b, n, note);
    } else if (b != n) {
      differs(key, b, n, note);
    }
  }
  for (const char* which : {"final", "trajectory"}) {
    const nlohmann::json b = base.contains("checksum") ? base["checksum"].value(which, nlohmann::json()) : nlohmann::json();
    if (b != now["checksum"][which]) differs(fmt::format("checksum.{}", which), b, now["checksum"][which], "");
  }
  const nlohmann::json bs = base.value("settings", nlohmann::json::object()), ns = now["settings"];
  for (const auto& [key, n] : ns.items())
    if (bs.value(key, nlohmann::json()) != n) differs("settings." + key, bs.value(key, nlohmann::json()), n, "");
  for (const auto& [key, b] : bs.items())
    if (!ns.contains(key)) differs("settings." + key, b, nlohmann::json(), "");
}

nlohmann::json read_baseline_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(fmt::format("{}: cannot read the baseline: no such file (create it with ballbench regress --update)", path));
  return parse_json_file(path, "the regress baseline");
}

// The baseline's format, written by --update: the only one this build reads.
constexpr int kBaselineFormat = 1;

void check_format(const nlohmann::json& baseline, const std::string& path) {
  const auto it = baseline.find("format_version");
  const std::string expected =
      fmt::format("expected {} (the baseline format this ballbench reads and `regress --update` writes)", kBaselineFormat);
  if (it == baseline.end()) throw InputError(fmt::format("{}: format_version: missing, {}", path, expected));
  if (!it->is_number_integer() || *it != kBaselineFormat)
    throw InputError(fmt::format("{}: format_version: got {}, {}", path, it->dump(), expected));
}

// A baseline as --update writes it, every field present: the field of another type is named.
JsonShape baseline_shape() {
  const nlohmann::json tolerances = default_tolerances();
  nlohmann::json run = record(Result{});
  for (const auto& [key, tolerance] : tolerances.items()) run["metrics"][key] = 0.0;
  return {{{"format_version", kBaselineFormat},
           {"about", ""},
           {"generated_with", ""},
           {"tolerances", tolerances},
           {"runs", nlohmann::json::array({run})}},
          ""};
}

// Throws unless `key` is a metric the suite computes (one no run computes would never be compared).
void check_metric(const std::string& key, const std::string& where, const std::string& path) {
  const nlohmann::json known = default_tolerances();
  if (known.contains(key)) return;
  std::vector<std::string> names;
  for (const auto& [k, v] : known.items()) names.push_back(k);
  throw InputError(fmt::format("{}: {}: metric '{}' is not one the suite computes{} (known: {})", path, where, key,
                               did_you_mean(key, names), fmt::join(names, ", ")));
}

// Each (scene, engine) run once (a run listed twice would be compared once), with metrics the
// suite computes.
void check_runs(const nlohmann::json& runs, const std::string& path) {
  std::vector<std::string> seen;
  for (const auto& run : runs) {
    if (!run.contains("scene") || !run.contains("engine"))
      throw InputError(fmt::format("{}: runs: every run needs a scene and an engine", path));
    const std::string who = fmt::format("{} {}", json_text(run["scene"]), json_text(run["engine"]));
    if (std::find(seen.begin(), seen.end(), who) != seen.end())
      throw InputError(fmt::format("{}: runs: {} is listed twice", path, who));
    seen.push_back(who);
    if (run.contains("metrics"))
      for (const auto& [key, v] : run["metrics"].items()) check_metric(key, fmt::format("runs: {}", who), path);
  }
}

// A tolerance no plausible change could exceed passes anything: refused. A metric passes if
// |now - baseline| <= abs + rel |baseline|. With rel >= 1 a value may fall to zero or double and
// pass. abs is a floor for round-off near zero: at or above the largest |value| the baseline holds
// for the metric, every run's value may vanish or double and pass. The catalog's own floor is
// always taken; above it, a metric zero or absent in every run has no value to bound it by.
void check_can_fail(const std::string& key, const nlohmann::json& tolerance, const nlohmann::json& runs,
                    const std::string& path) {
  const std::string at = fmt::format("{}: tolerances.{}", path, key);
  const double rel = tolerance.value("rel", 0.0), abs = tolerance.value("abs", 0.0);
  if (rel >= 1)
    throw InputError(fmt::format("{}.rel: {} cannot fail: at 1 or above a value may vanish or double and pass "
                                 "(expected below 1)", at, rel));
  const double floor = default_tolerances()[key]["abs"].get<double>();
  double largest = 0;
  for (const auto& run : runs)
    if (run.contains("metrics") && run["metrics"].contains(key) && run["metrics"][key].is_number())
      largest = std::max(largest, std::abs(run["metrics"][key].get<double>()));
  if (abs <= floor || abs < largest) return;
  if (largest <= floor)
    throw InputError(fmt::format("{}.abs: {}: no run in the baseline has a |{}| above the default {} to show it can "
                                 "fail (expected at most {})", at, abs, key, floor, floor));
  throw InputError(fmt::format("{}.abs: {} cannot fail: at or above the largest |{}| in the baseline ({}), every run's "
                               "value may vanish or double and pass (expected below {})", at, abs, key, largest, largest));
}

void check_tolerances(const nlohmann::json& tolerances, const nlohmann::json& runs, const std::string& path) {
  for (const auto& [key, v] : tolerances.items()) {
    check_metric(key, "tolerances", path);
    for (const char* part : {"rel", "abs"})
      if (v.contains(part) && !(v[part].is_number() && v[part].get<double>() >= 0 && std::isfinite(v[part].get<double>())))
        throw InputError(fmt::format("{}: tolerances.{}.{}: expected a finite number >= 0, got {}", path, key, part,
                                     v[part].dump()));
    check_can_fail(key, v, runs, path);
  }
}

// A baseline the comparison would read wrongly is refused before anything runs, each problem one
// line naming the file: a field of another type than --update writes, a run listed twice, a
// metric the suite does not compute, a tolerance that cannot fail.
void check_baseline(const nlohmann::json& baseline, const std::string& path) {
  if (const std::string m = json_shape_mismatch(baseline_shape(), baseline); !m.empty())
    throw InputError(fmt::format("{}: {}", path, m));
  const nlohmann::json& runs = baseline["runs"];
  check_runs(runs, path);
  if (baseline.contains("tolerances")) check_tolerances(baseline["tolerances"], runs, path);
}

struct RegressArgs {
  std::string baseline = std::string(BALLBENCH_REGRESS_DIR) + "/baseline.json";
  bool update = false;
  std::vector<std::string> sets;
  double timeout_s = 120;
};

// Read before running, so a missing or broken baseline (or one --update cannot write) is
// reported at once.
nlohmann::json baseline_to_compare(const RegressArgs& a) {
  if (a.update) {
    std::vector<PathUse> uses = noted_input_files();
    uses.push_back({"--baseline", a.baseline, true});
    check_path_clashes(uses);
    check_writable(a.baseline, "the baseline", true);
    return nullptr;
  }
  nlohmann::json baseline = read_baseline_file(a.baseline);
  // The format first where it is given: a baseline of another format may hold anything else.
  if (baseline.is_object() && baseline.contains("format_version")) check_format(baseline, a.baseline);
  if (!baseline.is_object() || !baseline.contains("runs") || !baseline["runs"].is_array())
    throw InputError(fmt::format("{}: not a regress baseline: no \"runs\" array", a.baseline));
  check_format(baseline, a.baseline);
  check_baseline(baseline, a.baseline);
  return baseline;
}

// The suite's scenes, loaded, with the --set settings checked on each before anything runs (an
// engine refusing them would otherwise fail every run, each a difference that never names the key).
std::vector<std::pair<Scene, long>> suite_scenes(const nlohmann::json& overrides) {
  std::vector<std::pair<Scene, long>> scenes;
  for (const SuiteScene& item : suite()) {
    scenes.emplace_back(load_scene(item.scene), item.steps);
    check_settings(scenes.back().first, overrides);
  }
  return scenes;
}

// The suite's runs, each as the baseline records it.
std::vector<nlohmann::json> run_suite(const RegressArgs& a, RunOptions options,
                                      const std::vector<const EngineEntry*>& engines,
                                      const std::vector<std::pair<Scene, long>>& scenes) {
  std::vector<nlohmann::json> runs;
  for (const auto& [scene, steps] : scenes) {
    options.steps = steps;
    for (const Result& r : run_all(scene, engines, "", options, true, Isolation{true, a.timeout_s}))
      runs.push_back(record(r));
    if (interrupt_signal()) break;
    if (!Progress::quiet) fmt::print(stderr, "regress: ran {}\n", scene.name);
  }
  return runs;
}

// --update: the runs as the new baseline. The old baseline's own tolerances win (checked against
// the new runs); a metric new since it was written gets its default. A baseline that cannot be
// read (the reason to replace it) gives none.
void write_baseline(const RegressArgs& a, const std::vector<nlohmann::json>& runs) {
  nlohmann::json tolerances = default_tolerances();
  if (std::filesystem::exists(a.baseline)) {
    try {
      const nlohmann::json old = read_baseline_file(a.baseline);
      if (old.is_object() && old.contains("tolerances") && old["tolerances"].is_object()) {
        check_baseline({{"tolerances", old["tolerances"]}, {"runs", runs}}, a.baseline);
        tolerances.update(old["tolerances"]);
      }
    } catch (const InputError& e) {
      fmt::print(stderr, "regress: the old baseline's tolerances are not kept ({}): the defaults are written\n",
                 printable(e.what()));
    }
  }
  const MachineInfo m = machine_info();
  write_file_atomically(a.baseline, nlohmann::json{{"format_version", kBaselineFormat},
                               {"about", kAbout},
                               {"generated_with", fmt::format("{}, {} build", m.compiler, m.build_type)},
                               {"tolerances", tolerances},
                               {"runs", runs}}.dump(2) + "\n",
                        "the baseline");
  fmt::print("regress: wrote {} ({} runs)\n", a.baseline, runs.size());
}

// Each run against its baseline run: a line per difference beyond its tolerance, per run missing
// on either side.
std::vector<std::string> differences(const RegressArgs& a, const nlohmann::json& baseline,
                                     const std::vector<nlohmann::json>& runs) {
  const nlohmann::json tolerances = baseline.value("tolerances", default_tolerances());
  auto key = [](const nlohmann::json& r) { return json_text(r.value("scene", nlohmann::json())) + " " + json_text(r.value("engine", nlohmann::json())); };
  std::vector<std::string> lines;
  try {
    for (const auto& now : runs) {
      const auto& base = baseline["runs"];
      const auto it = std::find_if(base.begin(), base.end(), [&](const nlohmann::json& b) { return key(b) == key(now); });
      if (it == base.end()) lines.push_back(fmt::format("{}: not in the baseline", key(now)));
      else compare(*it, now, tolerances, lines);
    }
    for (const auto& b : baseline["runs"])
      if (std::none_of(runs.begin(), runs.end(), [&](const nlohmann::json& r) { return key(r) == key(b); }))
        lines.push_back(fmt::format("{}: in the baseline but no longer in the suite", key(b)));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a regress baseline: {}", a.baseline, e.what()));
  }
  return lines;
}

void regress(const RegressArgs& a) {
  RunOptions options;
  for (const auto& s : a.sets) add_setting(options.overrides, s);
  std::vector<const EngineEntry*> engines;
  for (const char* name : kEngines) engines.push_back(&find_engine(name));
  for (const auto& [name, v] : options.overrides.items())
    if (std::none_of(std::begin(kEngines), std::end(kEngines), [&](const char* e) { return name == e; }))
      throw InputError(fmt::format("--set {}: regress runs only {}", name, fmt::join(kEngines, ", ")));
  const auto scenes = suite_scenes(options.overrides);
  const nlohmann::json baseline = baseline_to_compare(a);
  install_interrupt_handlers();
  const std::vector<nlohmann::json> runs = run_suite(a, options, engines, scenes);
  // A suite cut short is compared with nothing and written nowhere.
  exit_if_interrupted(fmt::format("the suite was cut short after {} run(s): nothing compared{}", runs.size(),
                                  a.update ? ", the baseline not rewritten" : ""));
  if (a.update) return write_baseline(a, runs);
  const std::vector<std::string> lines = differences(a, baseline, runs);
  if (lines.empty()) {
    fmt::print("regress: {} runs match {}\n", runs.size(), a.baseline);
    return;
  }
  for (const auto& l : lines) fmt::print("regressed: {}\n", l);
  fmt::print("regress: {} difference{} from {} (if intended: ballbench regress --update)\n", lines.size(),
             lines.size() == 1 ? "" : "s", a.baseline);
  throw CheckFailed{1};
}

}  // namespace

void add_regress(CLI::App& app) {
  auto a = std::make_shared<RegressArgs>();
  auto* cmd = app.add_subcommand("regress", "run our solvers on the regression suite and compare with the baseline");
  cmd->add_option("--baseline", a->baseline, "baseline file (default: tests/regress/baseline.json in the source tree)");
  auto* set = cmd->add_option("--set", a->sets, "engine setting ENGINE.KEY=VALUE (repeatable): see what a change does");
  cmd->add_flag("--update", a->update, "rewrite the baseline from this run (after an intended change)")->excludes(set);
  cmd->add_option("--timeout", a->timeout_s, "seconds each run may take before it is killed (default 120)")
      ->check(kPositiveNumber);
  add_quiet(cmd, Progress::quiet);
  cmd->callback([a] { regress(*a); });
}

}  // namespace ballbench::cli

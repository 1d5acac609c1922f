#include "run_engines.h"

#include <algorithm>
#include <atomic>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "data_file.h"
#include "ensemble.h"
#include "shell_word.h"
#include "input_error.h"
#include "interrupt.h"
#include "isolated_run.h"
#include "machine_info.h"
#include "metrics/catalog.h"
#include "progress.h"
#include "recorded_reference.h"
#include "run_status.h"
#include "trajectory_csv.h"

namespace ballbench::cli {
namespace {

// The row of a run an interrupt kept from starting.
Result not_started(const Scene& scene, const EngineEntry& entry, const RunOptions& options) {
  Result r = result_header(scene, entry, options);
  r.status = RunStatus::interrupted;
  r.error = fmt::format("interrupted by {} before this run started", interrupt_name());
  return r;
}

// The trajectory CSV of isolated runs: each child writes its own part (a complete CSV, header
// included, by TrajectoryCsv); the parts are joined here, in run order, under one header. Every
// temporary file is this run's own: named with this process's id and a random token and created
// here before the child starts (O_EXCL), so a part left by a killed run, or written by another run
// at the same time, is never taken. The file appears only when complete (written beside it, then
// renamed), and the parts are removed even if a run throws.
class TrajectoryParts {
 public:
  TrajectoryParts(std::string path, bool rotation) : path_(std::move(path)) {
    try {
      joined_ = create_temp_beside(temp_base(path_), "the trajectory");
      TrajectoryCsv(joined_, rotation, joined_ + ".header").close();  // the header alone, from the one writer
    } catch (const InputError&) {
      remove_all();
      throw InputError(fmt::format("--trajectory {}: cannot open for writing", path_));
    }
  }
  ~TrajectoryParts() { remove_all(); }
  TrajectoryParts(const TrajectoryParts&) = delete;
  TrajectoryParts& operator=(const TrajectoryParts&) = delete;

  // A new, empty part for the next run; its child renames its rows over it when its run is done.
  std::string next_part() {
    parts_.push_back(create_temp_beside(temp_base(path_) + ".part", "the trajectory"));
    return parts_.back();
  }

  // Appends the rows of the last part, if its run wrote them (a run that crashed left it empty).
  void take_last() {
    std::ifstream in(parts_.back(), std::ios::binary);
    if (!in) return;
    std::string header;
    std::getline(in, header);
    // A run that wrote no row (refused as unsupported): copying nothing would set the failbit.
    if (in.peek() == std::ifstream::traits_type::eof()) return;
    std::ofstream out(joined_, std::ios::binary | std::ios::app);
    out << in.rdbuf();
    out.flush();
    if (!out) throw InputError(fmt::format("--trajectory {}: writing failed: {}", path_, write_error_text(errno)));
  }

  void finish() {
    move_file_into_place(joined_, path_, "the trajectory");
    joined_.clear();
  }

 private:
  void remove_all() {
    std::error_code ec;
    for (const std::string& p : parts_) std::filesystem::remove(p, ec), std::filesystem::remove(p + ".tmp", ec);
    if (!joined_.empty()) std::filesystem::remove(joined_, ec), std::filesystem::remove(joined_ + ".header", ec);
  }
  std::string path_, joined_;
  std::vector<std::string> parts_;
};

std::string& command_line_store() {
  static std::string line;
  return line;
}

}  // namespace

void set_command_line(int argc, char** argv) {
  std::string& line = command_line_store();
  line.clear();
  for (int k = 0; k < argc; ++k) line += (k ? " " : "") + shell_word(argv[k]);
}

nlohmann::json run_context() {
  const MachineInfo m = machine_info();
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return {{"cpu", m.cpu},
          {"cores", m.cores},
          {"os", m.os},
          {"compiler", m.compiler},
          {"build_type", m.build_type},
          {"flags", m.flags},
          {"build", m.build},
          {"command", command_line_store()},
          {"date", date}};
}

void add_setting(nlohmann::json& overrides, const std::string& item) {
  const auto dot = item.find('.'), eq = item.find('=');
  if (dot == std::string::npos || eq == std::string::npos || dot > eq || dot == 0 || eq == dot + 1)
    throw InputError(fmt::format("--set '{}': expected ENGINE.KEY=VALUE", item));
  const std::string value = item.substr(eq + 1);
  nlohmann::json parsed = nlohmann::json::parse(value, nullptr, false);
  if (parsed.is_discarded() || parsed.is_object() || parsed.is_array()) parsed = value;
  nlohmann::json& slot = overrides[item.substr(0, dot)][item.substr(dot + 1, eq - dot - 1)];
  if (!slot.is_null()) throw InputError(fmt::format("--set {}: set twice (give each setting once)", item.substr(0, eq)));
  slot = parsed;
}

// One row per run: its outcome, the catalog's metrics that have a heading (core/metrics/catalog.h)
// and that some run has, the error against the reference and the timing.
void print_table(const std::vector<Result>& results) {
  std::vector<const MetricDef*> shown;
  for (const MetricDef& m : metric_catalog())
    if (!m.heading.empty() &&
        std::any_of(results.begin(), results.end(), [&](const Result& r) { return !m.get(r).is_null(); }))
      shown.push_back(&m);
  fmt::print("{:<18} {:<11} {:>6} {:>8}", "engine", "status", "n", "steps");
  for (const MetricDef* m : shown) fmt::print(" {:>10}", m->heading);
  fmt::print(" {:>10} {:>9} {:>12} {:>10}\n", "pos.err", "horizon", "ns/ball-step", "with pipe");
  for (const auto& r : results) {
    const auto& e = r.reference;
    fmt::print("{:<18} {:<11} {:>6} {:>8}", printable(run_label(r)), run_status_text(r.status), r.n, r.steps_done);
    for (const MetricDef* m : shown) fmt::print(" {:>10}", metric_text(m->get(r)));
    // A run that made no step measured no time: "-", never a 0.0 that reads as infinitely fast.
    fmt::print(" {:>10} {:>9} {:>12} {:>10}\n", e.available ? fmt::format("{:.3g}", e.pos_rms_final) : "-",
               !e.available ? "-" : e.horizon ? fmt::format("{:.3g}", *e.horizon) : "never",
               r.measured() ? fmt::format("{:.1f}", r.ns_per_ball_step) : "-",
               r.engine_process_s ? fmt::format("{:.1f}", r.engine_s * 1e9 / std::max(1L, r.steps_done) / std::max(1, r.n))
                                  : "-");
  }
  if (std::any_of(results.begin(), results.end(), [](const Result& r) { return r.engine_process_s.has_value(); }))
    fmt::print("ns/ball-step: the engine's own step time; an engine in another process times its step calls itself, "
               "and `with pipe` is the harness's time of the whole request\n");
  for (const auto& r : results) {
    if (!r.error.empty()) fmt::print("{}: {}\n", printable(run_label(r)), printable(r.error));
    if (!r.clamped.empty()) fmt::print("{}: clamped: {}\n", printable(run_label(r)), printable(r.clamped));
    for (const std::string& note : r.skipped)
      if (note.rfind(kStrideNote, 0) == 0) fmt::print("{}: {}\n", run_label(r), note);
    if (r.reference.reference_failed_step >= 0)
      fmt::print("{}: reference {} failed at step {}, error compared up to it: {}\n", run_label(r),
                 r.reference.reference, r.reference.reference_failed_step, r.reference.reference_error);
  }
  if (!results.empty() && results.front().reference.available)
    fmt::print("pos.err: position RMS error against {} at the last step (m); horizon: first time it exceeded {:.3g} m\n",
               results.front().reference.reference, results.front().reference.horizon_tolerance);
}

void print_ensemble(const std::vector<Result>& results, int seeds, const std::string& ours) {
  const auto rows = summarise_ensemble(results, ours);
  const auto& metrics = ensemble_metrics();
  fmt::print("{} placements of {}: mean [95% bootstrap interval] over the runs that ended ok{}\n", seeds,
             results.empty() ? "" : results.front().scene,
             ours.empty() ? "" : fmt::format("; +/-: significantly above/below {} on the same placements, =: not", ours));
  fmt::print("{:<18} {:>3}", "engine", "ok");
  for (const auto& m : metrics) fmt::print("  {:<31}", m.name);
  fmt::print("\n");
  for (const EnsembleRow& row : rows) {
    fmt::print("{:<18} {:>3}", row.label, row.placements);
    for (size_t k = 0; k < metrics.size(); ++k)
      fmt::print("  {:<31}", row.metrics[k] ? interval_text(*row.metrics[k]) + " " + row.versus_ours[k] : "-");
    fmt::print("\n");
  }
  for (const auto& r : results)
    if (!r.error.empty()) fmt::print("{} (seed offset {}): {}\n", printable(run_label(r)), r.seed_offset, printable(r.error));
}

namespace {

// "tuned,default" -> {"tuned", "default"}: the names of a --profile list, each once.
std::vector<std::string> profile_names(const std::string& list) {
  std::vector<std::string> names;
  size_t at = 0;
  while (at <= list.size()) {
    const size_t comma = std::min(list.find(',', at), list.size());
    const std::string name = list.substr(at, comma - at);
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    at = comma + 1;
  }
  return names;
}

}  // namespace

void check_json_and_csv(const Scene& scene, const std::string& json, const std::string& csv, const std::string& what) {
  std::vector<PathUse> uses = noted_input_files();
  if (std::filesystem::exists(scene.source)) uses.push_back({"--scene", scene.source, false});
  uses.push_back({"--json", json, true});
  uses.push_back({"--csv", csv, true});
  check_path_clashes(uses);
  check_writable(json, what + " results", true);
  check_writable(csv, what + " CSV", true);
}

std::vector<std::string> profiles_for(const EngineEntry& e, const std::string& profile) {
  const auto& mine = e.info.profiles;
  std::vector<std::string> out;
  for (const std::string& name : profile_names(profile)) {
    if (name == "all") return mine;
    if (std::find(mine.begin(), mine.end(), name) != mine.end()) out.push_back(name);
  }
  if (out.empty()) out.push_back(mine.front());
  return out;
}

size_t run_count(const std::vector<const EngineEntry*>& engines, const std::string& profile) {
  size_t runs = 0;
  for (const EngineEntry* e : engines) runs += profiles_for(*e, profile).size();
  return runs;
}

void check_profile(const std::vector<const EngineEntry*>& engines, const std::string& profile) {
  std::vector<std::string> known;
  for (const auto* e : engines)
    for (const auto& p : e->info.profiles)
      if (std::find(known.begin(), known.end(), p) == known.end()) known.push_back(p);
  for (const std::string& name : profile_names(profile))
    if (name != "all" && std::find(known.begin(), known.end(), name) == known.end())
      throw InputError(fmt::format("--profile: no selected engine has a profile '{}' (they have: {}, or all)", name,
                                   fmt::join(known, ", ")));
}

namespace {

// Where the runs' trajectories go: one CSV written in this process, or parts from child processes
// joined. A trajectory that cannot be written (a full disk) loses the trajectory, not the runs:
// the error is kept for the command to report after its table and JSON.
class TrajectorySink {
 public:
  TrajectorySink(const Scene& scene, const Isolation& isolation, const std::string& path, bool keep_errors)
      : keep_errors_(keep_errors), path_(path) {
    if (path.empty()) return;
    const bool rotation = scene.features().rotation;
    if (isolation.enabled) parts_.emplace(path, rotation);
    else csv_.emplace(path, rotation);
  }
  TrajectoryCsv* csv() { return csv_ && lost_.empty() ? &*csv_ : nullptr; }
  // The next child's part file ("" for none).
  std::string next_part() {
    std::string part;
    if (parts_) keep_going([&] { part = parts_->next_part(); });
    return part;
  }
  // `lost`: why the child could not write its part ("" if it did): the trajectory is lost, and
  // whatever was at its path kept.
  void take_last(const std::string& part, const std::string& lost) {
    if (parts_ && !lost.empty())
      keep_going([&] { throw InputError(fmt::format("--trajectory {}: writing failed: {}", path_, lost)); });
    if (parts_ && !part.empty()) keep_going([&] { parts_->take_last(); });
  }
  // Closes the file; the error that lost the trajectory, or "".
  std::string finish() {
    if (csv_) keep_going([&] { csv_->close(); });
    if (parts_) keep_going([&] { parts_->finish(); });
    return lost_;
  }

 private:
  void keep_going(const std::function<void()>& write) {
    if (!lost_.empty()) return;
    try {
      write();
    } catch (const InputError& e) {
      if (!keep_errors_) throw;
      lost_ = e.what();
      parts_.reset();
    }
  }
  bool keep_errors_;
  std::string path_;
  std::optional<TrajectoryCsv> csv_;     // in this process
  std::optional<TrajectoryParts> parts_;  // from child processes
  std::string lost_;
};

// One engine and profile, in this process or a child. The settings were checked before the first
// run; an engine that refuses them only now (an engine process answering its scene with a settings
// error) fails its own row, not the rows already run.
Result run_one(const Scene& scene, const EngineEntry& e, RunOptions options, const Isolation& isolation,
               TrajectorySink& sink) {
  const auto settings_refused = [&](const InputError& err) {
    Result r = result_header(scene, e, options);
    r.status = RunStatus::failed;
    r.error = fmt::format("the engine refused its settings: {}", err.what());
    return r;
  };
  if (!isolation.enabled) {
    options.trajectory = sink.csv();
    try {
      return run_engine(scene, e, options);
    } catch (const InputError& err) {
      return settings_refused(err);
    }
  }
  const std::string part = sink.next_part();
  std::string lost;
  Result r;
  try {
    r = run_engine_isolated(scene, e, options, IsolationOptions{isolation.timeout_s, part, &lost});
  } catch (const InputError& err) {
    r = settings_refused(err);
  }
  sink.take_last(part, lost);
  return r;
}

// Every engine and profile, `isolation.jobs` at a time, each run in its own child; the rows in
// engine order, as one at a time.
std::vector<Result> run_side_by_side(const Scene& scene, const std::vector<const EngineEntry*>& engines,
                                     const std::string& profile, const RunOptions& base, bool quiet,
                                     const Isolation& isolation) {
  std::vector<std::pair<const EngineEntry*, std::string>> runs;
  for (const EngineEntry* e : engines)
    for (const std::string& p : profiles_for(*e, profile)) runs.emplace_back(e, p);
  const auto options_for = [&](size_t i) {
    RunOptions options = base;
    options.profile = runs[i].second;
    options.overrides = base.overrides.value(runs[i].first->info.name, nlohmann::json::object());
    return options;
  };
  // An engine in a process of its own runs in this thread: its process dies with the thread that
  // started it (PR_SET_PDEATHSIG), and this one's serves the next table; the others fork a child.
  std::vector<size_t> own, forked;
  for (size_t i = 0; i < runs.size(); ++i) (runs[i].first->info.own_process ? own : forked).push_back(i);
  std::vector<std::optional<Result>> made(runs.size());
  std::atomic<size_t> next_own{0}, next_forked{0};
  std::mutex shown;
  size_t done = 0;
  Progress progress(fmt::format("{}: {} runs, {} at once", scene.name, runs.size(), isolation.jobs));
  const auto take = [&](bool this_thread) -> std::optional<size_t> {
    if (this_thread)
      if (const size_t k = next_own++; k < own.size()) return own[k];
    if (const size_t k = next_forked++; k < forked.size()) return forked[k];
    return std::nullopt;
  };
  const auto worker = [&](bool this_thread) {
    TrajectorySink none(scene, isolation, "", false);
    for (std::optional<size_t> i; !interrupt_signal() && (i = take(this_thread));) {
      made[*i] = run_one(scene, *runs[*i].first, options_for(*i), isolation, none);
      std::lock_guard lock(shown);
      if (!quiet)
        progress.count(++done, runs.size(),
                       fmt::format("{} ({}): {}", runs[*i].first->info.name, runs[*i].second, run_status_text(made[*i]->status)));
    }
  };
  {
    std::vector<std::jthread> threads;  // joined on the way out, whatever this thread's worker throws
    for (int j = 1; j < std::min<int>(isolation.jobs, int(runs.size())); ++j) threads.emplace_back(worker, false);
    worker(true);
  }
  // Interrupted, the rows made in full first, in engine order, then those the signal cut (one a
  // thread), or else a row for the first run not begun: the last row says the table is incomplete,
  // as one at a time.
  std::vector<Result> results, cut;
  std::optional<size_t> first_missing;
  for (size_t i = 0; i < runs.size(); ++i) {
    if (!made[i]) {
      if (!first_missing) first_missing = i;
      continue;
    }
    (made[i]->status == RunStatus::interrupted ? cut : results).push_back(std::move(*made[i]));
  }
  results.insert(results.end(), cut.begin(), cut.end());
  if (cut.empty() && first_missing) results.push_back(not_started(scene, *runs[*first_missing].first, options_for(*first_missing)));
  return results;
}

}  // namespace

std::vector<Result> run_all(const Scene& scene, const std::vector<const EngineEntry*>& engines,
                            const std::string& profile, const RunOptions& base, bool quiet,
                            const Isolation& isolation, const std::string& trajectory_path,
                            std::string* trajectory_error) {
  TrajectorySink sink(scene, isolation, trajectory_path, trajectory_error != nullptr);
  std::vector<Result> results;
  // The reference once for every run of the scene, where more than one run compares against it.
  std::shared_ptr<const RecordedReference> recorded = base.recorded_reference;
  if (!recorded && base.reference && run_count(engines, profile) > 1)
    recorded = record_reference(scene, base, isolation.timeout_s);
  if (isolation.enabled && isolation.jobs > 1 && trajectory_path.empty()) {
    RunOptions shared = base;
    shared.recorded_reference = recorded;
    return run_side_by_side(scene, engines, profile, shared, quiet, isolation);
  }
  for (const EngineEntry* e : engines)
    for (const std::string& p : profiles_for(*e, profile)) {
      RunOptions options = base;
      options.recorded_reference = recorded;
      options.profile = p;
      if (interrupt_signal()) {  // asked to stop: the rows so far are the result
        // A signal between runs marks the run that was next; one during a run marked that run.
        if (results.empty() || results.back().status != RunStatus::interrupted) results.push_back(not_started(scene, *e, options));
        const std::string lost = sink.finish();
        if (trajectory_error) *trajectory_error = lost;
        return results;
      }
      Progress progress(fmt::format("{} ({}) on {}", e->info.name, p, scene.name));
      if (!quiet) options.progress = [&](long done, long total) { progress.update(double(done) / total); };
      options.overrides = base.overrides.value(e->info.name, nlohmann::json::object());
      results.push_back(run_one(scene, *e, options, isolation, sink));
    }
  const std::string lost = sink.finish();
  if (trajectory_error) *trajectory_error = lost;
  return results;
}

void run_further_placements(std::vector<Result>& results, const Scene& first, int seeds,
                            const std::function<Scene(int)>& place, const std::vector<const EngineEntry*>& engines,
                            const std::string& profile, const RunOptions& base, bool quiet,
                            const Isolation& isolation) {
  for (int k = 1; k < seeds && !engines.empty(); ++k) {
    if (!results.empty() && results.back().status == RunStatus::interrupted) return;  // run_all stopped
    if (interrupt_signal()) {  // placement k's first run is the one that was next
      RunOptions options = base;
      options.profile = profiles_for(*engines.front(), profile).front();
      Result r = not_started(first, *engines.front(), options);
      r.seed_offset = k;
      results.push_back(r);
      return;
    }
    auto more = run_all(place(k), engines, profile, base, quiet, isolation);
    results.insert(results.end(), more.begin(), more.end());
  }
}

}  // namespace ballbench::cli

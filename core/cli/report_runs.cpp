#include "report_runs.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "bench_results.h"
#include "conform_run.h"
#include "core_affinity.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "machine_info.h"
#include "match.h"
#include "progress.h"
#include "registry.h"
#include "restitution_calibration.h"
#include "scene_digest.h"
#include "scene_loader.h"
#include "stability_frontier.h"
#include "sweep.h"
#include "viewer_page.h"

namespace ballbench::cli {
namespace {

namespace fs = std::filesystem;

// A progress line on stderr, unless --quiet.
template <class... Args>
void progress_line(fmt::format_string<Args...> f, Args&&... args) {
  if (!Progress::quiet) fmt::print(stderr, f, std::forward<Args>(args)...);
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The names and versions of `engines`, as a part's context records the engines a report asked it for.
nlohmann::json engine_list(const std::vector<const EngineEntry*>& engines) {
  nlohmann::json list = nlohmann::json::array();
  for (const EngineEntry* e : engines) list.push_back(e->info.name + " " + e->info.version);
  return list;
}

// A part's results are reused only if this build made them, of the scene's present content, for the
// engines this report asks (an earlier report of another --engine list, an edited scene file or a
// rebuilt harness made other ones): why not, or "" if they are this report's.
std::string made_elsewhere(const nlohmann::json& context, const nlohmann::json& want) {
  constexpr std::pair<const char*, const char*> kOrigins[] = {{"build", "made by another build"},
                                                              {"scene_digest", "made of other contents of the scene"},
                                                              {"report_engines", "made for another list of engines"}};
  for (const auto& [key, why] : kOrigins)
    if (want.contains(key) && (!context.is_object() || context.value(key, nlohmann::json()) != want[key])) return why;
  return "";
}

// A results file holding exactly the runs a report makes of `scene` (every engine x profile), of
// its present content and by this build, left by an earlier report that stopped later on: reusing
// it resumes the report. Files are written whole (write_results_file), so one that reads back is
// complete.
bool complete_results(const std::string& path, const Scene& scene, const std::vector<const EngineEntry*>& engines,
                      int seeds) {
  if (!std::filesystem::exists(path)) return false;
  std::vector<Result> found;
  try {
    found = read_results_file(path);
  } catch (const InputError&) {
    return false;
  }
  std::vector<std::string> want, have;
  for (int k = 0; k < seeds; ++k)
    for (const auto* e : engines)
      for (const auto& p : profiles_for(*e, "all")) want.push_back(fmt::format("{}/{}/{}", e->info.name, p, k));
  const std::string digest = scene_digest(scene);
  for (const auto& r : found) {
    if (r.status == RunStatus::interrupted) return false;  // a report stopped in this part
    if (r.scene != scene.name || r.steps != scene.steps() || r.n != scene.n() || r.build != build_id()) return false;
    if (r.seed_offset == 0 && r.scene_digest != digest) return false;  // further placements are other contents
    have.push_back(fmt::format("{}/{}/{}", r.engine, r.profile, r.seed_offset));
  }
  std::sort(want.begin(), want.end()), std::sort(have.begin(), have.end());
  return want == have;
}

// Runs benchmark binary `bin` once per filter into `path` (Google Benchmark's JSON, via its own
// --benchmark_out, the processes' outputs joined); its console table goes to stderr as progress.
// `found` says whether an output holds what the filter asked for. A missing binary is reported and
// the section skipped ("`section` skipped: ..."); a filter whose run failed or found nothing is
// reported and left out, and the other filters' results stand. Returns what was left out, for the
// report to say (one line each).
std::vector<std::string> run_bench(const std::string& bin, const std::vector<std::string>& filters, std::optional<double> min_time,
               double budget_s, const std::string& path, const std::string& section,
               const std::function<bool(const BenchResults&)>& found) {
  std::vector<std::string> left_out;
  if (bin.empty() || ::access(bin.c_str(), X_OK) != 0) {
    fmt::print(stderr, "{} skipped: no benchmark at {} (build with -DBALLBENCH_BENCH=ON)\n", section, bin);
    return {fmt::format("the {} section: no benchmark binary at {} (built without -DBALLBENCH_BENCH=ON)", section,
                        fs::path(bin).filename().string())};
  }
  progress_line("running {} for the {} section\n", bin, section);
  // One process per filter, so a filter that runs one benchmark alone (the 10^6 bowl) has its peak
  // resident set to itself.
  nlohmann::json joined;
  for (size_t k = 0; k < filters.size(); ++k) {
    const std::string& filter = filters[k];
    const std::string tmp = create_temp_beside(path, "the benchmark output");  // this report's own
    const std::string cmd =
        fmt::format("'{}' --benchmark_filter='{}' {} --budget_s={} --benchmark_out='{}' --benchmark_out_format=json {}",
                    bin, filter, min_time ? fmt::format("--benchmark_min_time={}", *min_time) : "", budget_s, tmp,
                    Progress::quiet ? ">/dev/null 2>&1" : "1>&2");
    const int rc = std::system(cmd.c_str());
    // std::system ignores SIGINT while it waits; a benchmark ended by the terminal's SIGINT (or a
    // SIGTERM) is this report's interrupt too, raised here so that interrupt.h sees it.
    const int sig = WIFSIGNALED(rc) ? WTERMSIG(rc) : WIFEXITED(rc) && WEXITSTATUS(rc) > 128 ? WEXITSTATUS(rc) - 128 : 0;
    if (sig == SIGINT || sig == SIGTERM || interrupt_signal()) {
      fs::remove(tmp);
      if (!interrupt_signal()) std::raise(sig);
      return left_out;
    }
    std::string why = rc == 0            ? ""
                      : WIFEXITED(rc)    ? fmt::format("it failed (exit status {})", WEXITSTATUS(rc))
                      : WIFSIGNALED(rc)  ? fmt::format("it was killed by signal {}", WTERMSIG(rc))
                                         : fmt::format("it failed (wait status {})", rc);
    // Google Benchmark writes nothing, and exits 0, when its filter matches no benchmark.
    const bool empty = why.empty() && fs::file_size(tmp) == 0;
    if (empty) why = "no benchmark matched it (`--benchmark_list_tests` lists them)", fs::remove(tmp);
    if (why.empty()) try {
        if (!found(read_bench_file(tmp))) why = "no benchmark matched " + filter;
      } catch (const InputError& e) {
        why = e.what();
      }
    if (!why.empty()) {  // this filter's part is left out; the others' stand
      fmt::print(stderr, "{}: part skipped: {} --benchmark_filter='{}': {}{}\n", section, bin, filter, why,
                 empty ? "" : "; its output is in " + tmp);
      left_out.push_back(fmt::format("part of the {} section, --benchmark_filter='{}': {}", section, filter, why));
      continue;
    }
    const nlohmann::json part = parse_json_file(tmp, "Google Benchmark JSON");
    if (joined.is_null()) joined = part;
    else for (const auto& b : part.at("benchmarks")) joined["benchmarks"].push_back(b);
    fs::remove(tmp);
  }
  if (joined.is_null()) {
    fmt::print(stderr, "{} skipped: no part of it ran\n", section);
    return left_out;
  }
  write_file_atomically(path, joined.dump(2) + "\n", "the benchmark results");
  return left_out;
}

std::string path_of(const ReportRun& run, const ReportPart& part) { return run.results_dir + "/" + part_file(part); }

// What a part's results are made from: this build, the content of its scene (null: a part of no
// scene) and the engines the report asked of it.
nlohmann::json made_for(const Scene* scene, const std::vector<const EngineEntry*>& engines) {
  nlohmann::json m = {{"build", build_id()}, {"report_engines", engine_list(engines)}};
  if (scene) m["scene_digest"] = scene_digest(*scene);
  return m;
}

// The context a part's results file records: the machine and command, and what it is made from.
nlohmann::json part_context(const Scene* scene, const std::vector<const EngineEntry*>& engines) {
  nlohmann::json c = run_context();
  c.update(made_for(scene, engines));
  return c;
}

// A part's results file left by an earlier report that reads back, ran to its end, and was made
// from what this report asks (made_for); one that was not is said, and run again.
template <class Read>
bool reusable(const ReportRun& run, const ReportPart& part, Read read, const std::vector<const EngineEntry*>& engines) {
  const std::string path = path_of(run, part);
  if (!fs::exists(path)) return false;
  try {
    const auto r = read(path);
    if constexpr (requires { r.interrupted; })
      if (!r.interrupted.empty()) return false;
    const std::optional<Scene> scene = part.scene.empty() ? std::nullopt : std::optional(load_scene(part.scene));
    const std::string why = made_elsewhere(r.context, made_for(scene ? &*scene : nullptr, engines));
    if (!why.empty()) progress_line("not reusing {}: {}\n", path, why);
    return why.empty();
  } catch (const InputError&) {
    return false;
  }
}

// Every engine and profile at the scene's own step, on each placement the suite asks for.
void run_table(const ReportRun& run, const ReportPart& part) {
  const Scene scene = load_scene(part.scene);
  const int seeds = scene.random_placement ? run.suite.seeds : 1;
  RunOptions options;
  // The error against `exact` (or a converged run) in every row, but for the heaps.
  if (!contains(run.suite.unreferenced, part.scene)) use_reference(options);
  // A scene marked `animated` (the thesis's): in the viewer and a GIF, as many frames as a page of every run holds.
  if (scene.animated) options.frames = viewer_frames(scene, static_cast<int>(run_count(run.engines, "all")));
  // A run on each core at once: the table's costs are each engine's CPU time.
  Isolation isolation = run.isolation;
  isolation.jobs = core_count();
  std::vector<Result> runs = run_all(scene, run.engines, "all", options, run.quiet, isolation);
  // Further placements, for the ensemble table: without frames (the animation and the viewer are of offset 0).
  options.frames = 0;
  run_further_placements(runs, scene, seeds, [&](int k) { return load_scene(part.scene, k); }, run.engines, "all",
                         options, run.quiet, isolation);
  write_results_file(path_of(run, part), runs);
}

void run_match_part(const ReportRun& run, const ReportPart& part) {
  const Scene scene = load_scene(part.scene);
  MatchOptions o;
  o.spec = scene_spec(scene);
  o.budget_runs = run.suite.match_budget;
  o.ceiling = run.suite.match_ceiling;
  o.max_halvings = run.suite.match_max_halvings;
  o.store = run.store;
  o.jobs = core_count();
  o.isolation = run.isolation;
  o.reference = reference_engine();
  o.converged_reference = converged_reference_engine();
  o.quiet = run.quiet;
  write_match_files(run_match(scene, run.matched, o, part_context(&scene, run.matched)), path_of(run, part),
                    fmt::format("{}/match-{}.csv", run.results_dir, part.scene));
}

const MeasuredMatch& measured_of(const ReportRun& run, const ReportPart& part) {
  for (const MeasuredMatch& m : run.suite.measured_matches)
    if (m.scene == part.scene) return m;
  throw std::logic_error("a measured part the suite does not name");
}

// A search measured before, copied into the results as it is (its own date and build), once its
// scene's content is checked to be today's.
void run_measured_part(const ReportRun& run, const ReportPart& part) {
  const MeasuredMatch& measured = measured_of(run, part);
  const MatchResult m = read_match_file(measured.path);
  const std::string now = scene_digest(load_scene(part.scene));
  if (m.scene_digest != now)
    throw InputError(fmt::format("{}: searched another content of scene {} (digest {}, now {}): measure it again with "
                                 "`ballbench match --scene {} --json {}`",
                                 measured.path, part.scene, m.scene_digest.empty() ? "not recorded" : m.scene_digest,
                                 now, part.scene, measured.path));
  write_file_atomically(path_of(run, part), read_text_file(measured.path), "the measured search's copy");
}

void run_sweep_part(const ReportRun& run, const ReportPart& part) {
  SweepOptions o;
  o.repeats = 5;
  o.quiet = run.quiet;
  o.reference = reference_engine();
  o.isolation = run.isolation;
  const Scene scene = load_scene(part.scene);
  write_sweep_files(run_sweep(scene, run.swept, o, part_context(&scene, run.swept)), path_of(run, part),
                    fmt::format("{}/sweep-{}.csv", run.results_dir, part.scene));
}

void run_stress_part(const ReportRun& run, const ReportPart& part) {
  const Scene scene = load_scene(part.scene);
  StressOptions o;
  o.profile = "all";
  o.levels = run.suite.stress_levels;
  o.quiet = run.quiet;
  o.reference = reference_engine();
  o.isolation = run.isolation;
  if (scene.container.kind != ContainerKind::Box) std::erase(o.knobs, "count");
  write_frontier_file(path_of(run, part), run_frontier(scene, run.swept, o, part_context(&scene, run.swept)));
}

void run_calibration_part(const ReportRun& run, const ReportPart& part) {
  CalibrationOptions o;
  o.isolation.timeout_s = run.suite.timeout_s;
  write_calibration_file(path_of(run, part), run_calibration(run.engines, o, part_context(nullptr, run.engines)));
}

void run_conform_part(const ReportRun& run, const ReportPart& part) {
  const ConformResult c = run_conform(run.engines, "all", part_context(nullptr, run.engines), false);
  if (run.store) keep_claim_checks(*run.store, c, run.engines);
  write_conform_file(path_of(run, part), c);
}

std::string harness_path(const ReportRun& run) { return run.results_dir + "/harness.json"; }

// The step benchmark, then the harness benchmark beside it (their ratios from one machine).
void run_bench_part(const ReportRun& run, const ReportPart& part) {
  const auto also = [&](const std::vector<std::string>& lines) {
    if (run.left_out) run.left_out->insert(run.left_out->end(), lines.begin(), lines.end());
  };
  const ReportSuite& s = run.suite;
  if (!fs::exists(path_of(run, part)))
    also(run_bench(run.bench_binary, s.bench_filters, s.bench_min_time, s.bench_budget_s, path_of(run, part),
                   "scaling", [](const BenchResults& b) { return !b.rows.empty() || !b.pipe.empty(); }));
  if (interrupt_signal()) return;
  if (!fs::exists(harness_path(run)))
    also(run_bench((fs::path(run.bench_binary).parent_path() / "ballbench_harness_benchmark").string(),
                   {s.harness_filter}, std::nullopt, s.bench_budget_s, harness_path(run), "harness overhead",
                   [](const BenchResults& b) { return !b.harness.empty(); }));
}

// How each kind of part runs and is known complete.
struct PartRunner {
  PartKind kind;
  void (*run)(const ReportRun&, const ReportPart&);
  bool (*complete)(const ReportRun&, const ReportPart&);
  const char* done;  // the progress line: its verb before the scene, or all of it for a part of every engine
};

const PartRunner kRunners[] = {
    {PartKind::table, run_table,
     [](const ReportRun& r, const ReportPart& p) {
       const Scene scene = load_scene(p.scene);
       return complete_results(path_of(r, p), scene, r.engines, scene.random_placement ? r.suite.seeds : 1);
     },
     "ran"},
    {PartKind::match, run_match_part,
     [](const ReportRun& r, const ReportPart& p) { return reusable(r, p, read_match_file, r.matched); }, "matched"},
    // Checked and copied again by every report: it takes a second, and the scene may have changed.
    {PartKind::measured, run_measured_part, [](const ReportRun&, const ReportPart&) { return false; },
     "carried the search measured before of"},
    {PartKind::sweep, run_sweep_part,
     [](const ReportRun& r, const ReportPart& p) { return reusable(r, p, read_sweep_file, r.swept); }, "swept"},
    {PartKind::stress, run_stress_part,
     [](const ReportRun& r, const ReportPart& p) { return reusable(r, p, read_frontier_file, r.swept); }, "stressed"},
    {PartKind::conform, run_conform_part,
     [](const ReportRun& r, const ReportPart& p) { return reusable(r, p, read_conform_file, r.engines); },
     "checked every engine against the closed forms"},
    {PartKind::calibration, run_calibration_part,
     [](const ReportRun& r, const ReportPart& p) { return reusable(r, p, read_calibration_file, r.engines); },
     "calibrated restitution"},
    {PartKind::bench, run_bench_part,
     [](const ReportRun& r, const ReportPart& p) { return fs::exists(path_of(r, p)) && fs::exists(harness_path(r)); },
     "ran the benchmarks"},
};

const PartRunner& runner(PartKind k) {
  for (const PartRunner& r : kRunners)
    if (r.kind == k) return r;
  throw std::logic_error("a part kind without a runner");
}

}  // namespace

// A benchmark binary built beside this executable (build/<preset>/bench/ next to core/cli/).
std::string default_bench_binary(const std::string& name) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  return (self.parent_path().parent_path().parent_path() / "bench" / name).string();
}

void choose_engines(ReportRun& run, const std::vector<const EngineEntry*>& engines) {
  // Sweeps, frontiers and matches may leave out engines whose runs are costly: each of their points
  // is a run of its own, which starts the engine's process (a Node engine: 0.1 to 0.4 s) or Open MPI
  // and thousands of DEM sub-steps (LAMMPS), hundreds of times over. Their scene tables,
  // calibration and benchmarks have every engine.
  for (const std::string& name : run.suite.match_costly_engines)
    if (!contains(engine_names(), name))
      throw InputError(fmt::format("the suite's match_costly_engines: unknown engine '{}'", name));
  run.engines = run.swept = run.matched = engines;
  if (run.suite.costly_engines) return;
  std::erase_if(run.swept, [](const EngineEntry* e) { return e->info.costly_runs; });
  std::erase_if(run.matched, [&](const EngineEntry* e) {
    return e->info.costly_runs && !contains(run.suite.match_costly_engines, e->info.name);
  });
}

bool part_complete(const ReportRun& run, const ReportPart& part) { return runner(part.kind).complete(run, part); }

void run_part(const ReportRun& run, const ReportPart& part) {
  const PartRunner& r = runner(part.kind);
  r.run(run, part);
  if (interrupt_signal()) return;
  if (part.scene.empty()) progress_line("{}\n", r.done);
  else progress_line("{} {}\n", r.done, part.scene);
}

}  // namespace ballbench::cli

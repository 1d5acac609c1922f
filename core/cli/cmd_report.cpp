// `ballbench report`: run the standard comparison (scene tables, work-precision sweeps, stability
// frontiers, the step and harness benchmarks), write the results and render REPORT.md with its
// figures.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>

#include <thread>

#include <fmt/format.h>

#include "commands.h"
#include "data_file.h"
#include "figures.h"
#include "bench_results.h"
#include "input_error.h"
#include "interrupt.h"
#include "match.h"
#include "report_suite.h"
#include "progress.h"
#include "registry.h"
#include "restitution_calibration.h"
#include "try_store.h"
#include "report_writer.h"
#include "run_engines.h"
#include "scene_loader.h"
#include "shard.h"
#include "stability_frontier.h"
#include "sweep.h"
#include "validators.h"
#include "viewer_page.h"

namespace ballbench::cli {
namespace {

namespace fs = std::filesystem;

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

struct ReportArgs {
  std::string out = "reports";
  bool quick = false;  // the default; the flag is there to say so
  bool full = false;
  bool render_only = false;
  bool fresh = false;
  bool no_bench = false;
  std::string bench_binary;  // default: beside this executable's build tree
  std::string shard;         // "I/N": run only that share of the parts, render nothing
  int seeds = 0;             // placements of each seed scene; 0: the suite's
  std::string engines = "all";  // the engines compared (parse_engine_list)
  std::string suites;           // the suites file (default: report_suites_file())
  std::string store = TryStore::default_dir();  // the equal-accuracy searches' results store
  bool quiet = false;           // no progress on stderr (what is skipped or left out is still said)
};

// A progress line on stderr, unless --quiet.
template <class... Args>
void progress_line(fmt::format_string<Args...> f, Args&&... args) {
  if (!Progress::quiet) fmt::print(stderr, f, std::forward<Args>(args)...);
}

// The report's parts in run order, each a results file (or, for "bench", the step and harness
// benchmarks together, so their ratios come from one machine). A shard runs the parts it takes.
std::vector<std::string> report_parts(const ReportSuite& suite, bool bench) {
  std::vector<std::string> parts;
  for (const auto& name : suite.scenes) parts.push_back("table:" + name);
  for (const auto& name : suite.match_scenes) parts.push_back("match:" + name);
  for (const auto& name : suite.sweep_scenes) parts.push_back("sweep:" + name);
  for (const auto& name : suite.stress_scenes) parts.push_back("stress:" + name);
  parts.push_back("calibration");
  if (bench) parts.push_back("bench");
  return parts;
}

// A results file holding exactly the runs a report makes of `scene` (every engine x profile),
// left by an earlier report that stopped later on: reusing it resumes the report. Files are written
// whole (write_results_file), so one that reads back is complete.
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
  for (const auto& r : found) {
    if (r.status == RunStatus::interrupted) return false;  // a report stopped in this part
    if (r.scene != scene.name || r.steps != scene.steps() || r.n != scene.n()) return false;
    have.push_back(fmt::format("{}/{}/{}", r.engine, r.profile, r.seed_offset));
  }
  std::sort(want.begin(), want.end()), std::sort(have.begin(), have.end());
  return want == have;
}

// A sweep or frontier file left by an earlier report that reads back and ran to its end.
template <class Read>
bool uninterrupted(const std::string& path, Read read) {
  if (!fs::exists(path)) return false;
  try {
    return read(path).interrupted.empty();
  } catch (const InputError&) {
    return false;
  }
}

// A benchmark binary built beside this executable (build/<preset>/bench/ next to core/cli/).
std::string default_bench_binary(const std::string& name) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  return (self.parent_path().parent_path().parent_path() / "bench" / name).string();
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

}  // namespace

void render_report_folder(const std::string& out) {
  ReportInputs inputs = read_report_inputs(out + "/results");
  inputs.roles = engine_roles();
  std::string md;
  try {
    md = render_report(inputs, draw_figures(inputs, out));
  } catch (const nlohmann::json::exception& e) {  // a field of run.json of another type than a report writes
    // The run record's fields that rendering reads by type (the machine's are shown as they are).
    const JsonShape record{{{"command", ""}, {"date", ""}, {"suite", ""}, {"scenes", nlohmann::json::array({""})}}, ""};
    throw InputError(json_type_error(out + "/results/run.json", "a report's run record", e, inputs.run, &record));
  } catch (const std::exception&) {  // a figure's gnuplot ended by the signal that stops this process
    if (interrupt_signal()) exit_if_interrupted(fmt::format("{}/REPORT.md not rewritten", out));
    throw;
  }
  exit_if_interrupted(fmt::format("{}/REPORT.md not rewritten", out));
  write_file_atomically(out + "/REPORT.md", md, "the report");
  fmt::print("wrote {}/REPORT.md\n", out);
}

namespace {

// What the report reads (an engines file, the benchmark binaries; with --render-only the results)
// lies outside what it writes and, with --fresh, empties: OUT/results, OUT/figures, OUT/REPORT.md.
void check_report_paths(const ReportArgs& a) {
  std::vector<PathUse> uses = noted_input_files();
  const std::string bin = a.bench_binary.empty() ? default_bench_binary("ballbench_step_benchmark") : a.bench_binary;
  if (!a.render_only && !a.no_bench && !bin.empty())
    for (const std::string& b : {bin, (fs::path(bin).parent_path() / "ballbench_harness_benchmark").string()})
      if (fs::exists(b)) uses.push_back({a.bench_binary.empty() ? "the benchmark" : "--bench-binary", b, false});
  if (!a.suites.empty()) uses.push_back({"--suites", a.suites, false});
  std::error_code ec;
  if (a.render_only)  // each result file read, against REPORT.md (a link to one would be written into it)
    for (const auto& e : fs::directory_iterator(a.out + "/results", ec))
      if (e.is_regular_file()) uses.push_back({"the results file", e.path().string(), false});
  if (!a.render_only) uses.push_back({"--out", a.out + "/results", true, true});
  uses.push_back({"--out", a.out + "/figures", true, true});
  uses.push_back({"--out", a.out + "/REPORT.md", true});
  check_path_clashes(uses);
}

void report(const ReportArgs& a) {
  install_interrupt_handlers();  // first: a stop request during the handshakes too
  Progress::quiet = a.quiet;
  if (!a.bench_binary.empty() && ::access(a.bench_binary.c_str(), X_OK) != 0)
    throw InputError(fmt::format("--bench-binary {}: not an executable file", a.bench_binary));
  const std::string results_dir = a.out + "/results";
  // Every place the report writes is checked before anything runs (a report takes minutes): an
  // --out that cannot hold them is one line, not an error from deep inside after the runs.
  for (const std::string& p : {a.out + "/REPORT.md", results_dir + "/run.json", a.out + "/figures/scaling.png"})
    check_writable(p, "the report's files", true);
  check_report_paths(a);
  ReportSuite suite = load_report_suite(a.full ? "full" : "quick", a.suites);
  const auto engines = parse_engine_list(a.engines);  // a bad name is an error before anything runs
  if (a.seeds > 0) suite.seeds = a.seeds;
  const Shard shard = a.shard.empty() ? Shard{} : parse_shard(a.shard);
  const std::vector<std::string> parts = report_parts(suite, !a.no_bench);
  const auto mine = [&](const std::string& part) {
    return shard.takes(std::find(parts.begin(), parts.end(), part) - parts.begin());
  };
  if (a.fresh) {
    // What an earlier report left (a --full one has more parts) must not reach this one.
    std::error_code ec;
    for (const std::string& dir : {results_dir, a.out + "/figures"})
      for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file()) fs::remove(e.path(), ec);
  }
  // Asked to stop: the part in progress is written (marked) and every finished part kept; a report
  // run again resumes from them. REPORT.md is only rendered from a report that ran to its end.
  auto stop_if_interrupted = [&] {
    exit_if_interrupted(fmt::format("the parts finished are in {} (a report run again resumes from them); {}/REPORT.md "
                                    "not rewritten",
                                    results_dir, a.out));
  };
  // What this report leaves out, said in it (run.json's "left_out").
  std::vector<std::string> left_out;
  if (a.no_bench)
    left_out.push_back("the scaling and harness overhead sections, and the pipe's cost: `--no-bench` ran no "
                       "benchmark");
  if (!a.render_only) {
    fs::create_directories(results_dir);
    // Sweeps, frontiers and matches may leave out engines whose runs are costly: each of their
    // points is a run of its own, which starts the engine's process (a Node engine: 0.1 to 0.4 s) or
    // Open MPI and thousands of DEM sub-steps (LAMMPS), hundreds of times over. Their scene
    // tables, calibration and benchmarks have every engine.
    std::vector<const EngineEntry*> swept = engines, matched = engines;
    for (const std::string& name : suite.match_costly_engines)
      if (!contains(engine_names(), name))
        throw InputError(fmt::format("the suite's match_costly_engines: unknown engine '{}'", name));
    if (!suite.costly_engines) {
      std::erase_if(swept, [](const EngineEntry* e) { return e->info.costly_runs; });
      std::erase_if(matched, [&](const EngineEntry* e) {
        return e->info.costly_runs && !contains(suite.match_costly_engines, e->info.name);
      });
    }
    Isolation isolation;
    isolation.timeout_s = suite.timeout_s;
    const TryStore store(a.store, a.fresh);
    // A part whose complete results are already there is reused (a report that stopped resumes).
    auto reuse = [&](const std::string& path, bool complete) {
      if (a.fresh || !complete) return false;
      progress_line("reusing {} (--fresh runs it again)\n", path);
      return true;
    };
    for (const std::string& name : suite.scenes) {
      if (!mine("table:" + name)) continue;
      const Scene scene = load_scene(name);
      const int seeds = scene.random_placement ? suite.seeds : 1;
      const std::string path = fmt::format("{}/{}.json", results_dir, name);
      if (reuse(path, complete_results(path, scene, engines, seeds))) continue;
      RunOptions options;
      // The error against `exact` (or a converged run) in every row, but for the heaps.
      if (!contains(suite.unreferenced, name))
        use_reference(options);
      // A scene marked `animated` (the thesis's): in the viewer and a GIF, as many frames as a page of every run holds.
      if (scene.animated)
        options.frames = viewer_frames(scene, static_cast<int>(run_count(engines, "all")));
      std::vector<Result> runs = run_all(scene, engines, "all", options, a.quiet, isolation);
      // Further placements, for the ensemble table: without frames (the animation and the viewer are of
      // offset 0).
      options.frames = 0;
      run_further_placements(runs, scene, seeds, [&](int k) { return load_scene(name, k); }, engines, "all", options,
                             a.quiet, isolation);
      write_results_file(path, runs);
      stop_if_interrupted();
      progress_line("ran {}\n", name);
    }
    for (const std::string& name : suite.match_scenes) {
      if (!mine("match:" + name)) continue;
      const std::string path = fmt::format("{}/match-{}.json", results_dir, name);
      if (reuse(path, uninterrupted(path, read_match_file))) continue;
      const Scene scene = load_scene(name);
      MatchOptions o;
      o.spec = scene_spec(scene);
      o.budget_runs = suite.match_budget;
      o.ceiling = suite.match_ceiling;
      o.max_halvings = suite.match_max_halvings;
      o.store = &store;
      o.jobs = std::max(1, int(std::thread::hardware_concurrency()));
      o.isolation = isolation;
      o.reference = reference_engine();
      o.converged_reference = converged_reference_engine();
      o.quiet = a.quiet;
      const MatchResult m = run_match(scene, matched, o, run_context());
      write_match_files(m, path, fmt::format("{}/match-{}.csv", results_dir, name));
      stop_if_interrupted();
      progress_line("matched {}\n", name);
    }
    for (const std::string& name : suite.sweep_scenes) {
      if (!mine("sweep:" + name)) continue;
      const std::string path = fmt::format("{}/sweep-{}.json", results_dir, name);
      if (reuse(path, uninterrupted(path, read_sweep_file))) continue;
      SweepOptions o;
      o.repeats = 5;
      o.quiet = a.quiet;
      o.reference = reference_engine();
      o.isolation = isolation;
      write_sweep_files(run_sweep(load_scene(name), swept, o, run_context()), path,
                        fmt::format("{}/sweep-{}.csv", results_dir, name));
      stop_if_interrupted();
      progress_line("swept {}\n", name);
    }
    for (const std::string& name : suite.stress_scenes) {
      if (!mine("stress:" + name)) continue;
      const std::string path = fmt::format("{}/stress-{}.json", results_dir, name);
      if (reuse(path, uninterrupted(path, read_frontier_file))) continue;
      const Scene scene = load_scene(name);
      StressOptions o;
      o.profile = "all";
      o.levels = suite.stress_levels;
      o.quiet = a.quiet;
      o.reference = reference_engine();
      o.isolation = isolation;
      if (scene.container.kind != ContainerKind::Box) std::erase(o.knobs, "count");
      write_frontier_file(path, run_frontier(scene, swept, o, run_context()));
      stop_if_interrupted();
      progress_line("stressed {}\n", name);
    }
    if (mine("calibration")) {
      const std::string path = results_dir + "/calibration.json";
      if (!reuse(path, fs::exists(path))) {
        CalibrationOptions o;
        o.isolation.timeout_s = suite.timeout_s;
        write_calibration_file(path, run_calibration(engines, o, run_context()));
        stop_if_interrupted();
        progress_line("calibrated restitution\n");
      }
    }
    const std::string bench_path = results_dir + "/bench.json", harness_path = results_dir + "/harness.json";
    if (a.no_bench) {
      fs::remove(bench_path), fs::remove(harness_path);
    } else if (mine("bench")) {
      const std::string bin = a.bench_binary.empty() ? default_bench_binary("ballbench_step_benchmark") : a.bench_binary;
      const auto also = [&](const std::vector<std::string>& lines) { left_out.insert(left_out.end(), lines.begin(), lines.end()); };
      if (!reuse(bench_path, fs::exists(bench_path)))
        also(run_bench(bin, suite.bench_filters, suite.bench_min_time, suite.bench_budget_s, bench_path, "scaling",
                       [](const BenchResults& b) { return !b.rows.empty() || !b.pipe.empty(); }));
      stop_if_interrupted();
      // The harness benchmark beside the step benchmark.
      if (!reuse(harness_path, fs::exists(harness_path)))
        also(run_bench((fs::path(bin).parent_path() / "ballbench_harness_benchmark").string(), {suite.harness_filter},
                       std::nullopt, suite.bench_budget_s, harness_path, "harness overhead",
                       [](const BenchResults& b) { return !b.harness.empty(); }));
      stop_if_interrupted();
    }
    nlohmann::json context = run_context();
    context["suite"] = suite.name;
    context["seeds"] = suite.seeds;
    context["engine_list"] = a.engines;
    context["scenes"] = suite.scenes;  // the report's order
    context["parts"] = parts;
    context["engines"] = nlohmann::json::object();  // name -> version: shards of one report agree
    for (const auto& e : engine_registry()) context["engines"][e.info.name] = e.info.version;
    if (!shard.all()) {
      context["shard"] = {{"index", shard.index}, {"count", shard.count}};
      nlohmann::json& ran = context["ran"] = nlohmann::json::array();
      for (size_t k = 0; k < parts.size(); ++k)
        if (shard.takes(k)) ran.push_back(parts[k]);
    }
    context["left_out"] = left_out;
    write_file_atomically(results_dir + "/run.json", context.dump(2) + "\n", "the run record");
  }
  if (!shard.all()) {
    std::vector<std::string> ran;
    for (size_t k = 0; k < parts.size(); ++k)
      if (shard.takes(k)) ran.push_back(parts[k]);
    fmt::print("shard {}/{}: {} in {} (join the shards' folders with `ballbench merge --out DIR FOLDER...`)\n",
               shard.index, shard.count, ran.empty() ? "no parts" : fmt::format("{}", fmt::join(ran, ", ")),
               results_dir);
    return;
  }
  render_report_folder(a.out);
}

}  // namespace

void add_report(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  auto* cmd = app.add_subcommand(
      "report", "run the standard comparison (tables, sweeps, stability frontiers, scaling) and write REPORT.md");
  cmd->add_option("--out", a->out, "folder for REPORT.md, figures/ and results/ (default: reports)");
  auto* quick = cmd->add_flag("--quick", a->quick, "the quick suite (the default): about 47 minutes on 2 cores, 36 with --no-bench");
  cmd->add_flag("--full", a->full, "the complete evidence: more scenes, equal-accuracy searches, sweeps and "
                                   "frontiers, every benchmark (hours)")
      ->excludes(quick);
  auto* render_only =
      cmd->add_flag("--render-only", a->render_only, "only rebuild REPORT.md from the results already in OUT/results");
  cmd->add_flag("--fresh", a->fresh,
                "run everything again, even what complete results in OUT/results and the results store already hold")
      ->excludes(render_only);
  cmd->add_option("--store", a->store,
                  "the equal-accuracy searches' results store, as `match --store` (\"\" for none)")
      ->excludes(render_only);
  auto* no_bench = cmd->add_flag("--no-bench", a->no_bench,
                                 "leave the benchmarks (and the scaling and harness overhead sections) out")
                       ->excludes(render_only);
  cmd->add_option("--bench-binary", a->bench_binary,
                  "the step benchmark to run (default: bench/ballbench_step_benchmark in this build); the "
                  "harness benchmark is taken from the same folder")
      ->excludes(render_only)
      ->excludes(no_bench);
  cmd->add_option("--engine", a->engines,
                  "the engines compared: comma-separated names, or all (the default); the benchmarks run every "
                  "engine of their binary")
      ->excludes(render_only);
  cmd->add_option("--seeds", a->seeds,
                  "random placements of each scene with random placement, for its ensemble table (default: 3 quick, "
                  "10 full)")
      ->check(kPositiveCount)
      ->excludes(render_only);
  cmd->add_option("--suites", a->suites,
                  "the suites file: what --quick and --full run (default: scenarios/suites/report.toml)")
      ->excludes(render_only);
  cmd->add_option("--shard", a->shard,
                  "run only shard I of N of the report's parts (I/N, e.g. 2/3; the benchmarks are one part), on one "
                  "machine each; `ballbench merge --out DIR FOLDER...` joins the shards' --out folders and renders "
                  "REPORT.md")
      ->excludes(render_only);
  add_quiet(cmd, a->quiet);
  cmd->callback([a] { report(*a); });
}

}  // namespace ballbench::cli

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

#include <fmt/format.h>

#include "commands.h"
#include "data_file.h"
#include "figures.h"
#include "bench_results.h"
#include "input_error.h"
#include "interrupt.h"
#include "registry.h"
#include "restitution_calibration.h"
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

// What a report runs. `quick` is what scripts/report runs (about 13 minutes on 2 cores, 9 of them
// the benchmarks); `full` is the complete evidence (tens of minutes).
struct Suite {
  std::vector<std::string> scenes;        // a comparison table each, every engine and profile
  std::vector<std::string> sweep_scenes;  // work against precision
  std::vector<std::string> stress_scenes; // stability frontier
  int stress_levels = 5;
  std::vector<std::string> bench_filters;  // Google Benchmark --benchmark_filter, one process each
  double bench_min_time = 0.05;           // s per benchmark
  double bench_budget_s = 10;             // s a benchmark may run before it stops as failed, with its figure
  std::string harness_filter;             // of bench/ballbench_harness_benchmark (its own minimum times)
  double timeout_s = 600;                 // per engine run
  int seeds = 1;                          // placements of each scene with random placement (ensemble.h)
  // Scenes whose tables run without a reference: heaps, chaotic from the first contacts (every
  // engine parts from any reference within half a second), measured by their final angle of
  // repose; their reference runs (exact, or Chipmunk at dt / 64) cost more than every engine's.
  std::vector<std::string> unreferenced = {"rough-pile", "smooth-pile"};
};

Suite quick_suite() {
  Suite s;
  // The seed scenes, and friction: a ball sliding to roll, a spinning ball dropped, rough spinning
  // balls in a box, and a heap with friction beside its frictionless twin (the report's friction
  // section).
  s.scenes = {"seed-box", "seed-bowl", "slide-to-roll", "spin-drop", "rough-box", "rough-pile", "smooth-pile"};
  s.seeds = 3;
  s.sweep_scenes = {"seed-box"};
  s.stress_scenes = {"seed-box"};
  s.stress_levels = 5;
  // Every engine up to 10^4 balls, ours to 10^6 as well; the 10^6 bowl alone in its own process,
  // for its peak memory, with the pour's first second (the same scene, built once).
  // The settled pile and the fluid to 10^4 balls.
  s.bench_filters = {
      "^step/[^/]+/[^/]+/(gas|bowl)/(10|100|1000|10000)(/|$)|^step/home/default/(gas/(100000|1000000)|bowl/100000)(/|$)",
      "^(step|pour)/home/default/bowl/1000000(/|$)", "^step/[^/]+/[^/]+/(settled|fluid)/(100|1000|10000)(/|$)",
      "^pipe/"};
  s.bench_min_time = 0.05;
  // Issue 6's measure: 10^5 balls, every step and every 10th, and the floor beside it.
  s.harness_filter = "^(harness|floor)/home/gas/100000/";
  s.timeout_s = 120;
  return s;
}

Suite full_suite() {
  Suite s;
  s.scenes = {"seed-box", "seed-bowl", "bullet", "newtons-cradle", "mass-ratio", "crowd", "gas", "pile", "slide-to-roll",
              "spin-drop", "rough-box", "rough-pile", "smooth-pile"};
  s.seeds = 10;
  s.sweep_scenes = {"seed-box", "seed-bowl"};
  s.stress_scenes = {"seed-box", "seed-bowl"};
  s.stress_levels = 6;
  // Everything registered: 10 .. 10^5 balls, 10^6 for ours (the 10^6 bowl in its own process);
  // the settled pile to 10^6 (settling 10^6 balls before timing takes a while) and the fluid to 10^5.
  s.bench_filters = {"^step/[^/]+/[^/]+/(gas|bowl)/(10|100|1000|10000|100000)(/|$)|^step/home/default/gas/1000000(/|$)",
                     "^(step|pour)/home/default/bowl/1000000(/|$)", "^step/[^/]+/[^/]+/(settled|fluid)/", "^pipe/"};
  s.bench_min_time = 0.2;
  s.bench_budget_s = 60;
  s.harness_filter = "^(harness|floor)/";
  s.timeout_s = 600;
  return s;
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
};

// The report's parts in run order, each a results file (or, for "bench", the step and harness
// benchmarks together, so their ratios come from one machine). A shard runs the parts it takes.
std::vector<std::string> report_parts(const Suite& suite, bool bench) {
  std::vector<std::string> parts;
  for (const auto& name : suite.scenes) parts.push_back("table:" + name);
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
// reported and left out, and the other filters' results stand.
void run_bench(const std::string& bin, const std::vector<std::string>& filters, std::optional<double> min_time,
               double budget_s, const std::string& path, const std::string& section,
               const std::function<bool(const BenchResults&)>& found) {
  if (bin.empty() || ::access(bin.c_str(), X_OK) != 0) {
    fmt::print(stderr, "{} skipped: no benchmark at {} (build with -DBALLBENCH_BENCH=ON)\n", section, bin);
    return;
  }
  fmt::print(stderr, "running {} for the {} section\n", bin, section);
  // One process per filter, so a filter that runs one benchmark alone (the 10^6 bowl) has its peak
  // resident set to itself.
  nlohmann::json joined;
  for (size_t k = 0; k < filters.size(); ++k) {
    const std::string& filter = filters[k];
    const std::string tmp = fmt::format("{}.running{}", path, k);
    const std::string cmd =
        fmt::format("'{}' --benchmark_filter='{}' {} --budget_s={} --benchmark_out='{}' --benchmark_out_format=json 1>&2",
                    bin, filter, min_time ? fmt::format("--benchmark_min_time={}", *min_time) : "", budget_s, tmp);
    const int rc = std::system(cmd.c_str());
    // std::system ignores SIGINT while it waits; a benchmark ended by the terminal's SIGINT (or a
    // SIGTERM) is this report's interrupt too, raised here so that interrupt.h sees it.
    const int sig = WIFSIGNALED(rc) ? WTERMSIG(rc) : WIFEXITED(rc) && WEXITSTATUS(rc) > 128 ? WEXITSTATUS(rc) - 128 : 0;
    if (sig == SIGINT || sig == SIGTERM || interrupt_signal()) {
      fs::remove(tmp);
      if (!interrupt_signal()) std::raise(sig);
      return;
    }
    std::string why = rc == 0            ? ""
                      : WIFEXITED(rc)    ? fmt::format("it failed (exit status {})", WEXITSTATUS(rc))
                      : WIFSIGNALED(rc)  ? fmt::format("it was killed by signal {}", WTERMSIG(rc))
                                         : fmt::format("it failed (wait status {})", rc);
    if (why.empty()) try {
        if (!found(read_bench_file(tmp))) why = "no benchmark matched " + filter;
      } catch (const InputError& e) {
        why = e.what();
      }
    if (!why.empty()) {  // this filter's part is left out; the others' stand
      fmt::print(stderr, "{}: part skipped: {} --benchmark_filter='{}': {}; its output is in {}\n", section, bin, filter,
                 why, tmp);
      continue;
    }
    const nlohmann::json part = parse_json_file(tmp, "Google Benchmark JSON");
    if (joined.is_null()) joined = part;
    else for (const auto& b : part.at("benchmarks")) joined["benchmarks"].push_back(b);
    fs::remove(tmp);
  }
  if (joined.is_null()) {
    fmt::print(stderr, "{} skipped: no part of it ran\n", section);
    return;
  }
  write_file_atomically(path, joined.dump(2) + "\n", "the benchmark results");
}

}  // namespace

void render_report_folder(const std::string& out) {
  ReportInputs inputs = read_report_inputs(out + "/results");
  inputs.roles = engine_roles();
  std::string md;
  try {
    md = render_report(inputs, draw_figures(inputs, out));
  } catch (const nlohmann::json::exception& e) {  // a field of run.json of another type than a report writes
    throw InputError(fmt::format("{}/results/run.json: not a report's run record: {}", out, e.what()));
  }
  write_file_atomically(out + "/REPORT.md", md, "the report");
  fmt::print("wrote {}/REPORT.md\n", out);
}

namespace {

void report(const ReportArgs& a) {
  if (!a.bench_binary.empty() && ::access(a.bench_binary.c_str(), X_OK) != 0)
    throw InputError(fmt::format("--bench-binary {}: not an executable file", a.bench_binary));
  const std::string results_dir = a.out + "/results";
  // Every place the report writes is checked before anything runs (a report takes minutes): an
  // --out that cannot hold them is one line, not an error from deep inside after the runs.
  for (const std::string& p : {a.out + "/REPORT.md", results_dir + "/run.json", a.out + "/figures/scaling.png"})
    check_writable(p, "the report's files", true);
  Suite suite = a.full ? full_suite() : quick_suite();
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
  install_interrupt_handlers();
  // Asked to stop: the part in progress is written (marked) and every finished part kept; a report
  // run again resumes from them. REPORT.md is only rendered from a report that ran to its end.
  auto stop_if_interrupted = [&] {
    exit_if_interrupted(fmt::format("the parts finished are in {} (a report run again resumes from them); {}/REPORT.md "
                                    "not rewritten",
                                    results_dir, a.out));
  };
  if (!a.render_only) {
    fs::create_directories(results_dir);
    // The quick suite's sweeps and frontiers leave out engines whose runs are costly: each of their
    // points is a run of its own, which starts the engine's process (a Node engine: 0.1 to 0.4 s) or
    // Open MPI and thousands of DEM sub-steps (LAMMPS), hundreds of times over; --full includes
    // them. Their scene tables, calibration and benchmarks are in both.
    std::vector<const EngineEntry*> swept = engines;
    if (!a.full) std::erase_if(swept, [](const EngineEntry* e) { return e->info.costly_runs; });
    Isolation isolation;
    isolation.timeout_s = suite.timeout_s;
    // A part whose complete results are already there is reused (a report that stopped resumes).
    auto reuse = [&](const std::string& path, bool complete) {
      if (a.fresh || !complete) return false;
      fmt::print(stderr, "reusing {} (--fresh runs it again)\n", path);
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
      if (std::find(suite.unreferenced.begin(), suite.unreferenced.end(), name) == suite.unreferenced.end())
        use_reference(options);
      // The thesis's scenes, animated and in the viewer: as many frames as a page of every run holds.
      if (scene.animated)
        options.frames = viewer_frames(scene, static_cast<int>(run_count(engines, "all")));
      std::vector<Result> runs = run_all(scene, engines, "all", options, false, isolation);
      // Further placements, for the ensemble table: without frames (the animation and the viewer are of
      // offset 0).
      options.frames = 0;
      run_further_placements(runs, scene, seeds, [&](int k) { return load_scene(name, k); }, engines, "all", options,
                             false, isolation);
      write_results_file(path, runs);
      stop_if_interrupted();
      fmt::print(stderr, "ran {}\n", name);
    }
    for (const std::string& name : suite.sweep_scenes) {
      if (!mine("sweep:" + name)) continue;
      const std::string path = fmt::format("{}/sweep-{}.json", results_dir, name);
      if (reuse(path, uninterrupted(path, read_sweep_file))) continue;
      SweepOptions o;
      o.repeats = 5;
      o.reference = reference_engine();
      o.isolation = isolation;
      write_sweep_files(run_sweep(load_scene(name), swept, o, run_context()), path,
                        fmt::format("{}/sweep-{}.csv", results_dir, name));
      stop_if_interrupted();
      fmt::print(stderr, "swept {}\n", name);
    }
    for (const std::string& name : suite.stress_scenes) {
      if (!mine("stress:" + name)) continue;
      const std::string path = fmt::format("{}/stress-{}.json", results_dir, name);
      if (reuse(path, uninterrupted(path, read_frontier_file))) continue;
      const Scene scene = load_scene(name);
      StressOptions o;
      o.profile = "all";
      o.levels = suite.stress_levels;
      o.reference = reference_engine();
      o.isolation = isolation;
      if (scene.container.kind != ContainerKind::Box) std::erase(o.knobs, "count");
      write_frontier_file(path, run_frontier(scene, swept, o, run_context()));
      stop_if_interrupted();
      fmt::print(stderr, "stressed {}\n", name);
    }
    if (mine("calibration")) {
      const std::string path = results_dir + "/calibration.json";
      if (!reuse(path, fs::exists(path))) {
        CalibrationOptions o;
        o.isolation.timeout_s = suite.timeout_s;
        write_calibration_file(path, run_calibration(engines, o, run_context()));
        stop_if_interrupted();
        fmt::print(stderr, "calibrated restitution\n");
      }
    }
    const std::string bench_path = results_dir + "/bench.json", harness_path = results_dir + "/harness.json";
    if (a.no_bench) {
      fs::remove(bench_path), fs::remove(harness_path);
    } else if (mine("bench")) {
      const std::string bin = a.bench_binary.empty() ? default_bench_binary("ballbench_step_benchmark") : a.bench_binary;
      if (!reuse(bench_path, fs::exists(bench_path)))
        run_bench(bin, suite.bench_filters, suite.bench_min_time, suite.bench_budget_s, bench_path, "scaling",
                  [](const BenchResults& b) { return !b.rows.empty() || !b.pipe.empty(); });
      stop_if_interrupted();
      // The harness benchmark beside the step benchmark.
      if (!reuse(harness_path, fs::exists(harness_path)))
        run_bench((fs::path(bin).parent_path() / "ballbench_harness_benchmark").string(), {suite.harness_filter},
                  std::nullopt, suite.bench_budget_s, harness_path, "harness overhead",
                  [](const BenchResults& b) { return !b.harness.empty(); });
      stop_if_interrupted();
    }
    nlohmann::json context = run_context();
    context["suite"] = a.full ? "full" : "quick";
    context["seeds"] = suite.seeds;
    context["engine_list"] = a.engines;
    context["scenes"] = suite.scenes;  // the report's order
    context["parts"] = parts;
    context["engines"] = nlohmann::json::object();  // name -> version: shards of one report agree
    for (const auto& e : engine_registry()) context["engines"][e.info.name] = e.info.version;
    if (!shard.all()) context["shard"] = {{"index", shard.index}, {"count", shard.count}};
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
  auto* quick = cmd->add_flag("--quick", a->quick, "the quick suite, about 13 minutes on 2 cores, 4 with --no-bench (the default)");
  cmd->add_flag("--full", a->full, "the complete evidence: more scenes, sweeps and frontiers, every benchmark "
                                   "(tens of minutes)")
      ->excludes(quick);
  auto* render_only =
      cmd->add_flag("--render-only", a->render_only, "only rebuild REPORT.md from the results already in OUT/results");
  cmd->add_flag("--fresh", a->fresh, "run everything again, even what complete results in OUT/results already hold")
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
  cmd->add_option("--shard", a->shard,
                  "run only shard I of N of the report's parts (I/N, e.g. 2/3; the benchmarks are one part), on one "
                  "machine each; `ballbench merge --out DIR FOLDER...` joins the shards' --out folders and renders "
                  "REPORT.md")
      ->excludes(render_only);
  cmd->callback([a] { report(*a); });
}

}  // namespace ballbench::cli

// `ballbench report`: run the standard comparison (core/report_part.h: scene tables, equal-accuracy
// searches, sweeps, stability frontiers, the closed-form checks, the calibration, the benchmarks),
// write the results and render REPORT.md with its pages and figures.
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
#include <set>

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
#include "report_part.h"
#include "report_runs.h"
#include "report_writer.h"
#include "run_engines.h"
#include "scene_digest.h"
#include "scene_loader.h"
#include "shard.h"
#include "stability_frontier.h"
#include "sweep.h"
#include "validators.h"
#include "viewer_page.h"

namespace ballbench::cli {
namespace {

namespace fs = std::filesystem;

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

// Writes the pages, REPORT.md last, and removes pages of an earlier report that this one does not have.
void write_pages(const std::string& out, const std::vector<ReportPage>& pages) {
  std::set<fs::path> written;
  for (auto it = pages.rbegin(); it != pages.rend(); ++it) {
    const fs::path path = fs::path(out) / it->path;
    fs::create_directories(path.parent_path());
    write_file_atomically(path.string(), it->text, "the report's page");
    written.insert(path);
  }
  std::error_code ec;
  for (const char* folder : {"pages", "scenes"})
    for (const auto& e : fs::directory_iterator(fs::path(out) / folder, ec))
      if (e.path().extension() == ".md" && !written.contains(e.path())) fs::remove(e.path(), ec);
}

}  // namespace

void render_report_folder(const std::string& out) {
  ReportInputs inputs = read_report_inputs(out + "/results");
  inputs.roles = engine_roles();
  std::vector<ReportPage> pages;
  try {
    pages = render_report(inputs, draw_figures(inputs, out));
  } catch (const nlohmann::json::exception& e) {  // a field of run.json of another type than a report writes
    // The run record's fields that rendering reads by type (the machine's are shown as they are).
    const JsonShape record{{{"command", ""}, {"date", ""}, {"suite", ""}, {"scenes", nlohmann::json::array({""})}}, ""};
    throw InputError(json_type_error(out + "/results/run.json", "a report's run record", e, inputs.run, &record));
  } catch (const std::exception&) {  // a figure's gnuplot ended by the signal that stops this process
    if (interrupt_signal()) exit_if_interrupted(fmt::format("{}/REPORT.md not rewritten", out));
    throw;
  }
  exit_if_interrupted(fmt::format("{}/REPORT.md not rewritten", out));
  write_pages(out, pages);
  fmt::print("wrote {}/REPORT.md and its {} pages\n", out, pages.size() - 1);
}

namespace {

// What the report reads (an engines file, the benchmark binaries, the suite's measured searches;
// with --render-only the results) lies outside what it writes and, with --fresh, empties:
// OUT/results, the rendered folders (kRenderedFolders) and OUT/REPORT.md.
void check_report_paths(const ReportArgs& a, const ReportSuite& suite) {
  std::vector<PathUse> uses = noted_input_files();
  if (!a.render_only)
    for (const MeasuredMatch& m : suite.measured_matches) uses.push_back({"the suite's measured_matches", m.path, false});
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
  for (const char* folder : kRenderedFolders) uses.push_back({"--out", a.out + "/" + folder, true, true});
  uses.push_back({"--out", a.out + "/REPORT.md", true});
  check_path_clashes(uses);
}

// What an earlier report left (a --full one has more parts) must not reach this one.
void clear_for_fresh(const ReportArgs& a) {
  std::error_code ec;
  std::vector<std::string> dirs = {a.out + "/results"};
  for (const char* folder : kRenderedFolders) dirs.push_back(a.out + "/" + folder);
  for (const std::string& dir : dirs)
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.is_regular_file()) fs::remove(e.path(), ec);
}

// The words of the parts this shard takes (every part for a report that is not sharded).
std::vector<std::string> words_of(const std::vector<ReportPart>& parts, const Shard& shard) {
  std::vector<std::string> words;
  for (size_t k = 0; k < parts.size(); ++k)
    if (shard.takes(k)) words.push_back(part_word(parts[k]));
  return words;
}

// Each part this shard takes, reused where an earlier report left it complete. Asked to stop: the
// part in progress is written (marked) and every finished part kept; a report run again resumes
// from them. REPORT.md is only rendered from a report that ran to its end.
void run_parts(const ReportArgs& a, const ReportRun& run, const std::vector<ReportPart>& parts, const Shard& shard) {
  for (size_t k = 0; k < parts.size(); ++k) {
    if (!shard.takes(k)) continue;
    if (!a.fresh && part_complete(run, parts[k])) {
      progress_line("reusing {}/{} (--fresh runs it again)\n", run.results_dir, part_file(parts[k]));
      continue;
    }
    run_part(run, parts[k]);
    exit_if_interrupted(fmt::format("the parts finished are in {} (a report run again resumes from them); "
                                    "{}/REPORT.md not rewritten",
                                    run.results_dir, a.out));
  }
}

// results/run.json: the machine, the suite, the parts and what the report left out.
void write_run_record(const ReportArgs& a, const ReportRun& run, const std::vector<ReportPart>& parts,
                      const Shard& shard) {
  nlohmann::json context = run_context();
  context["suite"] = run.suite.name;
  context["seeds"] = run.suite.seeds;
  context["engine_list"] = a.engines;
  context["scenes"] = run.suite.scenes;  // the report's order
  context["parts"] = words_of(parts, Shard{});
  context["scene_digests"] = nlohmann::json::object();  // each scene's content: shards of one report agree
  for (const ReportPart& p : parts)
    if (!p.scene.empty() && !context["scene_digests"].contains(p.scene))
      context["scene_digests"][p.scene] = scene_digest(load_scene(p.scene));
  context["engines"] = nlohmann::json::object();  // name -> version: shards of one report agree
  for (const auto& e : engine_registry()) context["engines"][e.info.name] = e.info.version;
  if (!shard.all()) {
    context["shard"] = {{"index", shard.index}, {"count", shard.count}};
    context["ran"] = words_of(parts, shard);
  }
  context["left_out"] = *run.left_out;
  write_file_atomically(run.results_dir + "/run.json", context.dump(2) + "\n", "the run record");
}

// Every place the report writes and reads is checked before anything runs (a report takes
// minutes): an --out that cannot hold them is one line, not an error from deep inside after the runs.
void check_before_running(const ReportArgs& a, const ReportSuite& suite) {
  if (!a.bench_binary.empty() && ::access(a.bench_binary.c_str(), X_OK) != 0)
    throw InputError(fmt::format("--bench-binary {}: not an executable file", a.bench_binary));
  for (const std::string& p : {a.out + "/REPORT.md", a.out + "/results/run.json", a.out + "/figures/scaling.png"})
    check_writable(p, "the report's files", true);
  check_report_paths(a, suite);
}

void report(const ReportArgs& a) {
  install_interrupt_handlers();  // first: a stop request during the handshakes too
  Progress::quiet = a.quiet;
  ReportSuite suite = load_report_suite(a.full ? "full" : "quick", a.suites);
  check_before_running(a, suite);
  const auto engines = parse_engine_list(a.engines);  // a bad name is an error before anything runs
  if (a.seeds > 0) suite.seeds = a.seeds;
  const Shard shard = a.shard.empty() ? Shard{} : parse_shard(a.shard);
  const std::vector<ReportPart> parts = report_parts(suite, !a.no_bench);
  if (a.fresh) clear_for_fresh(a);
  if (!a.render_only) {
    std::vector<std::string> left_out;  // said in the report (run.json's "left_out")
    if (a.no_bench)
      left_out.push_back("the scaling and harness overhead sections, and the pipe's cost: `--no-bench` ran no "
                         "benchmark");
    ReportRun run;
    run.suite = suite, run.results_dir = a.out + "/results";
    fs::create_directories(run.results_dir);
    if (a.no_bench) fs::remove(run.results_dir + "/bench.json"), fs::remove(run.results_dir + "/harness.json");
    const TryStore store(a.store, a.fresh);
    choose_engines(run, engines);
    run.isolation.timeout_s = suite.timeout_s;
    run.store = &store;
    run.bench_binary = a.bench_binary.empty() ? default_bench_binary("ballbench_step_benchmark") : a.bench_binary;
    run.quiet = a.quiet;
    run.left_out = &left_out;
    run_parts(a, run, parts, shard);
    write_run_record(a, run, parts, shard);
  }
  if (!shard.all()) {
    const auto ran = words_of(parts, shard);
    fmt::print("shard {}/{}: {} in {}/results (join the shards' folders with `ballbench merge --out DIR FOLDER...`)\n",
               shard.index, shard.count, ran.empty() ? "no parts" : fmt::format("{}", fmt::join(ran, ", ")), a.out);
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
  auto* quick = cmd->add_flag("--quick", a->quick, "the quick suite (the default): about 15 minutes on 2 cores, 12 with --no-bench");
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

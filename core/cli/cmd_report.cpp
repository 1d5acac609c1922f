// `ballbench report`: run the standard comparison, write the results and render REPORT.md.
#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "input_error.h"
#include "machine_info.h"
#include "figures.h"
#include "registry.h"
#include "report_writer.h"
#include "run_engines.h"
#include "scene_loader.h"

namespace ballbench::cli {
namespace {

struct ReportArgs {
  std::string out = "reports";
  bool render_only = false;
  bool fresh = false;
};

// A results file holding exactly the runs a report makes of `scene` (every engine x profile),
// left by an earlier report that stopped later on: reusing it resumes the report. Files are written
// whole (write_results_file), so one that reads back is complete.
bool complete_results(const std::string& path, const Scene& scene, const std::vector<const EngineEntry*>& engines) {
  if (!std::filesystem::exists(path)) return false;
  std::vector<Result> found;
  try {
    found = read_results_file(path);
  } catch (const InputError&) {
    return false;
  }
  std::vector<std::string> want, have;
  for (const auto* e : engines)
    for (const auto& p : profiles_for(*e, "all")) want.push_back(e->info.name + "/" + p);
  for (const auto& r : found) {
    if (r.scene != scene.name || r.steps != scene.steps() || r.n != scene.n()) return false;
    have.push_back(r.engine + "/" + r.profile);
  }
  std::sort(want.begin(), want.end()), std::sort(have.begin(), have.end());
  return want == have;
}

nlohmann::json run_context(const std::string& command) {
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
          {"command", command},
          {"date", date}};
}

void report(const ReportArgs& a) {
  const std::string results_dir = a.out + "/results";
  if (!a.render_only) {
    std::filesystem::create_directories(results_dir);
    const auto engines = parse_engine_list("all");
    bool ran = false;
    for (const std::string name : {"seed-box", "seed-bowl"}) {
      const Scene scene = load_scene(name);
      const std::string path = fmt::format("{}/{}.json", results_dir, name);
      if (!a.fresh && complete_results(path, scene, engines)) {
        fmt::print(stderr, "reusing {} (--fresh runs it again)\n", path);
        continue;
      }
      RunOptions options;
      options.reference = reference_engine();  // error against `exact` in every row
      write_results_file(path, run_all(scene, engines, "all", options, false));
      fmt::print(stderr, "ran {}\n", name);
      ran = true;
    }
    if (ran || !std::filesystem::exists(results_dir + "/run.json")) {
      nlohmann::json context = run_context("scripts/report");
      context["scenes"] = {"seed-box", "seed-bowl"};  // the report's order
      std::ofstream(results_dir + "/run.json") << context.dump(2) << '\n';
    }
  }
  const ReportInputs inputs = read_report_inputs(results_dir);
  const std::string md = render_report(inputs, draw_figures(inputs, a.out));
  const std::string path = a.out + "/REPORT.md";
  std::ofstream(path + ".tmp") << md;
  std::filesystem::rename(path + ".tmp", path);
  fmt::print("wrote {}\n", path);
}

}  // namespace

void add_report(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  auto* cmd = app.add_subcommand("report", "run the standard comparison and write REPORT.md");
  cmd->add_option("--out", a->out, "folder for REPORT.md and results/ (default: reports)");
  auto* render_only =
      cmd->add_flag("--render-only", a->render_only, "only rebuild REPORT.md from the results already in OUT/results");
  cmd->add_flag("--fresh", a->fresh, "run every scene again, even one whose complete results are already in OUT/results")
      ->excludes(render_only);
  cmd->callback([a] { report(*a); });
}

}  // namespace ballbench::cli

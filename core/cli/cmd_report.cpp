// `ballbench report`: run the standard comparison, write the results and render REPORT.md.
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "machine_info.h"
#include "registry.h"
#include "report_writer.h"
#include "run_engines.h"
#include "scene_loader.h"

namespace ballbench::cli {
namespace {

struct ReportArgs {
  std::string out = "reports";
  bool render_only = false;
};

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
    for (const std::string name : {"seed-box", "seed-bowl"}) {
      const Scene scene = load_scene(name);
      write_results_file(fmt::format("{}/{}.json", results_dir, name),
                         run_all(scene, parse_engine_list("all"), "all", RunOptions{}, false));
      fmt::print(stderr, "ran {}\n", name);
    }
    std::ofstream(results_dir + "/run.json") << run_context("scripts/report").dump(2) << '\n';
  }
  const std::string md = render_report(read_report_inputs(results_dir));
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
  cmd->add_flag("--render-only", a->render_only, "only rebuild REPORT.md from the results already in OUT/results");
  cmd->callback([a] { report(*a); });
}

}  // namespace ballbench::cli

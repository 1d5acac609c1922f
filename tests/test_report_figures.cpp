// The report's figures and glossary from results made by hand: what a reader is told of a run that
// stopped, and each unit once.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "figures.h"
#include "report_text.h"
#include "report_writer.h"
#include "viewer_page.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

Result energy_run(const std::string& engine, RunStatus status, long steps_done, long diverged_step) {
  Result r;
  r.engine = engine, r.profile = "default", r.engine_version = "1", r.scene = "s", r.n = 1, r.dt = 0.01;
  r.steps = 300, r.steps_done = steps_done, r.status = status, r.diverged_step = diverged_step;
  for (long k = 0; k <= steps_done; k += 50) r.series.t.push_back(k * r.dt), r.series.energy.push_back(1.0);
  r.metrics.set(Metric::energy_initial, 1.0);
  return r;
}

// A run that stopped says when in the energy figure's key, its line ending there: the step it
// diverged at (1.2 s), not its last sample's time (1.0 s); a run that ended ok is its name alone.
TEST(ReportFigures, TheEnergyKeySaysWhenARunStopped) {
  ReportInputs in;
  in.results = {energy_run("kept", RunStatus::ok, 300, -1), energy_run("lost", RunStatus::diverged, 119, 120),
                energy_run("broke", RunStatus::failed, 80, -1)};
  EXPECT_DOUBLE_EQ(stop_time(in.results[1]), 1.2);
  EXPECT_DOUBLE_EQ(stop_time(in.results[2]), 0.8);
  const fs::path dir = fs::temp_directory_path() / ("ballbench_figures." + std::to_string(::getpid()));
  const std::vector<Figure> figures = draw_figures(in, dir.string());
  std::ifstream gp(dir / "figures" / "s-energy.gp");
  std::stringstream text;
  text << gp.rdbuf();
  const std::string script = text.str();
  for (const char* title : {"title 'kept'", "title 'lost (diverged at 1.2 s)'", "title 'broke (failed at 0.8 s)'"})
    EXPECT_NE(script.find(title), std::string::npos) << title << "\n" << script;
  ASSERT_FALSE(figures.empty());
  EXPECT_NE(figures.front().caption.find("a run that stopped early says when in the key"), std::string::npos)
      << figures.front().caption;
  fs::remove_all(dir);
}

// A column whose header carries its unit ("slip at end (m/s)") is not given it twice.
TEST(ReportFigures, TheGlossaryGivesEachUnitOnce) {
  ReportInputs in;
  in.run = nlohmann::json::object();  // results/run.json, here with nothing in it
  const std::string md = all_pages(render_report(in));
  for (const char* once : {"- **slip at end (m/s)**: ", "- **time to roll (s)**: ", "- **angle of repose (deg)**: "})
    EXPECT_NE(md.find(once), std::string::npos) << once << "\n" << md.substr(md.find("## Table columns"));
  for (const char* twice : {"(m/s)** (m/s)", "(s)** (s)", "(deg)** (deg)"})
    EXPECT_EQ(md.find(twice), std::string::npos) << twice;
  EXPECT_NE(md.find("- **momentum drift (max abs)** (kg m/s): "), std::string::npos) << "a unit not in the header stays";
}

}  // namespace
}  // namespace ballbench

// `ballbench sweep`: the points it plans, what it writes (JSON, CSV), the Pareto front it marks,
// and its errors for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "cli_runner.h"
#include "input_error.h"
#include "registry.h"
#include "scene_loader.h"
#include "sweep.h"
#include "sweep_result.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;

SweepPoint point(const std::string& engine, double seconds, double error) {
  SweepPoint p;
  p.engine = engine, p.profile = "default", p.knob = "dt";
  p.engine_s = {seconds}, p.pos_rms = error;
  return p;
}

TEST(SweepPareto, KeepsThePointsNoOtherBeatsInBothTimeAndError) {
  std::vector<SweepPoint> ps{point("a", 1, 5), point("a", 2, 3), point("a", 3, 4), point("a", 4, 1),
                             point("b", 10, 10), point("a", 0.5, 6)};
  ps.push_back(point("a", 0.1, 0.5));
  ps.back().status = "diverged";  // a failed run is on no front, however fast
  mark_pareto(ps);
  const std::vector<bool> want{true, true, false, true, true, true, false};
  for (size_t k = 0; k < ps.size(); ++k) EXPECT_EQ(ps[k].pareto, want[k]) << k;
}

TEST(SweepPareto, MedianOfEvenAndOddCounts) {
  EXPECT_EQ(median({3, 1, 2}), 2);
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_TRUE(std::isnan(median({})));
}

TEST(SweepPlan, StepSizesForEveryEngineThenEachKnobValueTheProfileLacks) {
  const Scene scene = load_scene("seed-box");
  cli::SweepOptions o;
  o.reference = reference_engine();
  o.horizon = 0.2;
  const auto plan = cli::plan_sweep(scene, parse_engine_list("all"), o);
  std::map<std::string, int> dt_points;
  for (const auto& item : plan) {
    const std::string label = item.engine->info.name + "/" + item.profile;
    if (item.knob == "dt") {
      ++dt_points[label];
      EXPECT_NEAR(item.steps * item.dt, 0.2, 1e-12) << label;
    } else {
      EXPECT_EQ(item.dt, scene.dt) << label;
      EXPECT_EQ(item.overrides.size(), 1u) << label;
      // A knob value equal to the profile's own would repeat the dt series' point.
      const auto settings = item.engine->create(scene, item.profile, {})->settings();
      EXPECT_NE(settings[item.knob], item.value) << label << " " << item.knob;
    }
  }
  for (const auto& e : engine_registry())
    for (const auto& p : e.info.profiles) EXPECT_EQ(dt_points[e.info.name + "/" + p], 4) << e.info.name << "/" << p;
  // Bullet's profiles differ in CCD: each sweeps the other setting.
  int ccd = 0;
  for (const auto& item : plan) ccd += item.engine->info.name == "bullet" && item.knob == "ccd_motion_threshold";
  EXPECT_EQ(ccd, 2);
}

TEST(SweepPlan, AHorizonThatIsNoWholeNumberOfStepsIsAnError) {
  const Scene scene = load_scene("seed-box");
  cli::SweepOptions o;
  o.reference = reference_engine();
  o.horizon = 0.013;
  EXPECT_THROW(cli::plan_sweep(scene, parse_engine_list("home"), o), InputError);
}

class SweepCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("bb_sweep." + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SweepCli, WritesJsonAndCsvAndPrintsEachEnginesFront) {
  const std::string json = (dir_ / "s.json").string();
  const auto o = run_cli("sweep --scene seed-box --engine home,box2d --horizon 0.2 --repeats 2 --quiet --json " + json);
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("Pareto fronts on seed-box"), std::string::npos) << o.out;
  const SweepResult s = read_sweep_file(json);
  EXPECT_EQ(s.scene, "seed-box");
  EXPECT_EQ(s.reference, "exact");
  EXPECT_EQ(s.horizon, 0.2);
  int fronts_home = 0, fronts_box2d = 0;
  for (const SweepPoint& p : s.points) {
    ASSERT_EQ(p.status, "ok") << p.engine << " " << p.knob;
    EXPECT_EQ(p.engine_s.size(), 2u);
    EXPECT_EQ(p.ns_per_ball_step.size(), 2u);
    EXPECT_GT(p.pos_rms, 0);  // nobody tracks a chaotic 20-ball gas to round-off for 0.2 s
    EXPECT_FALSE(p.settings.empty());
    fronts_home += p.pareto && p.engine == "home";
    fronts_box2d += p.pareto && p.engine == "box2d";
  }
  EXPECT_GE(fronts_home, 1);
  EXPECT_GE(fronts_box2d, 1);
  // The CSV: a header and one row per point.
  const std::string csv = testing::slurp((dir_ / "s.csv").string());
  EXPECT_EQ(csv.rfind("engine,profile,knob,value,dt,steps,status,ns_per_ball_step_median", 0), 0u) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), static_cast<long>(s.points.size()) + 1);
}

TEST_F(SweepCli, BadInputIsOneLineAndStatus2) {
  for (const std::string args : {"--engine nosuch --horizon 0.2", "--engine home --horizon 0.013",
                                 "--engine home --repeats 0", "--engine home --dt-factors 1,-1"}) {
    const auto o = run_cli("sweep --scene seed-box --quiet --json " + (dir_ / "x.json").string() + " " + args);
    EXPECT_EQ(o.status, 2) << args << ": " << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << args << ": " << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.json")) << args;
  }
  // Outputs are checked before the sweep runs.
  const std::string same = (dir_ / "same.out").string();
  for (const std::string& args : {std::string("--json /proc/no/such/s.json"), "--json " + same + " --csv " + same}) {
    const auto o = run_cli("sweep --scene seed-box --engine home --horizon 0.2 --quiet " + args);
    EXPECT_EQ(o.status, 2) << args << ": " << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << args << ": " << o.err;
  }
  const auto stress = run_cli("stress --scene seed-box --engine home --levels 1 --steps 10 --json /proc/no/such/f.json");
  EXPECT_EQ(stress.status, 2) << stress.err;
  EXPECT_NE(stress.err.find("cannot write the frontiers there"), std::string::npos) << stress.err;
}

}  // namespace
}  // namespace ballbench

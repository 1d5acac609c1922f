// `ballbench sweep`: the points it plans, what it writes (JSON, CSV), the Pareto front it marks,
// and its errors for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <tuple>

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
  ps.back().status = RunStatus::diverged;  // a failed run is on no front, however fast
  mark_pareto(ps);
  const std::vector<bool> want{true, true, false, true, true, true, false};
  for (size_t k = 0; k < ps.size(); ++k) EXPECT_EQ(ps[k].pareto, want[k]) << k;
}

TEST(SweepFiles, APointNotMeasuredHasNullErrorsAndCountsAndEmptyCells) {
  SweepResult s;
  s.scene = "box";
  SweepPoint p;
  p.engine = "lazy", p.profile = "default", p.knob = "dt", p.value = 0.01, p.dt = 0.01;
  p.status = RunStatus::unsupported, p.measured = false;
  s.points = {p};
  const nlohmann::json j = to_json(s);
  for (const char* key : {"pos_rms", "vel_rms", "energy_rel", "tunnelling", "sticking"})
    EXPECT_TRUE(j["points"][0][key].is_null()) << key;
  EXPECT_FALSE(sweep_from_json(j).points[0].measured);
  EXPECT_NE(sweep_csv(s).find("unsupported,nan,nan,nan,nan,,,,,,0\n"), std::string::npos) << sweep_csv(s);
}

// Two settings whose timing repeats overlap are equally fast: the front keeps both, whichever
// median is lower; one faster beyond the noise and as accurate beats the other.
TEST(SweepPareto, RanksTimingsOnlyBeyondTheNoise) {
  const auto timed = [](double err, std::vector<double> times) {
    SweepPoint p;
    p.engine = "a", p.profile = "default", p.pos_rms = err, p.engine_s = std::move(times);
    return p;
  };
  std::vector<SweepPoint> ps = {timed(0.10, {1.0, 1.2, 1.4}),   // kept
                                timed(0.10, {1.1, 1.3, 1.5}),   // as accurate, slower median within the noise: kept
                                timed(0.20, {0.5, 0.6, 0.7}),   // less accurate, faster beyond the noise: kept
                                timed(0.15, {1.0, 1.1, 1.2}),   // less accurate, faster only within the noise: beaten
                                timed(0.20, {2.0, 2.1, 2.2})};  // less accurate and slower beyond the noise: beaten
  mark_pareto(ps);
  EXPECT_TRUE(ps[0].pareto);
  EXPECT_TRUE(ps[1].pareto);
  EXPECT_TRUE(ps[2].pareto);
  EXPECT_FALSE(ps[3].pareto);
  EXPECT_FALSE(ps[4].pareto);
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
      nlohmann::json settings;
      try {
        settings = item.engine->create(scene, item.profile, {})->settings();
      } catch (const SceneUnsupported&) {  // refused here (lammps: its sub-step cap), so every value is planned
        continue;
      }
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
    if (p.engine == "home" && p.profile == "soft") {  // home's soft profile refuses a scene without gravity
      EXPECT_EQ(p.status, RunStatus::unsupported) << p.knob;
      EXPECT_TRUE(p.engine_s.empty()) << p.knob;  // a refused point is not timed
      continue;
    }
    ASSERT_EQ(p.status, RunStatus::ok) << p.engine << " " << p.knob;
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

// Three shards of a sweep, each run apart and written to its own file, merged: the points of the
// unsharded sweep, in its order, equal in everything but timing (and the Pareto marks, which
// follow the timing).
TEST_F(SweepCli, ThreeShardsMergedEqualTheWholeSweepButForTiming) {
  const std::string common = "sweep --scene seed-box --engine home,box2d --horizon 0.2 --repeats 1 --quiet --json ";
  const std::string whole = (dir_ / "whole.json").string();
  ASSERT_EQ(run_cli(common + whole).status, 0);
  std::vector<std::string> shards;
  for (int i = 3; i >= 1; --i) {  // any order
    shards.push_back((dir_ / ("shard" + std::to_string(i) + ".json")).string());
    const auto o = run_cli(common + shards.back() + " --shard " + std::to_string(i) + "/3");
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(o.out.find("Pareto fronts"), std::string::npos) << "a shard's fronts are partial: " << o.out;
  }
  const std::string merged = (dir_ / "merged.json").string();
  const auto o = run_cli("merge --out " + merged + " " + shards[0] + " " + shards[1] + " " + shards[2]);
  ASSERT_EQ(o.status, 0) << o.err;
  const SweepResult a = read_sweep_file(whole), b = read_sweep_file(merged);
  EXPECT_EQ(a.plan, b.plan);
  EXPECT_EQ(b.shard_count, 1);
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_GE(a.points.size(), 8u);
  for (size_t k = 0; k < a.points.size(); ++k) {
    const SweepPoint &p = a.points[k], &q = b.points[k];
    const std::string where = p.engine + "/" + p.profile + " " + p.knob + " " + p.value.dump();
    EXPECT_EQ(q.plan_index, static_cast<long>(k)) << where;
    EXPECT_EQ(std::tie(p.engine, p.profile, p.knob, p.value, p.dt, p.steps, p.settings, p.status, p.error),
              std::tie(q.engine, q.profile, q.knob, q.value, q.dt, q.steps, q.settings, q.status, q.error))
        << where;
    // A point not measured (refused) has no figures in either: null, read back as NaN.
    EXPECT_EQ(p.measured, q.measured) << where;
    if (p.measured)
      EXPECT_EQ(std::tie(p.pos_rms, p.vel_rms, p.energy_rel, p.tunnelling, p.sticking),
                std::tie(q.pos_rms, q.vel_rms, q.energy_rel, q.tunnelling, q.sticking))
          << where;
    else
      EXPECT_TRUE(std::isnan(p.pos_rms) && std::isnan(q.pos_rms)) << where;
    EXPECT_EQ(q.engine_s.size(), q.status == RunStatus::ok ? 1u : 0u) << where;  // a refused point is not timed
  }
  EXPECT_TRUE(fs::exists(dir_ / "merged.csv"));
}

// Shards that do not make one sweep are refused in one line naming the file.
TEST_F(SweepCli, MergeRefusesShardsOfDifferentPlansRepeatsAndGaps) {
  const std::string common = "sweep --scene seed-box --horizon 0.2 --repeats 1 --no-knobs --dt-factors 1 --quiet ";
  const auto shard = [&](const std::string& name, const std::string& engines, const std::string& which) {
    const std::string path = (dir_ / name).string();
    const auto o = run_cli(common + "--engine " + engines + " --json " + path + " --shard " + which);
    EXPECT_EQ(o.status, 0) << o.err;
    return path;
  };
  const std::string one = shard("a1.json", "home,exact", "1/2"), two = shard("a2.json", "home,exact", "2/2");
  const std::string other = shard("b2.json", "home,box2d", "2/2");
  const std::string out = (dir_ / "m.json").string();
  const std::vector<std::pair<std::string, std::string>> cases{
      {one + " " + other, "is a shard of another sweep"},
      {one + " " + one, "are both shard 1/2"},
      {one, "shard 2/2 is missing"},
      {one + " " + (dir_ / "nosuch.json").string(), "no such file"},
  };
  for (const auto& [args, want] : cases) {
    const auto o = run_cli("merge --out " + out + " " + args);
    EXPECT_EQ(o.status, 2) << args << ": " << o.err;
    EXPECT_NE(o.err.find(want), std::string::npos) << args << ": " << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  EXPECT_EQ(run_cli("merge --out " + out + " " + two + " " + one).status, 0);
  fs::remove(out), fs::remove(sweep_csv_path(out));
  // A shard of the scene's other contents (same name, another restitution), one that lost a point,
  // and one of another build: each one line, nothing written.
  fs::create_directories(dir_ / "edited");
  std::string scene = testing::slurp(std::string(BALLBENCH_SOURCE_DIR) + "/scenarios/seed-box.toml");
  scene.replace(scene.find("restitution = 0.99"), 18, "restitution = 0.98");
  std::ofstream(dir_ / "edited" / "seed-box.toml") << scene;
  const std::string edited = (dir_ / "e2.json").string();
  std::string edited_common = common;
  edited_common.replace(edited_common.find("seed-box"), 8, (dir_ / "edited" / "seed-box.toml").string());
  const auto e = run_cli(edited_common + "--engine home,exact --json " + edited + " --shard 2/2");
  ASSERT_EQ(e.status, 0) << e.err;
  const auto edit = [&](const std::string& name, const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json j = nlohmann::json::parse(testing::slurp(two));
    change(j);
    std::ofstream((dir_ / name).string()) << j.dump(2);
    return (dir_ / name).string();
  };
  const std::string gap = edit("gap.json", [](nlohmann::json& j) { j["points"].erase(0); });
  const std::string built = edit("built.json", [](nlohmann::json& j) { j["context"]["build"] = "0123456789abcdef"; });
  for (const auto& [args, want] : std::vector<std::pair<std::string, std::string>>{
           {one + " " + edited, "is a shard of another sweep"},
           {one + " " + gap, "no shard holds the planned point 1"},
           {one + " " + built, "was made by build 0123456789abcdef"}}) {
    const auto o = run_cli("merge --out " + out + " " + args);
    EXPECT_EQ(o.status, 2) << args << ": " << o.err;
    EXPECT_NE(o.err.find(want), std::string::npos) << args << ": " << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  for (const std::string bad : {"0/2", "3/2", "1/0", "a/b", "1/2x", "1"}) {
    const auto o = run_cli(common + "--engine home --json " + (dir_ / "x.json").string() + " --shard " + bad);
    EXPECT_EQ(o.status, 2) << bad << ": " << o.err;
    EXPECT_NE(o.err.find("expected I/N"), std::string::npos) << bad << ": " << o.err;
  }
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

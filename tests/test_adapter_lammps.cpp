// The LAMMPS adapter: effective restitution measured from read-back states for both contact laws,
// the largest overlap against its target, energy in an elastic box, the sub-step cap, settings
// errors, and 2 MPI ranks against the library in this process.
#include <gtest/gtest.h>

#if BALLBENCH_HAS_LAMMPS

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "adapter_calibration.h"
#include "input_error.h"
#include "lammps/contact_model.h"
#include "lammps/lammps_engine.h"
#include "registry.h"
#include "runner.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

using calibration::Calibration;
using calibration::calibration_name;

State run(const Scene& s, const std::string& profile, int steps, const nlohmann::json& overrides = {}) {
  return calibration::run_steps("lammps", s, profile, steps, overrides);
}

// Two equal balls (r 0.1, m 1) head-on at +-2.5 m/s in open space: the design case of the pair
// contact (two of the heaviest balls, each at the scene's largest speed), contact at t = 0.06 s.
Scene equal_head_on(double e, double dt = 0.01, double gap = 0.3) {
  return parse_scene(fmt::format(R"(
dt = {}
duration = 1.0
restitution = {}
[[ball]]
pos = [{}, 0.0]
vel = [2.5, 0.0]
radius = 0.1
[[ball]]
pos = [{}, 0.0]
vel = [-2.5, 0.0]
radius = 0.1
)",
                                 dt, e, -0.1 - gap / 2, 0.1 + gap / 2),
                     "equal-head-on.toml");
}

// Velocity Verlet at a DEM step of t_c / 50 or less meets the contact's start and end within a
// step, and integrates the damped oscillation to O((pi / 50)^2): the measured restitution sits
// within 1% of the law's. Hertz's damping is fitted at the design speed, which both scenes use.
constexpr double kRestitutionTol = 0.01;

class LammpsCalibration : public ::testing::TestWithParam<Calibration> {};

TEST_P(LammpsCalibration, BallWallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = calibration::wall_scene(e, 5.0);  // at the wall t = 0.18 s, back by t = 0.4 s
  const State st = run(s, profile, 40);
  const double measured = -st.vel(0, 0) / s.initial.vel(0, 0);
  RecordProperty("effective_restitution", fmt::format("{:.6g}", measured));
  std::printf("lammps/%s ball-wall e = %g: measured %.6g\n", profile.c_str(), e, measured);
  EXPECT_NEAR(measured, e, kRestitutionTol);
  EXPECT_EQ(st.vel(0, 1), 0.0);
}

TEST_P(LammpsCalibration, BallBallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = equal_head_on(e);
  const State st = run(s, profile, 20);
  const double measured = (st.vel(1, 0) - st.vel(0, 0)) / 5.0;
  RecordProperty("effective_restitution", fmt::format("{:.6g}", measured));
  std::printf("lammps/%s ball-ball e = %g: measured %.6g\n", profile.c_str(), e, measured);
  EXPECT_NEAR(measured, e, kRestitutionTol);
  EXPECT_NEAR(st.vel(0, 0) + st.vel(1, 0), 0.0, 1e-12);  // momentum: pairwise forces, equal masses
}

INSTANTIATE_TEST_SUITE_P(Profiles, LammpsCalibration,
                         ::testing::Values(Calibration{"hooke", 0.8}, Calibration{"hooke", 1.0},
                                           Calibration{"hertz", 0.8}, Calibration{"hertz", 1.0}),
                         calibration_name);

// The stiffness puts the undamped design contact's deepest overlap at the target: read every DEM
// step (dt = the DEM step), an elastic head-on contact at the design speed reaches it to within the
// step's resolution. Velocity Verlet's discrete oscillator peaks above the continuous one by about
// (w dt)^2 / 8 = (pi / 50)^2 / 8 = 4.9e-4 of the amplitude at dt = t_c / 50 (measured: 1.8e-4
// hooke, 2.0e-4 hertz), so the bound is the target plus 1e-3 of it.
TEST(LammpsAdapter, LargestOverlapIsTheTarget) {
  for (const char* profile : {"hooke", "hertz"}) {
    const Scene probe = equal_head_on(1.0);
    const auto plan_dt = find_engine("lammps").create(probe, profile, {})->settings()["derived"]["dem_dt"].get<double>();
    const Scene s = equal_head_on(1.0, plan_dt, 0.001);
    auto e = find_engine("lammps").create(s, profile, {});
    ASSERT_EQ(e->settings()["derived"]["substeps"], 1) << profile;
    double deepest = 0;
    State st;
    for (int k = 0; k < 400; ++k) {
      e->step(s.dt);
      e->read(st);
      deepest = std::max(deepest, 0.2 - (st.pos(1, 0) - st.pos(0, 0)));
    }
    const double target = 0.005 * 0.1;
    std::printf("lammps/%s deepest overlap %.6g of target %.6g\n", profile, deepest, target);
    EXPECT_LE(deepest, target * (1 + 1e-3)) << profile;
    EXPECT_GE(deepest, target * 0.99) << profile;  // a DEM step moves the pair 0.5% of the target
  }
}

// An elastic gas in a box keeps its energy: velocity Verlet's error over a contact of 50 steps.
TEST(LammpsAdapter, ElasticBoxKeepsItsEnergy) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 0.5
restitution = 1.0
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[random]
count = 12
radius = 0.1
mass = 1.0
pos_min = [-0.8, -0.8]
pos_max = [0.8, 0.8]
vel_min = [-1.0, -1.0]
vel_max = [1.0, 1.0]
seed = 3
)",
                              "elastic-box.toml");
  for (const char* profile : {"hooke", "hertz"}) {
    RunOptions o;
    o.profile = profile;
    const Result r = run_engine(s, find_engine("lammps"), o);
    ASSERT_EQ(r.status, "ok") << r.error;
    ASSERT_TRUE(r.metrics.energy.max_rel_drift);
    const double drift = std::abs(r.metrics.energy.final - r.metrics.energy.initial) / r.metrics.energy.initial;
    std::printf("lammps/%s elastic box: final energy drift %.3g, max over samples %.3g, wall tunnelling %d\n", profile,
                drift, *r.metrics.energy.max_rel_drift, r.metrics.tunnelling_wall);
    EXPECT_LT(drift, 1e-4) << profile;
  }
}

TEST(LammpsAdapter, SceneBeyondTheSubStepCapIsUnsupported) {
  const Scene s = load_scene("seed-box");
  try {
    find_engine("lammps").create(s, "hooke", {});
    ADD_FAILURE() << "seed-box was accepted under the default cap";
  } catch (const SceneUnsupported& e) {
    EXPECT_NE(std::string(e.what()).find("DEM sub-steps per step"), std::string::npos) << e.what();
  }
  RunOptions o;
  o.profile = "hooke";
  const Result r = run_engine(s, find_engine("lammps"), o);
  EXPECT_EQ(r.status, "unsupported");
  EXPECT_NE(r.error.find("above max_substeps = 5000"), std::string::npos) << r.error;
}

TEST(LammpsAdapter, BadSettingsAreInputErrors) {
  const Scene s = equal_head_on(0.8);
  const auto& lammps = find_engine("lammps");
  const auto message = [&](const nlohmann::json& overrides) -> std::string {
    try {
      lammps.create(s, "hooke", overrides);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_NE(message({{"overlap", 0.01}}).find("settings.lammps.overlap: unknown setting"), std::string::npos);
  EXPECT_NE(message({{"ranks", "two"}}).find("expected a whole number"), std::string::npos);
  EXPECT_EQ(message({{"ranks", 0}}), "settings.lammps.ranks: must be >= 1 (1: in this process)");
  EXPECT_NE(message({{"overlap_target", 0.0}}).find("must be above 0"), std::string::npos);
  EXPECT_NE(message({{"hostfile", "/nonexistent"}, {"ranks", 2}}).find("is not a file"), std::string::npos);
  EXPECT_NE(message({{"hostfile", "/etc/hostname"}}).find("used only with ranks > 1"), std::string::npos);
  EXPECT_NE(message({{"hostfile", 3}}).find("expected a string"), std::string::npos);
  try {
    lammps.create(s, "x", {});
    ADD_FAILURE() << "an unknown profile was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "lammps: unknown profile 'x' (known: hooke, hertz)");
  }
}

}  // namespace
}  // namespace ballbench

#endif  // BALLBENCH_HAS_LAMMPS

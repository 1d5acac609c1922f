// The LAMMPS adapter: effective restitution measured from read-back states for both contact laws,
// the largest overlap against its target, energy in an elastic box, the sub-step cap, settings
// errors, 2 MPI ranks against the library in this process, and rotation: the scene's moment of
// inertia (a sliding ball rolls on at its speed), spins kept and their angle integrated.
#include <gtest/gtest.h>

#if BALLBENCH_HAS_LAMMPS

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

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

State run_lammps(const Scene& s, const std::string& profile, int steps, const nlohmann::json& overrides = {}) {
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

// `count` balls of `radius` (mass 1) in a 2 m box, placed at random with speeds up to `speed` per
// axis; restitution `e`, gravity `g` along y, `duration` at dt 0.01.
Scene gas_in_box(double e, double g, int count, double radius, double speed, int seed, double duration) {
  return parse_scene(fmt::format(R"(
dt = 0.01
duration = {}
restitution = {}
gravity = [0.0, {}]
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[random]
count = {}
radius = {}
mass = 1.0
pos_min = [-0.85, -0.85]
pos_max = [0.85, 0.85]
vel_min = [{}, {}]
vel_max = [{}, {}]
seed = {}
)",
                                 duration, e, g, count, radius, -speed, -speed, speed, speed, seed),
                     "gas-in-box.toml");
}

// Velocity Verlet at a DEM step of t_c / 50 or less meets the contact's start and end within a
// step, and integrates the damped oscillation to O((pi / 50)^2): the measured restitution sits
// within 1% of the law's. Hertz's damping is fitted at the design speed, which both scenes use.
constexpr double kLammpsRestitutionTol = 0.01;

class LammpsCalibration : public ::testing::TestWithParam<Calibration> {};

TEST_P(LammpsCalibration, BallWallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = calibration::wall_scene(e, 5.0);  // at the wall t = 0.18 s, back by t = 0.4 s
  const State st = run_lammps(s, profile, 40);
  const double measured = -st.vel(0, 0) / s.initial.vel(0, 0);
  RecordProperty("effective_restitution", fmt::format("{:.6g}", measured));
  std::printf("lammps/%s ball-wall e = %g: measured %.6g\n", profile.c_str(), e, measured);
  EXPECT_NEAR(measured, e, kLammpsRestitutionTol);
  EXPECT_EQ(st.vel(0, 1), 0.0);
}

TEST_P(LammpsCalibration, BallBallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = equal_head_on(e);
  const State st = run_lammps(s, profile, 20);
  const double measured = (st.vel(1, 0) - st.vel(0, 0)) / 5.0;
  RecordProperty("effective_restitution", fmt::format("{:.6g}", measured));
  std::printf("lammps/%s ball-ball e = %g: measured %.6g\n", profile.c_str(), e, measured);
  EXPECT_NEAR(measured, e, kLammpsRestitutionTol);
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
  const Scene s = gas_in_box(1.0, 0.0, 12, 0.1, 1.0, 3, 0.5);
  for (const char* profile : {"hooke", "hertz"}) {
    RunOptions o;
    o.profile = profile;
    const Result r = run_engine(s, find_engine("lammps"), o);
    ASSERT_EQ(r.status, RunStatus::ok) << r.error;
    ASSERT_TRUE(r.metrics.number(Metric::energy_max_rel_drift));
    const double drift = std::abs(r.metrics.value(Metric::energy_final) - r.metrics.value(Metric::energy_initial)) / r.metrics.value(Metric::energy_initial);
    std::printf("lammps/%s elastic box: final energy drift %.3g, max over samples %.3g, wall tunnelling %ld\n", profile,
                drift, *r.metrics.number(Metric::energy_max_rel_drift), r.metrics.count(Metric::tunnelling_wall));
    EXPECT_LT(drift, 1e-4) << profile;
  }
}

// Springs set for the heaviest balls are met by the lightest in a shorter contact, and, as LAMMPS
// damps per unit of reduced mass, with more bounce: the DEM step resolves the shorter one.
TEST(LammpsAdapter, TheLightestBallsContactSetsTheStepWhereMassesDiffer) {
  Scene s = equal_head_on(0.8);
  s.mass(1) = 100;  // heaviest 100, lightest 1
  for (const lammps::ContactLaw law : {lammps::ContactLaw::hooke, lammps::ContactLaw::hertz}) {
    const lammps::ContactModel m = lammps::derive_contact_model(s, {law});
    EXPECT_LT(m.light_pair.contact_time, m.pair.contact_time) << lammps::law_name(law);
    EXPECT_EQ(m.contact_time, std::min(m.light_pair.contact_time, m.light_wall.contact_time)) << lammps::law_name(law);
    EXPECT_GT(m.e_light_pair, 0.8) << lammps::law_name(law);
    // Hooke: t_c = pi / (w0 sqrt(1 - zeta^2)), w0 = sqrt(kn / meff), zeta = gn / (2 w0). meff 0.5
    // against 50 scales w0 by 10 and zeta (0.0709 at e 0.8) by 1/10: the ratio is
    // 0.1 sqrt(1 - 0.0709^2) / sqrt(1 - 0.00709^2) = 0.09975.
    if (law == lammps::ContactLaw::hooke) {
      EXPECT_NEAR(m.light_pair.contact_time / m.pair.contact_time, 0.09975, 1e-5);
    }
  }
  // Equal masses: the same contact as designed.
  const lammps::ContactModel equal = lammps::derive_contact_model(equal_head_on(0.8), {});
  EXPECT_DOUBLE_EQ(equal.light_pair.contact_time, equal.pair.contact_time);
  EXPECT_NEAR(equal.e_light_pair, 0.8, 1e-12);
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
  EXPECT_EQ(r.status, RunStatus::unsupported);
  EXPECT_NE(r.error.find("above max_substeps = 5000"), std::string::npos) << r.error;
  // What it would have run with is recorded, as for a run: the settings and the sub-steps it needs.
  EXPECT_EQ(r.settings.value("max_substeps", 0), 5000) << r.settings.dump();
  EXPECT_EQ(r.settings["derived"].value("substeps", 0), 7944) << r.settings.dump();
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
  const std::string unknown = message({{"overlap", 0.01}});
  EXPECT_NE(unknown.find("settings.lammps.overlap: unknown setting"), std::string::npos) << unknown;
  for (const char* key : {"ranks", "hostfile", "mpirun", "lmp", "workdir"})  // every key, paths included
    EXPECT_NE(unknown.find(key), std::string::npos) << key << " missing from: " << unknown;
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

// 24 balls in a box with gravity, 20 steps read every 5: 2 ranks under mpirun against the library
// in this process, the same input. Domain decomposition changes which rank sums a contact's force,
// never the pairwise forces, so the runs agree to round-off at most: 1e-9 relative on energy and
// momentum, the same counts (measured: bit-identical states, equal checksums).
Scene small_box() { return gas_in_box(0.9, -2.0, 24, 0.08, 0.5, 5, 0.2); }

TEST(LammpsAdapter, TwoRanksAgreeWithOne) {
  const Scene s = small_box();
  RunOptions o;
  o.profile = "hooke";
  o.overrides = {{"sample_every", 5}};
  const Result one = run_engine(s, find_engine("lammps"), o);
  o.overrides["ranks"] = 2;
  const Result two = run_engine(s, find_engine("lammps"), o);
  ASSERT_EQ(one.status, RunStatus::ok) << one.error;
  ASSERT_EQ(two.status, RunStatus::ok) << two.error;
  EXPECT_EQ(two.metrics.count(Metric::samples), 5);  // steps 0, 5, 10, 15, 20
  EXPECT_EQ(two.metrics_config.sample_every, 5);
  EXPECT_NE(std::find_if(two.skipped.begin(), two.skipped.end(),
                         [](const std::string& note) { return note.rfind(kStrideNote, 0) == 0; }),
            two.skipped.end());
  const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a)); };
  EXPECT_TRUE(near(one.metrics.value(Metric::energy_final), two.metrics.value(Metric::energy_final)))
      << one.metrics.value(Metric::energy_final) << " vs " << two.metrics.value(Metric::energy_final);
  EXPECT_TRUE(near(one.metrics.value(Metric::energy_max_abs_drift), two.metrics.value(Metric::energy_max_abs_drift)));
  EXPECT_TRUE(near(one.metrics.vec(Metric::momentum_final).x(), two.metrics.vec(Metric::momentum_final).x()));
  EXPECT_TRUE(near(one.metrics.vec(Metric::momentum_final).y(), two.metrics.vec(Metric::momentum_final).y()));
  EXPECT_TRUE(near(one.metrics.value(Metric::penetration_max), two.metrics.value(Metric::penetration_max)));
  EXPECT_EQ(one.metrics.count(Metric::tunnelling_wall) + one.metrics.count(Metric::tunnelling_pair), two.metrics.count(Metric::tunnelling_wall) + two.metrics.count(Metric::tunnelling_pair));
  EXPECT_EQ(one.metrics.count(Metric::sticking_wall) + one.metrics.count(Metric::sticking_pair), two.metrics.count(Metric::sticking_wall) + two.metrics.count(Metric::sticking_pair));
  std::printf("lammps 2 ranks vs 1: energy %.17g vs %.17g, checksums %s\n", two.metrics.value(Metric::energy_final),
              one.metrics.value(Metric::energy_final), one.checksum_trajectory == two.checksum_trajectory ? "equal" : "different");
}

TEST(LammpsAdapter, IsDeterministic) {
  RunOptions o;
  o.profile = "hertz";  // the one with per-contact history
  const Result a = run_engine(small_box(), find_engine("lammps"), o), b = run_engine(small_box(), find_engine("lammps"), o);
  ASSERT_EQ(a.status, RunStatus::ok) << a.error;
  EXPECT_EQ(a.checksum_trajectory, b.checksum_trajectory);
}

// One ball (r 0.25, m 1) set down on the floor of a box, sliding at 3 m/s without spin; friction
// 0.5, g 9.81. Friction slows it and spins it up until its contact point stops: angular momentum
// about the contact point is kept, so it rolls on at v0 / (1 + k), I = k m r^2: 2/3 v0 for a disk
// (nve/sphere disc), 5/7 v0 for a sphere (nve/sphere), after v0 k / ((1 + k) mu g) = 0.20 s and
// 0.17 s. Read at t = 0.5 s, at x ~ 1.1 (the far wall is at 4).
Scene sliding_ball(const char* inertia, double e) {
  return parse_scene(fmt::format(R"(
dt = 0.01
duration = 0.5
restitution = {}
friction = 0.5
inertia = "{}"
gravity = [0.0, -9.81]
[container]
min = [-1.0, 0.0]
max = [4.0, 1.0]
[[ball]]
pos = [0.0, 0.25]
vel = [3.0, 0.0]
radius = 0.25
mass = 1.0
)",
                                 e, inertia),
                     "sliding-ball.toml");
}

// Both laws, with restitution 0.5 (hooke's tangential force is a dashpot, gamma_t = gamma_n / 2:
// it needs some normal damping to act at all, below). The contact is soft, yet the rolling speed is
// the rigid one to round-off (measured: within 9e-13 of it, both laws, both moments; the brief's
// bound was 1%): friction and the normal force both act at the contact point, which keeps the
// angular momentum about it exactly, and LAMMPS's tangential velocity v + w r is zero at the fixed
// point its dashpot (or spring) relaxes to. The angle, the trapezoid of the spins read after every
// step, grows linearly in the slide, constant after: -w_roll (T - t_roll / 2),
// to the trapezoid's error at the kink (measured 4.7e-4 rad disk, 6.1e-4 sphere).
TEST(LammpsAdapter, SlidingBallRollsOnAtTheMomentsSpeed) {
  for (const char* profile : {"hooke", "hertz"}) {
    for (const auto& [inertia, factor] : {std::pair{"disk", 2.0 / 3.0}, std::pair{"sphere", 5.0 / 7.0}}) {
      const Scene s = sliding_ball(inertia, 0.5);
      ASSERT_TRUE(s.features().rotation);
      auto e = find_engine("lammps").create(s, profile, {});
      EXPECT_EQ(e->settings()["derived"]["inertia"].get<std::string>().rfind(inertia, 0), 0u) << e->settings().dump();
      for (int k = 0; k < 50; ++k) e->step(s.dt);
      State st;
      e->read(st);
      ASSERT_EQ(st.w.size(), 1);
      ASSERT_EQ(st.angle.size(), 1);
      const double v = st.vel(0, 0), w = st.w(0), expected = factor * 3.0;
      std::printf("lammps/%s %s: final speed %.9g (rigid %.9g, off by %.3g of it), w %.9g, w r + v %.3g, angle %.9g\n",
                  profile, inertia, v, expected, v / expected - 1, w, w * 0.25 + v, st.angle(0));
      RecordProperty(fmt::format("{}_{}_final_speed", profile, inertia), fmt::format("{:.6g}", v));
      EXPECT_NEAR(v / expected, 1.0, 1e-9) << profile << " " << inertia;
      EXPECT_NEAR(w * 0.25 + v, 0.0, 1e-9) << profile << " " << inertia;  // rolling: the contact point rests
      const double k = factor == 2.0 / 3.0 ? 0.5 : 0.4, t_roll = 3.0 * k / ((1 + k) * 0.5 * 9.81);
      EXPECT_NEAR(st.angle(0), -expected / 0.25 * (0.5 - t_roll / 2), 2e-3) << profile << " " << inertia;  // clockwise
    }
  }
  // Through the runner: a rotating scene's states carry w and angle, so the run is judged.
  RunOptions o;
  o.profile = "hooke";
  const Result r = run_engine(sliding_ball("disk", 0.5), find_engine("lammps"), o);
  EXPECT_EQ(r.status, RunStatus::ok) << r.error;
  // 2 ranks, the spins from the dumps every 5 steps: the same spin as one rank (measured: equal
  // bits), the angle a trapezoid over 5 steps instead of 1, off at the kink only (measured 0.0030 rad).
  const Scene s = sliding_ball("disk", 0.5);
  const State one = run_lammps(s, "hooke", 50), two = run_lammps(s, "hooke", 50, {{"ranks", 2}, {"sample_every", 5}});
  std::printf("lammps 2 ranks vs 1, sliding disk: w %.17g vs %.17g, angle %.9g vs %.9g\n", two.w(0), one.w(0),
              two.angle(0), one.angle(0));
  EXPECT_NEAR(two.w(0), one.w(0), 1e-9);
  EXPECT_NEAR(two.vel(0, 0), one.vel(0, 0), 1e-9);
  EXPECT_NEAR(two.angle(0), one.angle(0), 0.02);
}

// Hooke's tangential force is -meff gamma_t vt with gamma_t = gamma_n / 2 (no tangential spring
// without shear history): at restitution 1, gamma_n = 0 and friction does nothing. Hertz/history
// keeps its tangential spring (Kt = 2/7 Kn), so it still rolls.
// hooke's friction is a damper of half its normal damping, which is 0 at restitution 1: it would
// ignore the friction, so it refuses the scene; hertz (history, a spring) still rolls.
TEST(LammpsAdapter, ElasticHookeContactsRefuseFriction) {
  const Scene s = sliding_ball("disk", 1.0);
  RunOptions o;
  o.profile = "hooke";
  const Result refused = run_engine(s, find_engine("lammps"), o);
  EXPECT_EQ(refused.status, RunStatus::unsupported);
  EXPECT_NE(refused.error.find("would be ignored"), std::string::npos) << refused.error;
  const State hertz = run_lammps(s, "hertz", 50);
  EXPECT_NEAR(hertz.vel(0, 0) / 2.0, 1.0, 0.01);
}

// A frictionless ball spinning at 3 rad/s keeps its spin, and the angle (the adapter's integral of
// the spins read back: LAMMPS's spheres have no orientation) reaches 3 rad at t = 1 s: read every
// step in this process, and every 10 steps from 2 ranks under mpirun (the trapezoid between dumps).
Scene spinning_ball() {
  return parse_scene(R"(
dt = 0.01
duration = 1.0
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[[ball]]
pos = [0.5, 0.0]
vel = [0.5, 0.0]
radius = 0.25
spin = 3.0
)",
                     "spinning-ball.toml");
}

TEST(LammpsAdapter, FrictionlessSpinIsKeptAndItsAngleIntegrated) {
  const Scene s = spinning_ball();
  ASSERT_TRUE(s.features().rotation);
  for (const nlohmann::json& overrides : {nlohmann::json::object(), nlohmann::json{{"ranks", 2}, {"sample_every", 10}}}) {
    auto e = find_engine("lammps").create(s, "hooke", overrides);
    State st;
    e->read(st);
    ASSERT_EQ(st.w.size(), 1);
    EXPECT_EQ(st.w(0), 3.0);
    EXPECT_EQ(st.angle(0), 0.0);
    for (int k = 0; k < 100; ++k) e->step(s.dt);  // the wall x = 1 at t = 0.5 s, and back: no torque without friction
    e->read(st);
    std::printf("lammps %s: spin %.17g, angle %.17g at t = %g\n", overrides.dump().c_str(), st.w(0), st.angle(0), st.t);
    EXPECT_EQ(st.w(0), 3.0) << overrides.dump();
    EXPECT_NEAR(st.angle(0), 3.0, 1e-12) << overrides.dump();
    EXPECT_NEAR(st.vel(0, 0), -0.5, 1e-3) << overrides.dump();  // it did meet the wall (elastic)
  }
  // A scene that does not rotate reads back no spins.
  Scene still = s;
  still.initial.w.setZero();
  ASSERT_FALSE(still.features().rotation);
  EXPECT_EQ(run_lammps(still, "hooke", 1).w.size(), 0);
}

// mpirun that cannot run its program ends the run as failed, with mpirun's own words.
TEST(LammpsAdapter, AFailedMpirunIsAFailedRunWithItsStderr) {
  RunOptions o;
  o.profile = "hooke";
  o.overrides = {{"ranks", 2}, {"lmp", "false"}};
  const Result r = run_engine(small_box(), find_engine("lammps"), o);
  EXPECT_EQ(r.status, RunStatus::failed);
  EXPECT_NE(r.error.find("mpirun -np 2"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("exited with status"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("its stderr:"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace ballbench

#endif  // BALLBENCH_HAS_LAMMPS

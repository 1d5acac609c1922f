// The built-in validation scenes (scenarios/) against their analytic answers, for our solvers.
// The exact engine's own precision tests are in test_exact.cpp; here both `exact` and `home` must
// reproduce the physics each scene file promises.
#include <gtest/gtest.h>

#include <cmath>

#include "registry.h"
#include "runner.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

State final_state(const std::string& scene_name, const std::string& engine, double dt = 0) {
  Scene s = load_scene(scene_name);
  if (dt > 0) s.dt = dt;
  auto e = find_engine(engine).create(s, "default", merged_settings(s, engine, {}));
  for (long k = 0; k < s.steps(); ++k) e->step(s.dt);
  State st;
  e->read(st);
  return st;
}

class Validation : public ::testing::TestWithParam<std::string> {};

TEST_P(Validation, TwoBallCollisionsFollowEquations4To8) {
  // v1' = (m1 - m2) / (m1 + m2) v1, v2' = 2 m1 / (m1 + m2) v1 with v1 = 2. Tolerance: one impulse's
  // round-off in double, times the mass ratio's condition (1000).
  for (const auto& [scene, m2] : {std::pair{"two-ball-1", 1.0}, {"two-ball-3", 3.0}, {"two-ball-1000", 1000.0}}) {
    const State st = final_state(scene, GetParam());
    EXPECT_NEAR(st.vel(0, 0), (1 - m2) / (1 + m2) * 2, 1e-12 * m2) << scene;
    EXPECT_NEAR(st.vel(1, 0), 2 / (1 + m2) * 2, 1e-12 * m2) << scene;
  }
}

TEST_P(Validation, CorridorBallIsWhereTheUnfoldedLineSaysAfter40Bounces) {
  // After 73 m of travel in a 1.8 m corridor (centre range [-0.9, 0.9]) the ball is where the
  // straight line folded at every wall puts it, moving at exactly its speed. Tolerance: round-off
  // of ~40 reflections and 1000 position updates of ~7 m each.
  const State st = final_state("corridor", GetParam());
  const double unfolded = std::fmod(73.0 + 0.9, 3.6);
  EXPECT_NEAR(st.pos(0, 0), unfolded < 1.8 ? unfolded - 0.9 : 2.7 - unfolded, 1e-9);
  EXPECT_DOUBLE_EQ(std::abs(st.vel(0, 0)), 7.3);
}

TEST_P(Validation, NewtonsCradlePassesTheImpactAlongTheRow) {
  // With gaps the impacts are a sequence of binary elastic collisions of equal masses: each
  // exchanges velocities, so only the last ball moves on, at the striker's 1 m/s.
  const State st = final_state("newtons-cradle", GetParam());
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(st.vel(i, 0), 0.0, 1e-12) << "ball " << i;  // round-off of 5 impulses
  EXPECT_NEAR(st.vel(5, 0), 1.0, 1e-12);
}

TEST_P(Validation, DroppedBallPeaksFollowEToThe2N) {
  // Peaks h_n = e^(2n) h0 with e = 0.8, h0 = 4 m above the resting height. Sampling every 1 ms
  // misses a peak by at most g dt^2 / 8 = 1.2e-6 m; home's symplectic Euler adds a first-order
  // error of the order g dt t per flight (~1e-2 m over the first second), hence its 1% tolerance.
  Scene s = load_scene("drop");
  auto e = find_engine(GetParam()).create(s, "default", merged_settings(s, GetParam(), {}));
  State st;
  std::vector<double> peaks;
  double prev_vy = 0, top = 0;
  for (long k = 0; k < s.steps(); ++k) {
    e->step(s.dt);
    e->read(st);
    const double h = st.pos(0, 1) - 0.25;
    top = std::max(top, h);
    if (prev_vy > 0 && st.vel(0, 1) <= 0) peaks.push_back(top);  // past the top of a flight
    if (st.vel(0, 1) > 0 && prev_vy <= 0) top = 0;              // a bounce starts a new flight
    prev_vy = st.vel(0, 1);
  }
  ASSERT_GE(peaks.size(), 3u);
  const double tolerance = GetParam() == "exact" ? 1e-5 : 1e-2;
  for (int n = 1; n <= 3; ++n) EXPECT_NEAR(peaks[n - 1] / 4.0, std::pow(0.8, 2 * n), tolerance) << "peak " << n;
}

TEST_P(Validation, ProjectileErrorShowsTheIntegratorsOrder) {
  // s0 + v0 t + g t^2 / 2 at t = 2 s: exact to round-off; symplectic Euler (velocity first) is
  // g dt t / 2 ahead in the fall, first order: halving dt halves the error.
  const double y = 10.0 * 2 - 9.81 * 2 * 2 / 2;
  const double err = std::abs(final_state("projectile", GetParam()).pos(0, 1) - y);
  if (GetParam() == "exact") {
    EXPECT_LT(err, 1e-12);
  } else {
    const double err_half = std::abs(final_state("projectile", GetParam(), 0.005).pos(0, 1) - y);
    EXPECT_NEAR(err, 9.81 * 0.01 * 2 / 2, 1e-9);
    EXPECT_NEAR(err / err_half, 2.0, 1e-6);
  }
}

TEST_P(Validation, ElasticGasKeepsItsEnergyAndBecomesRayleigh) {
  const Scene s = load_scene("gas");
  const Result r = run_engine(s, find_engine(GetParam()), {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_LT(*r.metrics.number(Metric::energy_max_rel_drift), 1e-12);  // elastic: round-off of ~10^5 impulses
  ASSERT_TRUE(r.metrics.has(Metric::speed_ks));
  EXPECT_LT(*r.metrics.number(Metric::speed_ks), *r.metrics.number(Metric::speed_ks_critical));  // Rayleigh not rejected at the 1% level
  EXPECT_EQ(r.metrics.count(Metric::tunnelling_pair) + r.metrics.count(Metric::sticking_pair), 0);
}

INSTANTIATE_TEST_SUITE_P(OurSolvers, Validation, ::testing::Values("exact", "home"));

TEST(Stress, BulletBallPassesNothingInOurSolvers) {
  // 1000 m/s, 10 m per step, through five balls to a wall: continuous collision must catch all.
  for (const std::string engine : {"exact", "home"}) {
    const Result r = run_engine(load_scene("bullet"), find_engine(engine), {});
    EXPECT_EQ(r.metrics.count(Metric::tunnelling_pair) + r.metrics.count(Metric::tunnelling_wall), 0) << engine;
    EXPECT_LT(*r.metrics.number(Metric::energy_max_rel_drift), 1e-12) << engine;
  }
}

}  // namespace
}  // namespace ballbench

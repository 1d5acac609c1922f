// The use-case scenes (scenarios/README.md, "Use cases"): each is what its file's comment says, of
// the class and spec it says, and our solver meets that spec on it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "accuracy_spec.h"
#include "metrics/rolling.h"
#include "registry.h"
#include "runner.h"
#include "scene_loader.h"
#include "spec_verdict.h"

namespace ballbench {
namespace {

// 400 balls of r 0.5 in a box of side 39.6: packing fraction 0.2; the gas class with its energy
// bound relaxed to 1e-3.
TEST(UseCaseScenes, ElasticGasIsAGasOfPacking02JudgedByItsEnergy) {
  const Scene s = load_scene("elastic-gas");
  ASSERT_EQ(s.n(), 400);
  EXPECT_EQ(s.radius.minCoeff(), 0.5);
  EXPECT_EQ(s.radius.maxCoeff(), 0.5);
  const Eigen::Vector2d side = s.container.max - s.container.min;
  EXPECT_NEAR(s.n() * std::numbers::pi * 0.25 / (side.x() * side.y()), 0.2, 0.001);
  EXPECT_EQ(scene_class(s), SceneClass::gas);
  const AccuracySpec spec = scene_spec(s);
  EXPECT_EQ(spec[SpecTerm::energy_drift], 1e-3);
  EXPECT_EQ(spec[SpecTerm::tunnelling], 0);
  EXPECT_EQ(spec[SpecTerm::overlap], 0.01);
  const Result r = run_engine(s, find_engine("home"), {});
  const SpecVerdict v = judge(spec, r);
  EXPECT_TRUE(v.met) << v.why_not;
}

// 100 balls sliding on the floor, ball i at x = 1 + 0.6 i and vx_i = 1 + 2 i / 99: each rolls at
// 2/3 vx_i (a disk) from vx_i / (3 mu g), the scene by the fastest's time. Our solver ends each
// ball on its closed form to round-off.
TEST(UseCaseScenes, RollingBallsEachRollOnTheirOwnClosedForm) {
  const Scene s = load_scene("rolling-balls");
  ASSERT_EQ(s.n(), 100);
  EXPECT_EQ(scene_class(s), SceneClass::rolling);
  EXPECT_EQ(scene_spec(s)[SpecTerm::rolling], 0.005);
  const double mu = 0.5, g = 9.81;
  for (int i = 0; i < s.n(); ++i) {
    const double vx = 1 + 2.0 * i / 99;
    EXPECT_NEAR(s.initial.pos(i, 0), 1 + 0.6 * i, 1e-12) << i;
    EXPECT_EQ(s.initial.pos(i, 1), 0.25) << i;
    EXPECT_NEAR(s.initial.vel(i, 0), vx, 1e-15) << i;
    const RollingClosedForm c = rolling_closed_form(s, i);
    EXPECT_NEAR(c.speed, vx * 2 / 3, 1e-15) << i;
    ASSERT_TRUE(c.time_to_roll) << i;
    EXPECT_NEAR(*c.time_to_roll, vx / (3 * mu * g), 1e-15) << i;
  }
  const Result r = run_engine(s, find_engine("home"), {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_NEAR(*r.metrics.number(Metric::rolling_expected_time_to_roll), 3 / (3 * mu * g), 1e-15);
  ASSERT_TRUE(r.metrics.number(Metric::rolling_error));
  EXPECT_LT(*r.metrics.number(Metric::rolling_error), 1e-9);
  const SpecVerdict v = judge(scene_spec(s), r);
  EXPECT_TRUE(v.met) << v.why_not;
}

}  // namespace
}  // namespace ballbench

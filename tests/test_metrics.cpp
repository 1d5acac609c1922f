// Metrics on hand-made state sequences with known answers.
#include <gtest/gtest.h>

#include "metrics/energy.h"
#include "metrics/metrics.h"
#include "metrics/tunnelling.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

// Two balls of radius 0.25 and masses 1 and 3 in the box [-5, 5]^2, gravity (0, -10).
Scene two_balls() {
  return parse_scene(R"(
dt = 0.01
duration = 1.0
gravity = [0.0, -10.0]
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [-1.0, 0.0]
vel = [2.0, 0.0]
radius = 0.25
mass = 1.0
[[ball]]
pos = [1.0, 1.0]
vel = [0.0, -4.0]
radius = 0.25
mass = 3.0
)",
                     "two.toml");
}

State state(std::initializer_list<double> xy, std::initializer_list<double> v) {
  State s;
  s.resize(static_cast<int>(xy.size() / 2));
  auto p = xy.begin(), w = v.begin();
  for (int i = 0; i < s.n(); ++i) {
    s.pos(i, 0) = *p++, s.pos(i, 1) = *p++;
    s.vel(i, 0) = *w++, s.vel(i, 1) = *w++;
  }
  return s;
}

TEST(Energy, OfAKnownStateIsExact) {
  const Scene s = two_balls();
  // Floor at y = -5: heights 5 and 6. KE = 1*4/2 + 3*16/2 = 26; PE = 1*10*5 + 3*10*6 = 230.
  EXPECT_EQ(energy_reference(s), -50.0);  // -g . (x, -5) = 10 * -5
  EXPECT_EQ(total_energy(s.initial, s, energy_reference(s)), 256.0);
}

TEST(Momentum, DriftIsTheLargestChangeOfTheTotal) {
  const Scene s = two_balls();
  MetricsAccumulator m(s, {});
  m.observe(s.initial);  // P0 = (2, -12)
  m.observe(state({-1, 0, 1, 1}, {2, 0, 0, -3}));  // P = (2, -9): drift 3
  m.observe(state({-1, 0, 1, 1}, {2, 0, 0, -4}));  // back to P0
  EXPECT_DOUBLE_EQ(m.summary().momentum.max_abs_drift, 3.0);
  EXPECT_DOUBLE_EQ(m.summary().momentum.final.y(), -12.0);
}

// Steps through `states` as the runner does: the motion of every step, then the sample.
void feed(MetricsAccumulator& m, const std::vector<State>& states) {
  for (size_t k = 0; k < states.size(); ++k) {
    if (k > 0) m.observe_motion(states[k - 1], states[k]);
    m.observe(states[k]);
  }
}

TEST(Tunnelling, AnInjectedWallEscapeCountsOne) {
  const Scene s = two_balls();
  MetricsAccumulator m(s, {});
  feed(m, {s.initial, state({-1, 0, 1, -4.9}, {0, 0, 0, 0}),
           state({-1, 0, 1, -5.2}, {0, 0, 0, 0}),    // centre beyond the floor
           state({-1, 0, 1, -5.3}, {0, 0, 0, 0})});  // still beyond: the same escape
  EXPECT_EQ(m.summary().tunnelling_wall, 1);
}

TEST(Tunnelling, AnInjectedPassThroughCountsOne) {
  const Scene s = two_balls();
  MetricsAccumulator m(s, {});
  // Swapped places without ever overlapping in a sample.
  feed(m, {state({-1, 0, 1, 0}, {0, 0, 0, 0}), state({1, 0, -1, 0}, {0, 0, 0, 0})});
  EXPECT_EQ(m.summary().tunnelling_pair, 1);
  EXPECT_EQ(m.summary().sticking_pair, 0);
}

TEST(Tunnelling, OnlyTheMotionCounts) {
  // The same two samples fed as samples only (no motion between them): nothing to judge.
  const Scene s = two_balls();
  MetricsAccumulator m(s, {});
  m.observe(state({-1, 0, 1, 0}, {0, 0, 0, 0}));
  m.observe(state({1, 0, -1, 0}, {0, 0, 0, 0}));
  EXPECT_EQ(m.summary().tunnelling_pair, 0);
}

TEST(Tunnelling, AResolvedBounceDoesNotCount) {
  // Relative motion reflected at the contact point: both samples on the outer side of the tangent.
  EXPECT_GE(closest_approach({-0.6, 0.3}, {-0.6, 0.35}), 0.5);
  const Scene s = two_balls();
  MetricsAccumulator m(s, {});
  feed(m, {state({-0.6, 0, 0, 0.3}, {0, 0, 0, 0}), state({-0.6, 0, 0, 0.35}, {0, 0, 0, 0})});
  EXPECT_EQ(m.summary().tunnelling_pair, 0);
}

TEST(Tunnelling, TheSearchSkipsNoPassThroughThatCounts) {
  // Balls moving less than a chord through the contact circle (2 s (r_i + r_j), s = sqrt(1 - 0.98^2))
  // are not searched. The tightest pass that counts: apart by a hair more than r_i + r_j in both
  // samples, closest approach just inside 98% of it, so its travel is barely above that chord.
  const Scene s = two_balls();  // radius 0.25 each: rs = 0.5
  const double rs = 0.5, b = 0.979 * rs, half = 1.0001 * std::sqrt(rs * rs - b * b);  // d: (-half, b) -> (half, b)
  MetricsAccumulator m(s, {});
  feed(m, {state({-half / 2, b / 2, half / 2, -b / 2}, {0, 0, 0, 0}),
           state({half / 2, b / 2, -half / 2, -b / 2}, {0, 0, 0, 0})});
  EXPECT_EQ(m.summary().tunnelling_pair, 1);
  // The same pass just outside 98%: not counted.
  MetricsAccumulator wide(s, {});
  const double b2 = 0.981 * rs, half2 = 1.0001 * std::sqrt(rs * rs - b2 * b2);
  feed(wide, {state({-half2 / 2, b2 / 2, half2 / 2, -b2 / 2}, {0, 0, 0, 0}),
              state({half2 / 2, b2 / 2, -half2 / 2, -b2 / 2}, {0, 0, 0, 0})});
  EXPECT_EQ(wide.summary().tunnelling_pair, 0);
}

TEST(Sticking, APairHeldOverlappingKPlusOneSamplesCountsOne) {
  const Scene s = two_balls();
  MetricsConfig cfg;
  cfg.stuck_samples = 3;
  MetricsAccumulator m(s, cfg);
  m.observe(s.initial);
  const State overlapping = state({0, 0, 0.4, 0}, {0, 0, 0, 0});  // depth 0.1 = 20% of the radius sum
  for (int k = 0; k < cfg.stuck_samples; ++k) m.observe(overlapping);
  EXPECT_EQ(m.summary().sticking_pair, 0);  // K samples: not yet stuck
  m.observe(overlapping);
  EXPECT_EQ(m.summary().sticking_pair, 1);
  for (int k = 0; k < 5; ++k) m.observe(overlapping);
  EXPECT_EQ(m.summary().sticking_pair, 1);  // the same episode
  m.observe(s.initial);
  for (int k = 0; k <= cfg.stuck_samples; ++k) m.observe(overlapping);
  EXPECT_EQ(m.summary().sticking_pair, 2);  // a new episode
}

TEST(Sticking, ABallHeldInAWallCountsOne) {
  const Scene s = two_balls();
  MetricsConfig cfg;
  cfg.stuck_samples = 2;
  MetricsAccumulator m(s, cfg);
  m.observe(s.initial);
  for (int k = 0; k < 3; ++k) m.observe(state({-4.9, 0, 1, 1}, {0, 0, 0, 0}));  // 0.15 deep in the left wall
  EXPECT_EQ(m.summary().sticking_wall, 1);
}

TEST(Penetration, MaxAndMeanAreRelativeToTheRadius) {
  const Scene s = two_balls();
  MetricsAccumulator m(s, {});
  m.observe(state({0, 0, 0.45, 0}, {0, 0, 0, 0}));   // depth 0.05 -> 0.2
  m.observe(state({0, 0, 0.4, 0}, {0, 0, 0, 0}));    // depth 0.1 -> 0.4
  EXPECT_NEAR(m.summary().penetration_max, 0.4, 1e-12);
  EXPECT_NEAR(m.summary().penetration_mean, 0.3, 1e-12);
}

TEST(Divergence, EnergyFarAboveTheStartIsABlowUp) {
  const Scene s = two_balls();
  MetricsAccumulator m(s, {});
  m.observe(s.initial);
  EXPECT_FALSE(m.energy_blew_up());
  m.observe(state({-1, 0, 1, 1}, {1e3, 0, 0, 0}));
  EXPECT_TRUE(m.energy_blew_up());
}

}  // namespace
}  // namespace ballbench

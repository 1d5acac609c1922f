// The event-driven reference solver `exact` against closed-form answers: binary impacts (thesis
// eq. 11-12), wall bounces, free flight under gravity, a bouncing ball's peaks, Newton's cradle,
// and the invariants of a gas and a pile (energy, no overlap, bit-for-bit reproducibility); with
// friction, slide to roll, the spin drop, rolling down an incline, rough oblique impacts, a rough
// gas's angular momentum, and the scenes it refuses or fails with the reason.
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <Eigen/LU>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "engine.h"
#include "input_error.h"
#include "overlap.h"
#include "registry.h"
#include "rough_gas.h"
#include "scene_loader.h"
#include "uniform_grid.h"

namespace ballbench {
namespace {

std::unique_ptr<Engine> make_exact(const Scene& s, const nlohmann::json& overrides = nlohmann::json::object()) {
  return find_engine("exact").create(s, "default", overrides);
}

State read(const Engine& e) {
  State st;
  e.read(st);
  return st;
}

// Records a measured figure in the test's XML properties and prints it.
template <class T>
void note(const char* key, const T& value) {
  ::testing::Test::RecordProperty(key, fmt::format("{}", value));
  fmt::print("  [exact] {} = {}\n", key, value);
}

double kinetic_energy(const State& st, const Scene& s) {
  double ke = 0;
  for (int i = 0; i < st.n(); ++i) ke += 0.5 * s.mass(i) * st.vel.row(i).squaredNorm();
  return ke;
}

// Deepest overlap of any pair (m), 0 if none.
double deepest_overlap(const State& st, const Scene& s) {
  OverlapScratch scratch;
  std::vector<Overlap> found;
  overlapping_pairs(st.pos, s.radius, scratch, found);
  double worst = 0;
  for (const Overlap& o : found) worst = std::max(worst, o.depth);
  return worst;
}

// Two balls on the x axis, ball 0 moving at v into ball 1 at rest: the 1D elastic result (thesis
// eq. 8) v1' = (m1 - m2) v1 / (m1 + m2), v2' = 2 m1 v1 / (m1 + m2).
void expect_head_on(double m1, double m2) {
  const Scene s = parse_scene(fmt::format(R"(
dt = 0.01
duration = 1.0
[[ball]]
pos = [-1.0, 0.0]
vel = [2.0, 0.0]
radius = 0.25
mass = {}
[[ball]]
pos = [0.0, 0.0]
radius = 0.25
mass = {}
)",
                                          m1, m2),
                              "head-on.toml");
  auto engine = make_exact(s);
  for (int k = 0; k < 100; ++k) engine->step(0.01);
  const State st = read(*engine);
  const double v1 = 2.0, u1 = (m1 - m2) / (m1 + m2) * v1, u2 = 2 * m1 / (m1 + m2) * v1;
  // One impulse: a few roundings of numbers of size |v1| (~1e-15); 1e-12 leaves a wide margin.
  EXPECT_NEAR(st.vel(0, 0), u1, 1e-12);
  EXPECT_NEAR(st.vel(1, 0), u2, 1e-12);
  EXPECT_EQ(st.vel(0, 1), 0.0);
  EXPECT_EQ(st.vel(1, 1), 0.0);
  // Contact after the 0.5 m gap closes at 2 m/s (t = 0.25 s); then 0.75 s at the new speeds.
  // Same round-off budget, times the positions' size (~1 m).
  EXPECT_NEAR(st.pos(0, 0), -0.5 + 0.75 * u1, 1e-12);
  EXPECT_NEAR(st.pos(1, 0), 0.75 * u2, 1e-12);
  note("head_on_error", fmt::format("{:.3g}", std::max(std::abs(st.vel(0, 0) - u1), std::abs(st.vel(1, 0) - u2))));
}

TEST(Exact, HeadOnMasses1And3) { expect_head_on(1.0, 3.0); }
TEST(Exact, HeadOnMassRatio1000) { expect_head_on(1.0, 1000.0); }

// An oblique impact: ball 1 at (-1, 0.3) moving (2, 0) meets ball 2 (at rest at the origin) when
// its centre is at (-0.4, 0.3), t = 0.3 s (|(-1 + 2t, 0.3)| = 0.5). The result is thesis eq. 11-12,
// with 2 generalised to 1 + e, and the tangential components untouched.
void expect_oblique(double e) {
  const Scene s = parse_scene(fmt::format(R"(
dt = 0.01
duration = 1.0
restitution = {}
[[ball]]
pos = [-1.0, 0.3]
vel = [2.0, 0.0]
radius = 0.25
mass = 1.0
[[ball]]
pos = [0.0, 0.0]
radius = 0.25
mass = 2.0
)",
                                          e),
                              "oblique.toml");
  auto engine = make_exact(s);
  engine->step(1.0);
  const State st = read(*engine);
  const Eigen::Vector2d x1{-0.4, 0.3}, x2{0, 0}, v1{2, 0}, v2{0, 0};
  const double m1 = 1, m2 = 2;
  const Eigen::Vector2d d = x1 - x2;
  const Eigen::Vector2d w1 = v1 - (1 + e) * m2 / (m1 + m2) * (v1 - v2).dot(d) / d.squaredNorm() * d;  // eq. 11
  const Eigen::Vector2d w2 = v2 - (1 + e) * m1 / (m1 + m2) * (v2 - v1).dot(-d) / d.squaredNorm() * (-d);  // eq. 12
  // Round-off of one impulse on O(1) numbers, plus the contact time found to a few ulps.
  EXPECT_NEAR(st.vel(0, 0), w1.x(), 1e-12);
  EXPECT_NEAR(st.vel(0, 1), w1.y(), 1e-12);
  EXPECT_NEAR(st.vel(1, 0), w2.x(), 1e-12);
  EXPECT_NEAR(st.vel(1, 1), w2.y(), 1e-12);
  const Eigen::Vector2d tangent{-d.y(), d.x()};
  EXPECT_NEAR(st.vel.row(0).dot(tangent), v1.dot(tangent), 1e-12);
  EXPECT_NEAR(st.vel.row(1).dot(tangent), v2.dot(tangent), 1e-12);
  // Positions: contact at t = 0.3, then 0.7 s at the new velocities.
  EXPECT_NEAR((st.pos.row(0).transpose() - (x1 + 0.7 * w1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((st.pos.row(1).transpose() - (x2 + 0.7 * w2)).norm(), 0.0, 1e-12);
  note("oblique_velocity_error", fmt::format("{:.3g}", std::max((st.vel.row(0).transpose() - w1).norm(),
                                                                (st.vel.row(1).transpose() - w2).norm())));
}

TEST(Exact, ObliqueImpactFollowsThesisEq11And12) { expect_oblique(1.0); }
TEST(Exact, ObliqueInelasticImpactKeepsTangentialVelocity) { expect_oblique(0.5); }

Scene corridor(double e) {
  return parse_scene(fmt::format(R"(
dt = 0.01
duration = 10.0
restitution = {}
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[[ball]]
pos = [0.0, 0.0]
vel = [7.3, 0.0]
radius = 0.1
)",
                                 e),
                     "corridor.toml");
}

TEST(Exact, ElasticBallBetweenWallsFollowsTheUnfoldedLine) {
  const Scene s = corridor(1.0);
  auto engine = make_exact(s);
  for (int k = 0; k < 1000; ++k) engine->step(0.01);
  const State st = read(*engine);
  // 73 m of travel in a corridor of 1.8 m for the centre: unfold, then fold back.
  const double unfolded = std::fmod(73.0 + 0.9, 3.6);
  const double expected = unfolded < 1.8 ? unfolded - 0.9 : 2.7 - unfolded;
  // 1e-9 relative to the corridor width; round-off of ~40 bounces and 1000 step ends on numbers of
  // size ~10 (the clock) is ~1e-13.
  EXPECT_NEAR(st.pos(0, 0), expected, 1e-9 * 1.8);
  EXPECT_EQ(std::abs(st.vel(0, 0)), 7.3);
  note("position_error", fmt::format("{:.3g}", std::abs(st.pos(0, 0) - expected)));
}

TEST(Exact, InelasticWallBouncesScaleTheSpeedByE) {
  const Scene s = corridor(0.9);
  auto engine = make_exact(s);
  double prev = 7.3, worst = 0;
  int bounces = 0;
  // The walls are >= 0.25 s apart in flight time at <= 7.3 m/s: at most one bounce per 0.01 s step.
  for (int k = 0; k < 1000; ++k) {
    engine->step(0.01);
    const double v = read(*engine).vel(0, 0);
    if ((v > 0) != (prev > 0)) ++bounces;
    prev = v;
    const double expected = 7.3 * std::pow(0.9, bounces);
    worst = std::max(worst, std::abs(std::abs(v) - expected) / expected);
  }
  EXPECT_GT(bounces, 10);
  // One rounding per bounce (v = e u) plus pow's: ~bounces ulps; 1e-12 is ample for ~20 bounces.
  EXPECT_LT(worst, 1e-12);
  note("speed_rel_error", fmt::format("{:.3g}", worst));
}

TEST(Exact, ProjectileFollowsTheParabola) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 3.0
gravity = [0.0, -9.81]
[[ball]]
pos = [1.0, 2.0]
vel = [3.0, 4.0]
radius = 0.1
)",
                              "projectile.toml");
  auto engine = make_exact(s);
  const Eigen::Vector2d s0{1, 2}, v0{3, 4}, g{0, -9.81};
  double worst = 0;
  for (int k = 1; k <= 300; ++k) {
    engine->step(0.01);
    const State st = read(*engine);
    const double t = st.t;
    const Eigen::Vector2d expected = s0 + v0 * t + 0.5 * g * t * t;
    worst = std::max(worst, (st.pos.row(0).transpose() - expected).norm() / expected.norm());
    EXPECT_NEAR((st.vel.row(0).transpose() - (v0 + g * t)).norm(), 0.0, 1e-12 * 30);
  }
  // One rounding per step end on numbers of size |s|: 300 steps ~ 300 eps ~ 7e-14.
  EXPECT_LT(worst, 1e-12);
  note("position_rel_error", fmt::format("{:.3g}", worst));
}

// A ball of radius 0.1 dropped from h0 = 1 (centre height above its rest position y = 0; the floor
// is at y = -0.1) with e = 0.8. Analytic: impact speed v1 = sqrt(2 g h0); after bounce n the take-off
// speed is s_n = e^n v1, the peak h_n = s_n^2 / 2g = e^(2n) h0 at time P_n = T_n + s_n / g, where
// T_1 = sqrt(2 h0 / g) and T_(n+1) = T_n + 2 s_n / g. The rest rule ends the bouncing at the first
// impact slower than rest_velocity.
struct Drop {
  static constexpr double h0 = 1.0, e = 0.8, g = 9.81, r = 0.1;
  Scene scene = parse_scene(R"(
dt = 0.001
duration = 5.0
gravity = [0.0, -9.81]
restitution = 0.8
[container]
min = [-1.0, -0.1]
max = [1.0, 3.0]
[[ball]]
pos = [0.0, 1.0]
radius = 0.1
)",
                            "drop.toml");
  std::vector<double> bounce;  // T_n, n = 1.. (bounce[0] = T_1)
  std::vector<double> speed;   // s_n after bounce n (speed[0] = v1 before the first)
  int flights = 0;             // bounces before the rule kicks in (the last peak index)

  explicit Drop(double v_rest) {
    const double v1 = std::sqrt(2 * g * h0);
    bounce.push_back(std::sqrt(2 * h0 / g));
    speed.push_back(v1);
    // Bounce n (impact speed e^(n-1) v1) is a bounce while that speed is >= v_rest.
    for (int n = 1; std::pow(e, n - 1) * v1 >= v_rest; ++n) {
      flights = n;
      speed.push_back(std::pow(e, n) * v1);
      bounce.push_back(bounce.back() + 2 * speed.back() / g);
    }
  }
  double peak_time(int n) const { return bounce[n - 1] + speed[n] / g; }
  double peak(int n) const { return std::pow(e, 2 * n) * h0; }
  // Which flight t is in: 0 before the first impact, n between bounces n and n + 1; -1 near a bounce.
  int flight(double t) const {
    int n = 0;
    while (n < static_cast<int>(bounce.size()) && t > bounce[n]) ++n;
    for (double b : bounce)
      if (std::abs(t - b) < 1e-9) return -1;
    return n;
  }
};

TEST(Exact, DroppedBallPeaksAreEToThe2nTimesH0) {
  Scene probe = Drop(1).scene;
  const double v_rest = make_exact(probe)->settings()["rest_velocity"].get<double>();
  const Drop d(v_rest);
  ASSERT_GT(d.flights, 20);

  // (a) Sampled with steps: the peak of the flight a sample is in, from its own state,
  // y + vy^2 / 2g (energy along the exact parabola), must be e^(2n) h0.
  {
    auto engine = make_exact(d.scene);
    double worst = 0, lowest = 0;
    for (int k = 0; k < 5000; ++k) {
      engine->step(0.001);
      const State st = read(*engine);
      lowest = std::min(lowest, st.pos(0, 1));
      const int n = d.flight(st.t);
      if (n < 0 || n > d.flights) continue;
      const double y = st.pos(0, 1), vy = st.vel(0, 1);
      const double estimate = y + vy * vy / (2 * Drop::g);
      const double expected = n == 0 ? Drop::h0 : d.peak(n);
      worst = std::max(worst, std::abs(estimate - expected) / expected);
    }
    // The floor is at y = 0 for the centre, so every quantity scales with the flight's own height:
    // a few roundings per step end over <= 1000 steps in a flight: ~1e-13 relative.
    EXPECT_LT(worst, 1e-9);
    // At rest on the floor after the last bounce (T_(flights+1) < 4.1 s), exactly.
    const State end = read(*engine);
    EXPECT_EQ(end.pos(0, 1), 0.0);
    EXPECT_EQ(end.vel(0, 1), 0.0);
    EXPECT_EQ(end.vel(0, 0), 0.0);
    // Never below the floor: a sample just before a bounce sees the parabola's value, exact to a
    // rounding of the flight's own (tiny) height.
    EXPECT_GE(lowest, -1e-15);
    note("sampled_peak_rel_error", fmt::format("{:.3g}", worst));
    note("lowest_y", fmt::format("{:.3g}", lowest));
  }

  // (b) The state at each analytic peak time, by stepping exactly there.
  {
    auto engine = make_exact(d.scene);
    double worst = 0, t = 0;
    for (int n = 1; n <= d.flights; ++n) {
      const double tp = d.peak_time(n);
      engine->step(tp - t);
      const State st = read(*engine);
      t = st.t;
      worst = std::max(worst, std::abs(st.pos(0, 1) - d.peak(n)) / d.peak(n));
      // At the peak vy = 0; the clock's rounding (~eps t) times g is the residue.
      EXPECT_NEAR(st.vel(0, 1), 0.0, 1e-12);
    }
    EXPECT_LT(worst, 1e-9);
    note("peak_rel_error", fmt::format("{:.3g}", worst));
    note("bounces_before_rest", d.flights);
  }
}

// Five equal balls on a line, the striker 1 m away at 1 m/s, the other four at rest.
Scene cradle(double gap) {
  std::string toml = "dt = 0.01\nduration = 3.0\n";
  toml += "[[ball]]\npos = [-2.0, 0.0]\nvel = [1.0, 0.0]\nradius = 0.5\n";
  for (int k = 0; k < 4; ++k) toml += fmt::format("[[ball]]\npos = [{:.17g}, 0.0]\nradius = 0.5\n", k * (1.0 + gap));
  return parse_scene(toml, "cradle.toml");
}

void expect_cradle(double gap) {
  const Scene s = cradle(gap);
  auto engine = make_exact(s);
  for (int k = 0; k < 300; ++k) engine->step(0.01);
  const State st = read(*engine);
  // Sequential binary collisions of equal masses swap velocities exactly (up to one rounding).
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(st.vel(i, 0), 0.0, 1e-12) << "ball " << i;
  EXPECT_NEAR(st.vel(4, 0), 1.0, 1e-12);
  EXPECT_LT(deepest_overlap(st, s), 1e-12);
  double worst = std::abs(st.vel(4, 0) - 1.0);
  for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(st.vel(i, 0)));
  note("cradle_velocity_error", fmt::format("{:.3g}", worst));
}

TEST(Exact, NewtonsCradleWithATinyGap) { expect_cradle(1e-6); }
// Exactly touching: hard-disk dynamics leaves it undefined; our rule (binary collisions in order
// of time, then ball index) gives the same textbook answer.
TEST(Exact, NewtonsCradleTouching) { expect_cradle(0.0); }

TEST(Exact, ElasticGasConservesEnergyWithoutOverlapAndReproduces) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 2.0
[container]
min = [-10.0, -10.0]
max = [10.0, 10.0]
[random]
count = 1000
radius = 0.1
vel_min = [-1.0, -1.0]
vel_max = [1.0, 1.0]
seed = 7
)",
                              "gas.toml");
  auto run = [&](double& worst_energy, double& worst_overlap) {
    auto engine = make_exact(s);
    const double e0 = kinetic_energy(read(*engine), s);
    worst_energy = worst_overlap = 0;
    for (int k = 0; k < 200; ++k) {
      engine->step(0.01);
      const State st = read(*engine);
      worst_energy = std::max(worst_energy, std::abs(kinetic_energy(st, s) - e0) / e0);
      worst_overlap = std::max(worst_overlap, deepest_overlap(st, s));
    }
    return read(*engine);
  };
  double energy1, overlap1, energy2, overlap2;
  const State a = run(energy1, overlap1);
  const State b = run(energy2, overlap2);
  // Each impulse conserves energy to a few roundings; thousands of collisions: ~1e-13.
  EXPECT_LT(energy1, 1e-10);
  // Contacts are found to the last ulps of positions of size 10: ~1e-14 m of round-off overlap.
  EXPECT_LT(overlap1, 1e-12);
  ASSERT_EQ(a.pos.size(), b.pos.size());
  EXPECT_EQ(std::memcmp(a.pos.data(), b.pos.data(), sizeof(double) * a.pos.size()), 0);
  EXPECT_EQ(std::memcmp(a.vel.data(), b.vel.data(), sizeof(double) * a.vel.size()), 0);
  note("energy_rel_drift", fmt::format("{:.3g}", energy1));
  note("deepest_overlap_m", fmt::format("{:.3g}", overlap1));
}

TEST(Exact, InelasticPileSettlesWithoutStallOrOverlap) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 3.0
gravity = [0.0, -9.81]
restitution = 0.5
[container]
min = [-1.0, 0.0]
max = [1.0, 6.0]
[random]
count = 200
radius = 0.04
pos_min = [-0.9, 1.0]
pos_max = [0.9, 5.9]
vel_min = [-0.5, -0.5]
vel_max = [0.5, 0.5]
seed = 3
)",
                              "pile.toml");
  auto engine = make_exact(s);
  double worst_overlap = 0, worst_wall = 0;
  State st;
  for (int k = 0; k < 300; ++k) {
    ASSERT_NO_THROW(engine->step(0.01)) << "at step " << k;
    st = read(*engine);
    worst_overlap = std::max(worst_overlap, deepest_overlap(st, s));
    for (int i = 0; i < st.n(); ++i) {
      worst_wall = std::max(worst_wall, s.container.min.y() - (st.pos(i, 1) - s.radius(i)));
      worst_wall = std::max(worst_wall, std::abs(st.pos(i, 0)) + s.radius(i) - 1.0);
    }
  }
  // Settling balls may creep into contact by at most 1e-9 of the radius sum (radius, for a wall)
  // before a collision stops them (EXACT.md, "Resting contact"): 8e-11 m here, 5e5 times below
  // a radius. Plus round-off of positions of size ~1.
  EXPECT_LT(worst_overlap, 1e-9 * 0.08 * (1 + 1e-6) + 1e-15);
  EXPECT_LT(worst_wall, 1e-9 * 0.04 * (1 + 1e-6) + 1e-15);
  // Settled: every ball at rest or moving slower than the rest threshold.
  double fastest = 0;
  for (int i = 0; i < st.n(); ++i) fastest = std::max(fastest, st.vel.row(i).norm());
  const double v_rest = engine->settings()["rest_velocity"].get<double>();
  EXPECT_LT(fastest, 10 * v_rest);
  note("deepest_overlap_m", fmt::format("{:.3g}", worst_overlap));
  note("fastest_at_end", fmt::format("{:.3g}", fastest));
}

TEST(Exact, RejectsUnknownSettingsAndReportsEveryKnob) {
  const Scene s = corridor(1.0);
  EXPECT_THROW(make_exact(s, {{"contact_tme", 1.0}}), InputError);
  const nlohmann::json j = make_exact(s)->settings();
  for (const char* key : {"contact_time", "rest_velocity", "sleep", "wake_velocity", "support_gap", "cell_size",
                          "max_events_per_ball"})
    EXPECT_TRUE(j.contains(key)) << key;
}

// ---- Friction and rotation (EXACT.md, "Friction") ----

// The slide-to-roll scene (scenarios/slide-to-roll.toml): a ball (r 0.25, m 1) on the floor at
// v0 = 3 m/s, friction mu = 0.5, g = 9.81, no spin. Kinetic friction mu m g decelerates it at mu g
// and spins it up at mu g / (k r) (torque r mu m g, I = k m r^2), so its slip v - (-w r) falls at
// mu g (1 + k) / k and vanishes at t_r = v0 k / ((1 + k) mu g); from there it rolls at
// v0 / (1 + k) (Goldstein, Classical Mechanics; tests/test_conformance.cpp, SlideToRoll).
void expect_slide_to_roll(Inertia inertia) {
  Scene s = load_scene("slide-to-roll");
  s.inertia = inertia;
  const double v0 = 3, mu = 0.5, g = 9.81, r = 0.25, x0 = 1, k = inertia_factor(inertia);
  const double t_r = v0 * k / ((1 + k) * mu * g), v_r = v0 / (1 + k);
  // Closed form of x, v, w and the angle at time t.
  struct Sample {
    double x, v, w, angle;
  };
  auto closed = [&](double t) {
    if (t <= t_r) return Sample{x0 + v0 * t - 0.5 * mu * g * t * t, v0 - mu * g * t, -mu * g / (k * r) * t,
                                -0.5 * mu * g / (k * r) * t * t};
    const double xr = x0 + v0 * t_r - 0.5 * mu * g * t_r * t_r, ar = -0.5 * mu * g / (k * r) * t_r * t_r;
    return Sample{xr + v_r * (t - t_r), v_r, -v_r / r, ar - v_r / r * (t - t_r)};
  };
  // Quantities of size <= 4 (x), 12 (w) computed in a few roundings each: ~1e-14; 1e-9 is the
  // issue's bound for the closed-form cases and leaves a wide margin.
  constexpr double kTol = 1e-9;
  double worst = 0, t_measured = 0;
  {
    auto engine = make_exact(s);
    double slip1 = 0, t1 = 0;
    for (int step = 1; step <= s.steps(); ++step) {
      engine->step(s.dt);
      const State st = read(*engine);
      ASSERT_TRUE(st.rotates());
      const Sample c = closed(st.t);
      worst = std::max({worst, std::abs(st.pos(0, 0) - c.x), std::abs(st.vel(0, 0) - c.v), std::abs(st.w(0) - c.w) * r,
                        std::abs(st.angle(0) - c.angle) * r});
      EXPECT_EQ(st.pos(0, 1), r);  // on the floor throughout
      EXPECT_EQ(st.vel(0, 1), 0.0);
      // The time to roll, measured from the engine's slip: linear while it slides, so two samples
      // before t_r extrapolate to its zero.
      const double slip = st.vel(0, 0) + st.w(0) * r;
      if (step == 5) slip1 = slip, t1 = st.t;
      if (step == 15) t_measured = st.t + slip * (st.t - t1) / (slip1 - slip);
      if (st.t > t_r) {
        EXPECT_NEAR(slip, 0.0, 1e-14) << "rolling: no slip, to round-off of v";
      }
    }
    const State end = read(*engine);
    EXPECT_NEAR(end.vel(0, 0), v_r, kTol);
    EXPECT_NEAR(end.pos(0, 0), closed(end.t).x, kTol);
  }
  EXPECT_LT(worst, kTol);
  EXPECT_NEAR(t_measured, t_r, kTol);
  // Stepped exactly to t_r: rolling has just begun (an error dt in the event time would show as
  // mu g dt in v); 1 ms before it still slides at v0 - mu g t.
  {
    auto engine = make_exact(s);
    engine->step(t_r);
    const State st = read(*engine);
    EXPECT_NEAR(st.vel(0, 0), v_r, kTol);
    EXPECT_NEAR(st.w(0), -v_r / r, kTol / r);
    auto early = make_exact(s);
    early->step(t_r - 1e-3);
    const State se = read(*early);
    EXPECT_NEAR(se.vel(0, 0), v0 - mu * g * (t_r - 1e-3), kTol);
    EXPECT_GT(se.vel(0, 0) + se.w(0) * r, 1e-3 * mu * g);  // slip (1 + k) / k mu g 1e-3 left
  }
  note("worst_error_m", fmt::format("{:.3g}", worst));
  note("time_to_roll_error_s", fmt::format("{:.3g}", std::abs(t_measured - t_r)));
}

TEST(ExactFriction, SlideToRollDisk) { expect_slide_to_roll(Inertia::disk); }
TEST(ExactFriction, SlideToRollSphere) { expect_slide_to_roll(Inertia::sphere); }

// The spin drop (tests/test_conformance.cpp, SpinDrop): a disk (r 0.25, m 1) from y = 1.25 over the
// floor y = 0 at v0 = (1, 0) with w0 = 20 rad/s, restitution 0, g 9.81. It lands at
// t_l = sqrt(2 h / g), h = 1, with normal speed u = g t_l. Independently of rough_impact.h: the
// contact point (0, -r) from the centre moves at c = v + w r along x; a horizontal impulse J there
// changes v by J / m and w by r J / I (torque of (J, 0) at (0, -r)), so c by J (1 + 1 / k) / m.
// Sticking takes J = -c m k / (1 + k); Coulomb allows |J| <= mu m u; beyond, J = -sgn(c) mu m u.
// Then, if c is left, kinetic friction -sgn(c) mu m g slides it until c = 0; it rolls at
// (v0 - k r w0) / (1 + k) = -1 m/s (angular momentum about the contact point).
void expect_spin_drop(double mu, bool sticks) {
  Scene s = load_scene("spin-drop");  // v0 (1, 0), w0 20 rad/s, r 0.25, m 1, dropped from 1 m, e 0
  s.friction = mu;
  const double g = 9.81, r = 0.25, m = 1, k = 0.5, I = k * m * r * r, v0 = 1, w0 = 20;
  const double t_l = std::sqrt(2 * 1.0 / g), u = g * t_l, x_l = v0 * t_l, angle_l = w0 * t_l;
  const double c = v0 + w0 * r;
  const double J_stick = -c * m * k / (1 + k), J_max = mu * m * u;
  ASSERT_EQ(std::abs(J_stick) <= J_max, sticks);
  const double J = std::abs(J_stick) <= J_max ? J_stick : -std::copysign(J_max, c);
  const double v1 = v0 + J / m, w1 = w0 + r * J / I, c1 = v1 + w1 * r;
  // Sliding after the impact: dv/dt = -sgn(c1) mu g, dw/dt = -sgn(c1) mu g r m / I, until c = 0.
  const double dv = c1 == 0 ? 0 : -std::copysign(mu * g, c1), dw = dv * r * m / I;
  const double t_s = std::abs(c1) <= 1e-12 ? 0 : -c1 / (dv + dw * r);
  const double v_roll = v1 + dv * t_s, w_roll = w1 + dw * t_s;
  auto closed_x = [&](double tau) {  // tau after the landing
    const double ts = std::min(tau, t_s);
    return x_l + v1 * ts + 0.5 * dv * ts * ts + v_roll * (tau - ts);
  };
  auto closed_angle = [&](double tau) {
    const double ts = std::min(tau, t_s);
    return angle_l + w1 * ts + 0.5 * dw * ts * ts + w_roll * (tau - ts);
  };
  EXPECT_NEAR(v_roll, (v0 - k * r * w0) / (1 + k), 1e-12);
  EXPECT_NEAR(w_roll, -v_roll / r, 1e-12);
  // Sizes up to 20 rad/s and 2 m, a few roundings each: ~1e-14; 1e-9 is the issue's bound.
  constexpr double kTol = 1e-9;
  auto engine = make_exact(s);
  const double just_after = 1e-4;
  engine->step(t_l + just_after);  // the state right after the impact
  State st = read(*engine);
  const double ta = std::min(just_after, t_s);
  EXPECT_NEAR(st.vel(0, 0), v1 + dv * ta, kTol);
  EXPECT_NEAR(st.w(0), w1 + dw * ta, kTol);
  EXPECT_NEAR(st.pos(0, 0), closed_x(just_after), kTol);
  EXPECT_EQ(st.pos(0, 1), r);
  EXPECT_EQ(st.vel(0, 1), 0.0);
  double worst = std::max(std::abs(st.vel(0, 0) - (v1 + dv * ta)), std::abs(st.w(0) - (w1 + dw * ta)) * r);
  if (t_s > 0) {  // mid-slide
    engine->step(0.5 * t_s - just_after);
    st = read(*engine);
    const double tau = st.t - t_l;
    EXPECT_NEAR(st.vel(0, 0), v1 + dv * tau, kTol);
    EXPECT_NEAR(st.w(0), w1 + dw * tau, kTol);
    EXPECT_NEAR(st.pos(0, 0), closed_x(tau), kTol);
    worst = std::max(worst, std::abs(st.pos(0, 0) - closed_x(tau)));
  }
  engine->step(2.0 - st.t);
  st = read(*engine);
  EXPECT_NEAR(st.vel(0, 0), -1.0, kTol);
  EXPECT_NEAR(st.w(0), 4.0, kTol);
  EXPECT_NEAR(st.pos(0, 0), closed_x(2.0 - t_l), kTol);
  EXPECT_NEAR(st.angle(0), closed_angle(2.0 - t_l), kTol);
  worst = std::max({worst, std::abs(st.vel(0, 0) + 1.0), std::abs(st.pos(0, 0) - closed_x(2.0 - t_l)),
                    std::abs(st.angle(0) - closed_angle(2.0 - t_l)) * r});
  note("worst_error", fmt::format("{:.3g}", worst));
  note("after_impact_v_w", fmt::format("{:.6g} {:.6g}", v1, w1));
  note("time_to_roll_after_landing_s", fmt::format("{:.6g}", t_s));
}

TEST(ExactFriction, SpinDropSlidesOffTheImpact) { expect_spin_drop(0.2, false); }
TEST(ExactFriction, SpinDropSticksAtTheImpact) { expect_spin_drop(0.8, true); }

// A rough ball on a floor tilted by gravity g = 9.81 (sin a, -cos a), a = 0.3 rad, from rest:
// with static friction enough (mu >= tan(a) k / (1 + k)) it rolls at a_t = g sin a / (1 + k);
// otherwise it slides at g (sin a - mu cos a) while friction spins it up at mu g cos a / (k r)
// (Goldstein, the rolling constraint; the incline problem).
void expect_incline(double mu, bool rolls) {
  const double a = 0.3, g = 9.81, r = 0.2, k = 0.5;
  const Scene s = parse_scene(fmt::format(R"(
dt = 0.01
duration = 1.0
gravity = [{:.17g}, {:.17g}]
restitution = 0.0
friction = {}
[container]
min = [-1.0, 0.0]
max = [20.0, 4.0]
[[ball]]
pos = [0.0, 0.2]
radius = 0.2
)",
                                          g * std::sin(a), -g * std::cos(a), mu),
                              "incline.toml");
  ASSERT_EQ(std::tan(a) * k / (1 + k) <= mu, rolls);
  const double acc = rolls ? g * std::sin(a) / (1 + k) : g * (std::sin(a) - mu * std::cos(a));
  const double spin = rolls ? -acc / r : -mu * g * std::cos(a) / (k * r);  // dw/dt
  auto engine = make_exact(s);
  double worst = 0;
  for (int step = 1; step <= 100; ++step) {
    engine->step(0.01);
    const State st = read(*engine);
    const double t = st.t;
    worst = std::max({worst, std::abs(st.pos(0, 0) - 0.5 * acc * t * t), std::abs(st.vel(0, 0) - acc * t),
                      std::abs(st.w(0) - spin * t) * r, std::abs(st.angle(0) - 0.5 * spin * t * t) * r});
    EXPECT_EQ(st.pos(0, 1), r);
  }
  // Sizes ~2 m, 100 step ends of a few roundings: ~1e-14.
  EXPECT_LT(worst, 1e-12);
  note("worst_error", fmt::format("{:.3g}", worst));
}

TEST(ExactFriction, RollsDownAnIncline) { expect_incline(0.5, true); }
TEST(ExactFriction, SlidesDownAnInclineBeyondStaticFriction) { expect_incline(0.05, false); }

// An oblique impact of two rough disks in open space, without gravity: ball 0 (r 0.3, m 1,
// w 4) comes at (-6, 0) along y = b onto ball 1 (r 0.5, m 2.5, w -7, at rest at the origin), e 0.7.
// The six velocities after it solve six linear equations (solved here with Eigen, not by the
// impulse law): linear momentum (2); each ball's angular momentum about the contact point (2);
// normal restitution (1); sticking: no slip after, or sliding: |P_t| = mu P_n against the slip (1).
void expect_rough_oblique(double mu, bool sticks) {
  const double r0 = 0.3, r1 = 0.5, m0 = 1, m1 = 2.5, e = 0.7, R = r0 + r1, b = 0.35, w0 = 4, w1 = -7, k = 0.5;
  const double I0 = k * m0 * r0 * r0, I1 = k * m1 * r1 * r1;
  const Scene s = parse_scene(fmt::format(R"(
dt = 0.01
duration = 0.5
restitution = {}
friction = {}
[[ball]]
pos = [{:.17g}, {}]
vel = [-6.0, 0.0]
spin = {}
radius = {}
mass = {}
[[ball]]
pos = [0.0, 0.0]
spin = {}
radius = {}
mass = {}
)",
                                          e, mu, std::sqrt(R * R - b * b) + 1.2, b, w0, r0, m0, w1, r1, m1),
                              "rough-oblique.toml");
  const Eigen::Vector2d n{std::sqrt(R * R - b * b) / R, b / R}, t{-n.y(), n.x()}, v0{-6, 0};
  const double slip_in = v0.dot(t) - (w0 * r0 + w1 * r1), vn_in = v0.dot(n);
  // Unknowns z = (u0x, u0y, u1x, u1y, x0, x1). With the impulse P = m0 (u0 - v0) on ball 0:
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs;
  A(0, 0) = m0, A(0, 2) = m1, rhs(0) = m0 * v0.x();  // momentum
  A(1, 1) = m0, A(1, 3) = m1, rhs(1) = m0 * v0.y();
  // Ball 0's angular momentum about the contact point (its centre at +r0 n from it):
  // I0 x0 + m0 (r0 n) x u0 = I0 w0 + m0 (r0 n) x v0; ball 1's likewise with its centre at -r1 n.
  A(2, 0) = -m0 * r0 * n.y(), A(2, 1) = m0 * r0 * n.x(), A(2, 4) = I0;
  rhs(2) = I0 * w0 + m0 * r0 * (n.x() * v0.y() - n.y() * v0.x());
  A(3, 2) = m1 * r1 * n.y(), A(3, 3) = -m1 * r1 * n.x(), A(3, 5) = I1;
  rhs(3) = I1 * w1;
  A(4, 0) = n.x(), A(4, 1) = n.y(), A(4, 2) = -n.x(), A(4, 3) = -n.y(), rhs(4) = -e * vn_in;  // restitution
  if (sticks) {  // (u0 - u1).t - (x0 r0 + x1 r1) = 0
    A(5, 0) = t.x(), A(5, 1) = t.y(), A(5, 2) = -t.x(), A(5, 3) = -t.y(), A(5, 4) = -r0, A(5, 5) = -r1, rhs(5) = 0;
  } else {  // m0 (u0 - v0).t = -sgn(slip_in) mu m0 (u0 - v0).n
    const double sg = slip_in > 0 ? 1 : -1;
    A(5, 0) = m0 * (t.x() + sg * mu * n.x()), A(5, 1) = m0 * (t.y() + sg * mu * n.y());
    rhs(5) = m0 * (t + sg * mu * n).dot(v0);
  }
  const Eigen::Matrix<double, 6, 1> z = A.fullPivLu().solve(rhs);
  // The case is what it claims: sticking within the cone, or sliding with the slip keeping its sign.
  const Eigen::Vector2d u0{z(0), z(1)}, u1{z(2), z(3)};
  const double Pn = m0 * (u0 - v0).dot(n), Pt = m0 * (u0 - v0).dot(t);
  ASSERT_GT(Pn, 0);
  if (sticks) {
    ASSERT_LE(std::abs(Pt), mu * Pn);
  } else {
    ASSERT_GE(((u0 - u1).dot(t) - (z(4) * r0 + z(5) * r1)) * slip_in, 0.0);
  }
  auto engine = make_exact(s);
  for (int step = 0; step < 50; ++step) engine->step(0.01);
  const State st = read(*engine);
  double worst = 0;
  for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(st.vel(c / 2, c % 2) - z(c)));
  worst = std::max({worst, std::abs(st.w(0) - z(4)) * r0, std::abs(st.w(1) - z(5)) * r1});
  // One impact on O(10) numbers: a few roundings; the 6x6 solve adds its own ~1e-15.
  EXPECT_LT(worst, 1e-9);
  note("worst_velocity_error", fmt::format("{:.3g}", worst));
  note("tangential_over_normal_impulse", fmt::format("{:.3g}", Pt / Pn));
}

TEST(ExactFriction, RoughObliqueImpactSticking) { expect_rough_oblique(0.9, true); }
TEST(ExactFriction, RoughObliqueImpactSliding) { expect_rough_oblique(0.1, false); }

// A rough gas in open space, no gravity: every impulse acts at a contact point, equal and
// opposite, so the angular momentum about a fixed point, orbital m (x vy - y vx) plus spin I w, is
// conserved to round-off at any friction and restitution, and the kinetic energy with (1/2) I w^2
// never grows (the impact law only takes energy).
void expect_rough_gas(double e) {
  const Scene s = rough_gas::scene(e);
  auto engine = make_exact(s);
  double scale0;
  const State start = read(*engine);
  const double L0 = rough_gas::angular_momentum(s, start, &scale0), E0 = rough_gas::kinetic_energy(s, start);
  double worst_L = 0, worst_gain = 0, E_end = E0;
  for (long step = 0; step < s.steps(); ++step) {
    engine->step(s.dt);
    const State st = read(*engine);
    worst_L = std::max(worst_L, std::abs(rough_gas::angular_momentum(s, st) - L0) / scale0);
    E_end = rough_gas::kinetic_energy(s, st);
    worst_gain = std::max(worst_gain, (E_end - E0) / E0);
  }
  // Each impulse moves L by a few roundings of terms of size ~scale / n: hundreds of impacts give
  // ~1e-15 of scale0.
  EXPECT_LT(worst_L, 1e-12);
  // Never above the start beyond round-off of a sum of 200 terms.
  EXPECT_LT(worst_gain, 1e-13);
  EXPECT_LT(E_end, E0);  // friction took some (sliding and sticking impacts both do)
  note("angular_momentum_rel_drift", fmt::format("{:.3g}", worst_L));
  note("energy_largest_gain_rel", fmt::format("{:.3g}", worst_gain));
  note("energy_lost_rel", fmt::format("{:.3g}", (E0 - E_end) / E0));
}

TEST(ExactFriction, RoughElasticGasKeepsAngularMomentum) { expect_rough_gas(1.0); }
TEST(ExactFriction, RoughInelasticGasKeepsAngularMomentum) { expect_rough_gas(0.9); }

// Spin without friction: no impact has a tangential impulse, so every w stays as it started and
// each angle is w0 t, through wall and ball impacts (a frictionless box under gravity).
TEST(ExactFriction, SpinWithoutFrictionIsUntouched) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 2.0
gravity = [0.0, -9.81]
restitution = 0.8
[container]
min = [-2.0, 0.0]
max = [2.0, 4.0]
[random]
count = 40
radius = 0.1
vel_min = [-2.0, -2.0]
vel_max = [2.0, 2.0]
spin_min = -10.0
spin_max = 10.0
seed = 2
)",
                              "spinning-box.toml");
  auto engine = make_exact(s);
  for (int step = 0; step < 200; ++step) engine->step(0.01);
  const State st = read(*engine);
  double worst = 0;
  for (int i = 0; i < st.n(); ++i) {
    EXPECT_EQ(st.w(i), s.spin(i));
    worst = std::max(worst, std::abs(st.angle(i) - s.spin(i) * st.t));
  }
  // The angle is summed over each ball's events (~100s): a few roundings of numbers up to 20 rad.
  EXPECT_LT(worst, 1e-12);
  note("angle_error_rad", fmt::format("{:.3g}", worst));
}

// A rough ball that rolls into a wall with restitution 0 is thrown up along it (the wall's friction
// stops its contact point) and lands in the corner, where the floor's friction drives it into the
// wall: two rough contacts at once, with no closed form. The run fails with that reason.
TEST(ExactFriction, ACornerWithFrictionFailsWithTheReason) {
  Scene s = load_scene("slide-to-roll");
  auto engine = make_exact(s);
  try {
    for (int step = 0; step < 1000; ++step) engine->step(0.01);  // reaches the wall at x = 9.75 after ~4.4 s
    ADD_FAILURE() << "expected a failure at the corner";
  } catch (const std::runtime_error& err) {
    EXPECT_NE(std::string(err.what()).find("corner"), std::string::npos) << err.what();
    note("failure", err.what());
  }
}

// Where exact has no closed form it refuses the scene before building anything.
TEST(ExactFriction, RefusesRoughBallsUnderGravity) {
  const EngineEntry& entry = find_engine("exact");
  EXPECT_TRUE(entry.info.caps.friction);
  const Scene pile = load_scene("rough-box");  // 40 rough balls falling in a box
  const std::string why = unsupported_reason(entry.info, pile);
  EXPECT_NE(why.find("no closed form"), std::string::npos) << why;
  EXPECT_THROW(make_exact(pile), SceneUnsupported);
  // One rough ball under gravity, and rough balls without it, are closed-form.
  EXPECT_EQ(unsupported_reason(entry.info, load_scene("slide-to-roll")), "");
  Scene weightless = pile;
  weightless.gravity.setZero();
  EXPECT_EQ(unsupported_reason(entry.info, weightless), "");
  note("reason", why);
}

}  // namespace
}  // namespace ballbench

// The event-driven reference solver `exact` against closed-form answers: binary impacts (thesis
// eq. 11-12), wall bounces, free flight under gravity, a bouncing ball's peaks, Newton's cradle,
// and the invariants of a gas and a pile (energy, no overlap, bit-for-bit reproducibility).
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "input_error.h"
#include "overlap.h"
#include "registry.h"
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

}  // namespace
}  // namespace ballbench

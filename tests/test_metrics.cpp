// Metrics on hand-made state sequences with known answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "metrics/energy.h"
#include "metrics/momentum.h"
#include "metrics/meter_set.h"
#include "metrics/tunnelling.h"
#include "overlap.h"
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
  MeterSet m(s, {});
  m.sample(s.initial);  // P0 = (2, -12)
  m.sample(state({-1, 0, 1, 1}, {2, 0, 0, -3}));  // P = (2, -9): drift 3
  m.sample(state({-1, 0, 1, 1}, {2, 0, 0, -4}));  // back to P0
  EXPECT_DOUBLE_EQ(m.values().value(Metric::momentum_max_abs_drift), 3.0);
  EXPECT_DOUBLE_EQ(m.values().vec(Metric::momentum_final).y(), -12.0);
}

// Steps through `states` as the runner does: the motion of every step, then the sample.
void feed(MeterSet& m, const std::vector<State>& states) {
  for (size_t k = 0; k < states.size(); ++k) {
    if (k > 0) m.motion(states[k - 1], states[k]);
    m.sample(states[k]);
  }
}

// two_balls() with friction (so it rotates) and the given inertia; spins 4 and -2 rad/s.
Scene two_rough_balls(const char* inertia) {
  Scene s = two_balls();
  s.friction = 0.5;
  s.inertia = inertia == std::string("sphere") ? Inertia::sphere : Inertia::disk;
  s.initial.resize(2, true);
  s.initial.pos = two_balls().initial.pos, s.initial.vel = two_balls().initial.vel;
  s.initial.w << 4.0, -2.0;
  s.initial.angle.setZero();
  return s;
}

TEST(Energy, CountsRotationWithTheScenesInertia) {
  for (const char* inertia : {"disk", "sphere"}) {
    const Scene s = two_rough_balls(inertia);
    const double k = inertia == std::string("sphere") ? 0.4 : 0.5;
    // I w^2 / 2 = k m r^2 w^2 / 2: 1 * 0.0625 * 16 and 3 * 0.0625 * 4, halved, times k.
    const double rotation = 0.5 * k * (0.0625 * 16 + 3 * 0.0625 * 4);
    EXPECT_DOUBLE_EQ(kinetic_energy(s.initial, s), 26.0 + rotation) << inertia;
    EXPECT_DOUBLE_EQ(total_energy(s.initial, s, energy_reference(s)), 256.0 + rotation) << inertia;
  }
}

TEST(AngularMomentum, IsOrbitalPlusSpinAboutTheBoxCentre) {
  const Scene s = two_rough_balls("disk");
  // About (0, 0): (x vy - y vx) m = (-1 * 0 - 0 * 2) * 1 + (1 * -4 - 1 * 0) * 3 = -12;
  // spin k m r^2 w = 0.5 * 0.0625 * (1 * 4 + 3 * -2) = -0.0625.
  MeterSet m(s, {});
  m.sample(s.initial);
  EXPECT_EQ(m.values().vec(Metric::angular_momentum_centre), Eigen::Vector2d(0, 0));
  EXPECT_DOUBLE_EQ(m.values().value(Metric::angular_momentum_initial), -12.0625);
  // Spin traded for orbit at the same total: no drift; then a change of 1 is one.
  State t = s.initial;
  t.vel(0, 1) = 0.0625;  // ball 0 at x = -1: x vy m = -0.0625, what the spins held
  t.w.setZero();
  m.sample(t);
  EXPECT_NEAR(m.values().value(Metric::angular_momentum_max_abs_drift), 0.0, 1e-15);
  t.vel(1, 0) = -1.0;  // - y vx m = -1 * -1 * 3 = +3
  m.sample(t);
  EXPECT_NEAR(m.values().value(Metric::angular_momentum_max_abs_drift), 3.0, 1e-12);
  EXPECT_NEAR(m.values().value(Metric::angular_momentum_final), -9.0625, 1e-12);
}

TEST(Slip, IsZeroForARollingBallAndTimesTheRoll) {
  Scene s = two_rough_balls("disk");
  s.initial.pos.row(0) << 0.0, -4.75;  // on the floor
  s.initial.pos.row(1) << 4.75, 0.0;   // on the right wall
  MeterSet m(s, {});
  State a = s.initial;
  a.vel.row(0) << 2.0, 0.0, a.vel.row(1) << 0.0, 1.0;
  a.w << -8.0 + 0.4, 4.0;  // floor: |-vx - w r| = |-2 + 1.9| = 0.1; right wall: |-vy - w r| = |-1 - 1| = 2
  m.sample(a);
  EXPECT_TRUE(m.values().has(Metric::slip_final_max));
  EXPECT_NEAR(m.values().value(Metric::slip_final_max), 2.0, 1e-12);
  EXPECT_FALSE(m.values().number(Metric::slip_time_to_roll));
  a.t = 0.5, a.w << -8.0, -4.0;  // both roll: floor -2 + 2, wall -1 + 1
  m.sample(a);
  EXPECT_EQ(m.values().value(Metric::slip_final_max), 0.0);
  ASSERT_TRUE(m.values().number(Metric::slip_time_to_roll));
  EXPECT_EQ(*m.values().number(Metric::slip_time_to_roll), 0.5);
  a.t = 0.6, a.pos(1, 0) = 0.0;  // ball 1 leaves the wall: its spin no longer counts
  a.w(1) = 100.0;
  m.sample(a);
  EXPECT_EQ(*m.values().number(Metric::slip_time_to_roll), 0.5);
  a.t = 0.7, a.w(0) = 0.0;  // the floor ball slips again: not rolling
  m.sample(a);
  EXPECT_FALSE(m.values().number(Metric::slip_time_to_roll));
  // A scene that does not rotate measures none.
  const Scene still = two_balls();  // the accumulator keeps a reference to its scene
  MeterSet plain(still, {});
  plain.sample(still.initial);
  EXPECT_FALSE(plain.values().has(Metric::slip_final_max));
}

TEST(Tunnelling, AnInjectedWallEscapeCountsOne) {
  const Scene s = two_balls();
  MeterSet m(s, {});
  feed(m, {s.initial, state({-1, 0, 1, -4.9}, {0, 0, 0, 0}),
           state({-1, 0, 1, -5.2}, {0, 0, 0, 0}),    // centre beyond the floor
           state({-1, 0, 1, -5.3}, {0, 0, 0, 0})});  // still beyond: the same escape
  EXPECT_EQ(m.values().count(Metric::tunnelling_wall), 1);
}

TEST(Tunnelling, AnInjectedPassThroughCountsOne) {
  const Scene s = two_balls();
  MeterSet m(s, {});
  // Swapped places without ever overlapping in a sample.
  feed(m, {state({-1, 0, 1, 0}, {0, 0, 0, 0}), state({1, 0, -1, 0}, {0, 0, 0, 0})});
  EXPECT_EQ(m.values().count(Metric::tunnelling_pair), 1);
  EXPECT_EQ(m.values().count(Metric::sticking_pair), 0);
}

TEST(Tunnelling, OnlyTheMotionCounts) {
  // The same two samples fed as samples only (no motion between them): nothing to judge.
  const Scene s = two_balls();
  MeterSet m(s, {});
  m.sample(state({-1, 0, 1, 0}, {0, 0, 0, 0}));
  m.sample(state({1, 0, -1, 0}, {0, 0, 0, 0}));
  EXPECT_EQ(m.values().count(Metric::tunnelling_pair), 0);
}

TEST(Tunnelling, AResolvedBounceDoesNotCount) {
  // Relative motion reflected at the contact point: both samples on the outer side of the tangent.
  EXPECT_GE(closest_approach({-0.6, 0.3}, {-0.6, 0.35}), 0.5);
  const Scene s = two_balls();
  MeterSet m(s, {});
  feed(m, {state({-0.6, 0, 0, 0.3}, {0, 0, 0, 0}), state({-0.6, 0, 0, 0.35}, {0, 0, 0, 0})});
  EXPECT_EQ(m.values().count(Metric::tunnelling_pair), 0);
}

TEST(Tunnelling, TheSearchSkipsNoPassThroughThatCounts) {
  // Balls moving less than a chord through the contact circle (2 s (r_i + r_j), s = sqrt(1 - 0.98^2))
  // are not searched. The tightest pass that counts: apart by a hair more than r_i + r_j in both
  // samples, closest approach just inside 98% of it, so its travel is barely above that chord.
  const Scene s = two_balls();  // radius 0.25 each: rs = 0.5
  const double rs = 0.5, b = 0.979 * rs, half = 1.0001 * std::sqrt(rs * rs - b * b);  // d: (-half, b) -> (half, b)
  MeterSet m(s, {});
  feed(m, {state({-half / 2, b / 2, half / 2, -b / 2}, {0, 0, 0, 0}),
           state({half / 2, b / 2, -half / 2, -b / 2}, {0, 0, 0, 0})});
  EXPECT_EQ(m.values().count(Metric::tunnelling_pair), 1);
  // The same pass just outside 98%: not counted.
  MeterSet wide(s, {});
  const double b2 = 0.981 * rs, half2 = 1.0001 * std::sqrt(rs * rs - b2 * b2);
  feed(wide, {state({-half2 / 2, b2 / 2, half2 / 2, -b2 / 2}, {0, 0, 0, 0}),
              state({half2 / 2, b2 / 2, -half2 / 2, -b2 / 2}, {0, 0, 0, 0})});
  EXPECT_EQ(wide.values().count(Metric::tunnelling_pair), 0);
}

// The definition of tunnelling.h (passes_through) over every pair: the reference the search must
// match exactly. (The definition itself is checked on hand-made motions above.)
// Pairs whose steps' bounding boxes are more than twice their radius sum apart on an axis are
// skipped: their chords stay farther apart than (1 - tolerance) (r_i + r_j) for any tolerance
// above -1, so they cannot count (the tests use -0.05 .. 0.3). This keeps the O(n^2) reference
// quick under the sanitizers.
// The pairs (i < j, ordered by i then j) that pass through each other.
std::vector<std::array<int, 2>> brute_force_pairs(const State& prev, const State& cur, const Eigen::VectorXd& radius,
                                                  double tolerance) {
  EXPECT_GT(tolerance, -1.0);
  const auto apart = [&](int i, int j, int axis, double gap) {
    const double lo_i = std::min(prev.pos(i, axis), cur.pos(i, axis)), hi_i = std::max(prev.pos(i, axis), cur.pos(i, axis));
    const double lo_j = std::min(prev.pos(j, axis), cur.pos(j, axis)), hi_j = std::max(prev.pos(j, axis), cur.pos(j, axis));
    return lo_i - hi_j > gap || lo_j - hi_i > gap;
  };
  std::vector<std::array<int, 2>> pairs;
  for (int i = 0; i < cur.n(); ++i)
    for (int j = i + 1; j < cur.n(); ++j) {
      const double rs = radius(i) + radius(j);
      if (apart(i, j, 0, 2 * rs) || apart(i, j, 1, 2 * rs)) continue;
      if (passes_through(prev, cur, i, j, rs, tolerance)) pairs.push_back({i, j});
    }
  return pairs;
}

int brute_force_passthroughs(const State& prev, const State& cur, const Eigen::VectorXd& radius, double tolerance) {
  return static_cast<int>(brute_force_pairs(prev, cur, radius, tolerance).size());
}

// Random motion that puts every branch of the search to work: unequal radii, balls kicked to high
// speed (escaping their allowance), teleports inside and far outside the box, balls thrown through
// a neighbour (pass-throughs that count), and some leaving the box.
class RandomMotion {
 public:
  RandomMotion(int n, unsigned seed) : rng_(seed), radius_(n) {
    std::uniform_real_distribution<double> r(0.05, 0.3), v(-5.0, 5.0);
    half_ = 0.6 * std::sqrt(static_cast<double>(n));
    box_.kind = ContainerKind::Box, box_.min = {-half_, -half_}, box_.max = {half_, half_};
    std::uniform_real_distribution<double> x(-half_, half_);
    state_.resize(n);
    for (int i = 0; i < n; ++i) {
      radius_(i) = r(rng_);
      state_.pos(i, 0) = x(rng_), state_.pos(i, 1) = x(rng_);
      state_.vel(i, 0) = v(rng_), state_.vel(i, 1) = v(rng_);
    }
  }
  const Eigen::VectorXd& radius() const { return radius_; }
  const Container& box() const { return box_; }
  const State& state() const { return state_; }

  // The next sample, dt = 0.01 later.
  const State& step() {
    const int n = state_.n();
    const State prev = state_;
    std::uniform_real_distribution<double> u(0.0, 1.0), v(-5.0, 5.0), x(-half_, half_);
    std::uniform_int_distribution<int> ball(0, n - 1);
    for (int i = 0; i < n; ++i) {
      if (u(rng_) < 0.02) state_.vel(i, 0) = 30 * v(rng_), state_.vel(i, 1) = 30 * v(rng_);  // kicked hard
      if (u(rng_) < 0.02) state_.vel(i, 0) = v(rng_), state_.vel(i, 1) = v(rng_);           // calmed
    }
    state_.pos += 0.01 * state_.vel;
    state_.t += 0.01;
    for (int k = 0; k < std::max(1, n / 100); ++k) {  // teleports, a few far outside the box
      const int i = ball(rng_);
      const double far = u(rng_) < 0.2 ? 50.0 : 1.0;
      state_.pos(i, 0) = far * x(rng_), state_.pos(i, 1) = far * x(rng_);
    }
    for (int k = 0; k < std::max(2, n / 30); ++k) {  // thrown through a neighbour: mirrored across it
      const int i = ball(rng_), j = ball(rng_);
      if (i == j) continue;
      const Eigen::Vector2d side = Eigen::Vector2d(v(rng_), v(rng_)).normalized();
      const double rs = radius_(i) + radius_(j), off = rs * u(rng_);
      const Eigen::Vector2d across(-side.y(), side.x());
      const Eigen::Vector2d pj = prev.pos.row(j).transpose();
      state_.pos.row(i) = (pj + (1.1 + u(rng_)) * rs * side + off * across).transpose();
      state_.pos.row(j) = pj.transpose();
      // Its previous sample was on the other side: rewrite it in the history we hand out.
      history_fix_.push_back({i, pj - (1.1 + u(rng_)) * rs * side + off * across});
    }
    return state_;
  }
  // Throws prepare the previous sample too: apply them to a copy of it.
  State previous_with_throws(const State& prev) {
    State p = prev;
    for (const auto& f : history_fix_) p.pos.row(f.first) = f.second.transpose();
    history_fix_.clear();
    return p;
  }

 private:
  std::mt19937 rng_;
  Eigen::VectorXd radius_;
  Container box_;
  double half_ = 1;
  State state_;
  std::vector<std::pair<int, Eigen::Vector2d>> history_fix_;
};

TEST(Overlaps, EveryOverlappingPairInTheGridsOrder) {
  // 600 balls of radii 0.1 - 0.5 dropped at random into a 12 x 12 square: hundreds of overlaps,
  // some of them between balls of very different sizes (the grid's cell is set by the largest).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> at(-6, 6), size(0.1, 0.5);
  const int n = 600;
  Eigen::MatrixX2d pos(n, 2);
  Eigen::VectorXd radius(n);
  for (int i = 0; i < n; ++i) pos(i, 0) = at(rng), pos(i, 1) = at(rng), radius(i) = size(rng);
  OverlapScratch scratch;
  std::vector<Overlap> found;
  overlapping_pairs(pos, radius, scratch, found);
  std::vector<Overlap> want;  // brute force, in the order the grid visits candidate pairs
  scratch.grid.for_each_candidate_pair([&](int i, int j) {
    const double d = (pos.row(i) - pos.row(j)).norm(), rs = radius(i) + radius(j);
    if (d < rs) want.push_back({std::min(i, j), std::max(i, j), rs - d});
  });
  int brute = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) brute += (pos.row(i) - pos.row(j)).norm() < radius(i) + radius(j);
  EXPECT_GT(brute, 300);
  ASSERT_EQ(static_cast<int>(found.size()), brute);
  ASSERT_EQ(found.size(), want.size());
  // Depths: the same distance through Eigen's norm here; 1e-12 m is a thousand ulps of the
  // coordinates (|x| < 6 m, ulp ~1e-15 m), so only a wrong pair or formula can miss it.
  for (size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(found[k].i, want[k].i) << k;
    EXPECT_EQ(found[k].j, want[k].j) << k;
    EXPECT_NEAR(found[k].depth, want[k].depth, 1e-12) << k;
  }
  // The scratch is reused: a second, smaller call finds the same as a fresh one.
  const Eigen::MatrixX2d few = pos.topRows(50);
  const Eigen::VectorXd few_r = radius.head(50);
  std::vector<Overlap> again, fresh;
  overlapping_pairs(few, few_r, scratch, again);
  OverlapScratch other;
  overlapping_pairs(few, few_r, other, fresh);
  ASSERT_EQ(again.size(), fresh.size());
  for (size_t k = 0; k < again.size(); ++k) {
    EXPECT_EQ(again[k].i, fresh[k].i);
    EXPECT_EQ(again[k].j, fresh[k].j);
  }
}

TEST(Tunnelling, TheListedSearchCountsExactlyTheBruteForcePassThroughs) {
  struct Tuning {
    double allowance_radii, rebuild_share;
  };
  // The default; a tiny allowance (most balls escape, rebuilds often); never rebuilt (escaped balls
  // pile up and are searched among themselves on a grid); a huge allowance (long list).
  const Tuning tunings[] = {{3.0, 0.1}, {0.2, 0.02}, {0.2, 2.0}, {10.0, 0.1}};
  // One motion, its steps and their brute-force counts made once and checked under every setting.
  constexpr int kSteps = 120;
  RandomMotion motion(300, 7);
  std::vector<std::pair<State, State>> steps;  // (the sample before, with throws; the sample after)
  State prev = motion.state();
  for (int k = 1; k <= kSteps; ++k) {
    const State cur = motion.step();
    steps.emplace_back(motion.previous_with_throws(prev), cur);
    prev = cur;
  }
  long total = 0;
  for (const double tolerance : {0.02, 0.0, 0.3, -0.05}) {
    std::vector<int> want_pair, want_wall;
    std::vector<std::vector<std::array<int, 2>>> want_pairs;  // which pairs, for the events
    for (const auto& [before, after] : steps) {
      want_pairs.push_back(brute_force_pairs(before, after, motion.radius(), tolerance));
      want_pair.push_back(static_cast<int>(want_pairs.back().size()));
      want_wall.push_back(wall_escapes(before, after, motion.box()));
      total += want_pair.back();
    }
    // One part, and three (each with its share of the balls, the grid's rows and the list).
    for (const int threads : {1, 3})
      for (const Tuning& tuning : tunings) {
        TunnellingCheck check(motion.radius(), motion.box(), tolerance, threads);
        check.set_tuning(tuning.allowance_radii, tuning.rebuild_share);
        for (int k = 0; k < kSteps; ++k) {
          const StepTunnelling got = check.step(steps[k].first, steps[k].second);
          ASSERT_TRUE(got.finite);
          ASSERT_EQ(got.pair, want_pair[k]) << threads << " parts, step " << k + 1 << ", tolerance " << tolerance
                                            << ", allowance " << tuning.allowance_radii << ", rebuild share "
                                            << tuning.rebuild_share;
          ASSERT_EQ(got.wall, want_wall[k]) << "step " << k + 1;
          // The events: the same pairs in the same order on any number of parts, and the balls
          // that escaped.
          ASSERT_EQ(check.pair_hits(), want_pairs[k]) << threads << " parts, step " << k + 1;
          ASSERT_EQ(check.wall_hits().size(), static_cast<size_t>(want_wall[k])) << "step " << k + 1;
          for (int i : check.wall_hits())
            ASSERT_TRUE(!beyond_wall(steps[k].first.pos.row(i).transpose(), motion.box()) &&
                        beyond_wall(steps[k].second.pos.row(i).transpose(), motion.box()));
        }
        if (tuning.rebuild_share < 1) {
          EXPECT_GT(check.rebuilds(), 2) << "the list was never rebuilt";
        }
      }
  }
  EXPECT_GT(total, 2000);  // the comparison saw many pass-throughs that count (10 817 when written)
}

TEST(Tunnelling, ATeleportThroughARowOfBallsIsCaughtWithoutARebuild) {
  // A 30 x 30 lattice (spacing 1, radius 0.25) gliding together at 12 m/s (no relative motion),
  // and one more ball beside it that jumps across row 10 in one step: 30 pass-throughs.
  const int side = 30, n = side * side + 1;
  Eigen::VectorXd radius = Eigen::VectorXd::Constant(n, 0.25);
  Container box;
  box.kind = ContainerKind::Box, box.min = {-100, -100}, box.max = {100, 100};
  State s;
  s.resize(n);
  for (int i = 0; i < side * side; ++i) s.pos(i, 0) = i % side, s.pos(i, 1) = i / side;
  s.pos(n - 1, 0) = -3, s.pos(n - 1, 1) = 10;
  s.vel.col(0).setConstant(12.0), s.vel.col(1).setZero();
  TunnellingCheck check(radius, box, 0.02);
  for (int k = 0; k < 5; ++k) {
    State next = s;
    next.pos.col(0).array() += 0.12, next.t += 0.01;
    EXPECT_EQ(check.step(s, next).pair, 0);
    s = next;
  }
  EXPECT_EQ(check.rebuilds(), 1);
  State jump = s;
  jump.pos.col(0).array() += 0.12, jump.t += 0.01;
  jump.pos(n - 1, 0) = 40;
  EXPECT_EQ(brute_force_passthroughs(s, jump, radius, 0.02), side);
  EXPECT_EQ(check.step(s, jump).pair, side);
  EXPECT_EQ(check.rebuilds(), 1);  // caught by the search of escaped balls, on the same list
}

TEST(Tunnelling, APassAtTheEdgeOfBothAllowancesIsListed) {
  // Radius 0.25 (rs 0.5), default allowance a = 3 r = 0.75: pairs with references closer than
  // rs + 2 a = 2 are listed. Balls 0 and 1, references 1.955 apart (just listed), each step up to
  // 0.744 from its reference (contained) and pass 0.475 apart: the tightest pass the list must hold.
  const int n = 23;
  Eigen::VectorXd radius = Eigen::VectorXd::Constant(n, 0.25);
  Container box;  // open space
  State s;
  s.resize(n);
  s.vel.setZero();
  for (int i = 2; i < n; ++i) s.pos(i, 0) = 100 + 3 * i, s.pos(i, 1) = 50;  // far away
  s.pos(0, 0) = 0, s.pos(0, 1) = 0, s.pos(1, 0) = 1.955, s.pos(1, 1) = 0;
  TunnellingCheck check(radius, box, 0.02);
  auto next = [&](double x0, double y0, double x1, double y1, double driver) {
    State t = s;
    t.t += 0.01;
    t.pos(0, 0) = x0, t.pos(0, 1) = y0, t.pos(1, 0) = x1, t.pos(1, 1) = y1, t.pos(2, 0) += driver;
    const int want = brute_force_passthroughs(s, t, radius, 0.02);
    const int got = check.step(s, t).pair;
    s = t;
    EXPECT_EQ(got, want);
    return got;
  };
  EXPECT_EQ(next(0, 0, 1.955, 0, 1.0), 0);  // ball 2 moves: the list is built, references here
  EXPECT_EQ(next(0.74, -0.08, 1.215, 0.08, 0), 0);
  EXPECT_EQ(next(0.74, 0.08, 1.215, -0.08, 0), 1);  // relative path (-0.475, -0.16) -> (-0.475, 0.16)
  EXPECT_EQ(check.rebuilds(), 1);
}

TEST(Tunnelling, ANonFiniteStateCountsNothing) {
  const Scene s = two_balls();
  MeterSet m(s, {});
  // Ball 1 leaves through the floor and ball 0's velocity turns NaN in the same step.
  const State before = state({-1, 0, 1, -4.9}, {0, 0, 0, 0});
  State after = state({-1, 0, 1, -5.2}, {0, 0, 0, 0});
  const std::string non_finite = "non-finite position or velocity";  // the run stops there
  m.motion(before, before);
  EXPECT_FALSE(m.stop_after_motion());
  after.vel(0, 1) = std::nan("");
  m.motion(before, after);
  EXPECT_EQ(m.stop_after_motion(), non_finite);
  after.vel(0, 1) = 0, after.pos(1, 0) = std::numeric_limits<double>::infinity();
  m.motion(before, after);
  EXPECT_EQ(m.stop_after_motion(), non_finite);
  EXPECT_EQ(m.values().count(Metric::tunnelling_wall), 0);
  // On two parts (one ball each): an escape in each part counts twice, a NaN in the first part
  // makes the whole step non-finite.
  TunnellingCheck check(s.radius, s.container, 0.02, 2);
  after = state({-1, -5.3, 1, -5.2}, {0, 0, 0, 0});
  EXPECT_EQ(check.step(before, after).wall, 2);
  after.vel(0, 0) = std::nan("");
  EXPECT_FALSE(check.step(before, after).finite);
}

TEST(Sticking, APairHeldOverlappingKPlusOneSamplesCountsOne) {
  const Scene s = two_balls();
  MetricsConfig cfg;
  cfg.stuck_samples = 3;
  MeterSet m(s, cfg);
  m.sample(s.initial);
  const State overlapping = state({0, 0, 0.4, 0}, {0, 0, 0, 0});  // depth 0.1 = 20% of the radius sum
  for (int k = 0; k < cfg.stuck_samples; ++k) m.sample(overlapping);
  EXPECT_EQ(m.values().count(Metric::sticking_pair), 0);  // K samples: not yet stuck
  m.sample(overlapping);
  EXPECT_EQ(m.values().count(Metric::sticking_pair), 1);
  for (int k = 0; k < 5; ++k) m.sample(overlapping);
  EXPECT_EQ(m.values().count(Metric::sticking_pair), 1);  // the same episode
  m.sample(s.initial);
  for (int k = 0; k <= cfg.stuck_samples; ++k) m.sample(overlapping);
  EXPECT_EQ(m.values().count(Metric::sticking_pair), 2);  // a new episode
}

TEST(Sticking, ABallHeldInAWallCountsOne) {
  const Scene s = two_balls();
  MetricsConfig cfg;
  cfg.stuck_samples = 2;
  MeterSet m(s, cfg);
  m.sample(s.initial);
  for (int k = 0; k < 3; ++k) m.sample(state({-4.9, 0, 1, 1}, {0, 0, 0, 0}));  // 0.15 deep in the left wall
  EXPECT_EQ(m.values().count(Metric::sticking_wall), 1);
}

TEST(Penetration, MaxAndMeanAreRelativeToTheRadius) {
  const Scene s = two_balls();
  MeterSet m(s, {});
  m.sample(state({0, 0, 0.45, 0}, {0, 0, 0, 0}));   // depth 0.05 -> 0.2
  m.sample(state({0, 0, 0.4, 0}, {0, 0, 0, 0}));    // depth 0.1 -> 0.4
  EXPECT_NEAR(m.values().value(Metric::penetration_max), 0.4, 1e-12);
  EXPECT_NEAR(m.values().value(Metric::penetration_mean), 0.3, 1e-12);
}

TEST(Divergence, EnergyFarAboveTheStartIsABlowUp) {
  const Scene s = two_balls();
  MeterSet m(s, {});
  m.sample(s.initial);
  EXPECT_FALSE(m.stop_after_sample().has_value());
  m.sample(state({-1, 0, 1, 1}, {1e3, 0, 0, 0}));
  EXPECT_TRUE(m.stop_after_sample().has_value());
}

}  // namespace
}  // namespace ballbench

// The home solver's scene-wide shortcuts (HomeShortcuts, core/solver/home.h) and its other speed
// choices change how fast it runs, never what it computes: each is run against the general path on
// the same scene and must give the same positions and velocities. The shortcuts and threading are
// exact by construction (same operations on the same numbers), so the comparison is exact;
// renumbering the balls reorders the contact solve and simultaneous events, so it is compared on
// an elastic gas within round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include <fmt/format.h>

#include "scene_loader.h"
#include "solver/home.h"

namespace ballbench {
namespace {

// n equal balls in a box of area 5 n, like the benchmark's gas; `extra` is appended to the TOML
// (gravity, restitution, another container).
Scene gas(int n, const std::string& extra = "", const std::string& container = "") {
  const double half = 0.5 * std::sqrt(5.0 * n);
  const std::string box =
      container.empty() ? fmt::format("[container]\nmin = [{0}, {0}]\nmax = [{1}, {1}]\n", -half, half) : container;
  return parse_scene(fmt::format(R"(
name = "gas"
dt = 0.01
duration = 1.0
{0}
{1}
[random]
count = {2}
radius = 0.25
pos_min = [{3}, {3}]
pos_max = [{4}, {4}]
vel_min = [-12.5, -12.5]
vel_max = [12.5, 12.5]
seed = 3
)",
                                 extra, box, n, -half + 0.3, half - 0.3),
                     "gas");
}

// The same balls, with every other one twice as large and twice as heavy.
Scene mixed(Scene s) {
  for (int i = 0; i < s.n(); i += 2) s.radius(i) *= 1.2, s.mass(i) *= 2.0;
  return s;
}

State run(const Scene& scene, const HomeSettings& settings, int steps) {
  std::unique_ptr<Engine> e = make_home(scene, settings);
  for (int k = 0; k < steps; ++k) e->step(scene.dt);
  State s;
  e->read(s);
  return s;
}

HomeSettings general() {
  HomeSettings s;
  s.allow = HomeShortcuts{false, false, false, false, false, false};
  return s;
}

// Exactly equal (== on doubles, so 0 and -0 agree: the general path adds a zero kick, which turns
// a -0 velocity into +0).
void expect_same(const State& a, const State& b) {
  ASSERT_EQ(a.n(), b.n());
  int differ = 0;
  for (int i = 0; i < a.n(); ++i)
    for (int k = 0; k < 2; ++k) differ += a.pos(i, k) != b.pos(i, k) || a.vel(i, k) != b.vel(i, k);
  EXPECT_EQ(differ, 0) << "of " << 4 * a.n() << " coordinates";
}

struct Case {
  const char* name;
  bool HomeShortcuts::*field;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class HomeShortcut : public ::testing::TestWithParam<Case> {};

// Each shortcut alone off, on a scene that allows it, and every shortcut off, against all on.
TEST_P(HomeShortcut, GivesTheGeneralPathsResults) {
  const Case c = GetParam();
  const std::string name = c.name;
  Scene scene = gas(600, "restitution = 1.0");
  if (name == "no_walls") scene = gas(600, "restitution = 1.0", "[container]\nkind = \"none\"\n");
  if (name == "no_pairs") scene = gas(1, "restitution = 1.0");
  HomeSettings off;
  off.allow.*c.field = false;
  const State fast = run(scene, {}, 200);
  expect_same(fast, run(scene, off, 200));
  expect_same(fast, run(scene, general(), 200));
}

INSTANTIATE_TEST_SUITE_P(Home, HomeShortcut,
                         ::testing::Values(Case{"no_gravity", &HomeShortcuts::no_gravity},
                                           Case{"no_walls", &HomeShortcuts::no_walls},
                                           Case{"equal_radii", &HomeShortcuts::equal_radii},
                                           Case{"equal_masses", &HomeShortcuts::equal_masses},
                                           Case{"no_pairs", &HomeShortcuts::no_pairs},
                                           Case{"elastic", &HomeShortcuts::elastic}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// The elastic shortcut on the one case where the contact pass acts in an elastic scene without
// gravity: a pair that touches and approaches at the start of a step (and a ball touching a wall,
// moving into it). The general path bounces them in the contact solve, the shortcut as events at
// t = 0 of the step: the same impulse, computed in another order, so equal within round-off
// (measured: identical after one step, 3.2e-14 m apart after 100, positions of a few metres; the
// bound leaves 30x room).
TEST(HomeShortcuts, ElasticBouncesTouchingPairsAsTheContactSolveDoes) {
  const Scene scene = parse_scene(R"(
name = "touching"
dt = 0.01
duration = 1.0
restitution = 1.0
[container]
min = [-3.0, -3.0]
max = [3.0, 3.0]
[[ball]]
pos = [-0.25, 0.0]
vel = [2.0, 0.3]
radius = 0.25
[[ball]]
pos = [0.25, 0.0]
vel = [-1.0, 0.0]
radius = 0.25
mass = 2.0
[[ball]]
pos = [-2.75, 2.0]
vel = [-3.0, 1.0]
radius = 0.25
)",
                                  "touching");
  HomeSettings no_elastic;
  no_elastic.allow.elastic = false;
  for (int steps : {1, 100}) {
    const State a = run(scene, {}, steps), b = run(scene, no_elastic, steps);
    EXPECT_LT((a.pos - b.pos).cwiseAbs().maxCoeff(), 1e-12) << steps << " steps";
    EXPECT_LT((a.vel - b.vel).cwiseAbs().maxCoeff(), 1e-12) << steps << " steps";
  }
  // And it did bounce: ball 0 moves left after the first step.
  EXPECT_LT(run(scene, {}, 1).vel(0, 0), 0.0);
}

// The elastic shortcut's neighbour list must follow balls that collisions make faster than the
// fastest ball was when the list was built: a heavy ball at 75 m/s ploughs through a gas of light
// ones (up to twice its speed after an impact), a second drives light balls into a wall (each
// bounce adds twice its speed), and the skin is the least the list allows (the fastest ball's step).
// A pair the list missed would pass through: no pair may overlap after any step. (One impact
// cannot take a ball beyond the skin within its step, since it at most doubles the fastest speed;
// the mid-step rebuild guards against chains of them, and was not needed here: removing it left
// this test green.) Against the general path (the grid, rebuilt every step with its own speed
// bound) the trajectories agree to round-off, which the balls pumped between heavy ball and wall
// amplify about threefold per step (measured: 7e-15 m and 1.7e-13 m/s after one step, 4e-11 m and
// 1.3e-9 m/s after ten), so the comparison covers 10 steps, with 25x room.
TEST(HomeShortcuts, ElasticListFollowsBallsMadeFastByCollisions) {
  Scene scene = mixed(gas(800, "restitution = 1.0"));
  scene.mass(0) = 1000.0;
  scene.initial.vel.row(0) << 60.0, 45.0;
  // A second heavy ball drives light ones into a wall: each bounce between it and the wall adds
  // twice its speed, so they leave their skin within a step.
  scene.mass(2) = 1000.0;
  scene.initial.pos.row(2) << scene.container.max.x() - 3.0, 0.0;
  scene.initial.vel.row(2) << 40.0, 0.0;
  for (int k = 0; k < 3; ++k) {
    scene.initial.pos.row(4 + 2 * k) << scene.container.max.x() - 2.2 + 0.7 * k, 0.01 * k;
    scene.initial.vel.row(4 + 2 * k) << 0.0, 0.0;
  }
  HomeSettings no_elastic, tight;
  no_elastic.allow.elastic = false;
  tight.list_steps = 1.0;  // a skin the fastest ball crosses in a step: any ball made faster leaves it
  std::unique_ptr<Engine> listed = make_home(scene, tight), grid = make_home(scene, no_elastic);
  State a, b;
  double fastest = 0;
  for (int k = 1; k <= 100; ++k) {
    listed->step(scene.dt);
    listed->read(a);
    fastest = std::max(fastest, a.vel.rowwise().norm().maxCoeff());
    int overlapping = 0;  // pairs that did not overlap at the start (mixed() made some that do)
    for (int i = 0; i < a.n(); ++i)
      for (int j = i + 1; j < a.n(); ++j) {
        const double rs = (scene.radius(i) + scene.radius(j)) * (1 - 1e-6);
        overlapping += (a.pos.row(i) - a.pos.row(j)).norm() < rs &&
                       (scene.initial.pos.row(i) - scene.initial.pos.row(j)).norm() >= rs;
      }
    ASSERT_EQ(overlapping, 0) << "step " << k;
    if (k > 10) continue;
    grid->step(scene.dt);
    grid->read(b);
    const double dp = (a.pos - b.pos).cwiseAbs().maxCoeff(), dv = (a.vel - b.vel).cwiseAbs().maxCoeff();
    ASSERT_LT(dp, k == 1 ? 1e-13 : 1e-9) << "step " << k;
    ASSERT_LT(dv, k == 1 ? 1e-12 : 1e-7) << "step " << k;
  }
  EXPECT_GT(fastest, 80.0);  // some light ball was made faster than the heavy one
}

// A scene that allows none of the shortcuts runs the general path either way.
TEST(HomeShortcuts, SceneWithoutThemIsUnchanged) {
  const Scene scene = mixed(gas(400, "gravity = [0.0, -100.0]\nrestitution = 0.9"));
  expect_same(run(scene, {}, 150), run(scene, general(), 150));
}

// The per-ball loops on 1, 2 or 3 threads: fixed contiguous ranges, results concatenated in order,
// no floating-point reduction across threads, so the same bits (a gas and a settling pile). This
// covers the parallel counting sort of the grid (per-part histograms; the same slot order as the
// serial sort) and the first predictions of a step (queued in ball order) too.
TEST(HomeThreads, SameResultsOnAnyNumberOfThreads) {
  for (const Scene& scene : {gas(3000, "restitution = 1.0"), gas(1000, "gravity = [0.0, -100.0]\nrestitution = 0.99"),
                             mixed(gas(1000, "gravity = [0.0, -100.0]\nrestitution = 0.9"))}) {
    HomeSettings one, two, three;
    one.threads = 1, two.threads = 2, three.threads = 3;
    const State a = run(scene, one, 60);
    expect_same(a, run(scene, two, 60));
    expect_same(a, run(scene, three, 60));
  }
}

// Without a neighbour list a step's final advance is left to the next step's first pass, and read()
// computes the end positions for its copy (core/solver/home.cpp, drift): a lone ball in free fall
// must read where symplectic Euler puts it after each step, x + (v + g dt) dt, not where the step
// began. Compared exactly: the solver evaluates the same products and sums in the same order (its
// clock is 0 at the step's start, so x + v (dt - 0) is x + v dt). The same expressions through the
// renumbering's gather are covered by HomeReorder.ReadKeepsTheScenesOrder, which a wrong clock
// index there fails.
TEST(HomeRead, EndOfStepPositions) {
  const Scene lone = parse_scene(R"(
name = "fall"
dt = 0.01
duration = 1.0
gravity = [0.0, -100.0]
[container]
min = [-50.0, -50.0]
max = [50.0, 50.0]
[[ball]]
pos = [1.0, 2.0]
vel = [3.0, 4.0]
radius = 0.5
)",
                                 "fall");
  std::unique_ptr<Engine> e = make_home(lone, {});
  double x = 1.0, y = 2.0, vy = 4.0;
  State s;
  for (int k = 0; k < 5; ++k) {
    e->step(lone.dt);
    e->read(s);
    vy += -100.0 * lone.dt;
    x += 3.0 * lone.dt, y += vy * lone.dt;
    EXPECT_EQ(s.pos(0, 0), x) << "step " << k + 1;
    EXPECT_EQ(s.pos(0, 1), y) << "step " << k + 1;
    EXPECT_EQ(s.vel(0, 1), vy) << "step " << k + 1;
  }
}

// Renumbering the balls in cell order (every step here, the most it can be done) is invisible in
// read(): the scene's order comes back, and on an elastic gas the same trajectory.
TEST(HomeReorder, ReadKeepsTheScenesOrder) {
  const Scene scene = mixed(gas(2000, "restitution = 1.0"));
  // With the neighbour list (elastic shortcut) and with the grid of every step.
  for (bool elastic : {true, false}) {
    HomeSettings never, every;
    never.reorder_steps = 0, every.reorder_steps = 1;
    never.allow.elastic = every.allow.elastic = elastic;
    const State a = run(scene, never, 40), b = run(scene, every, 40);
    ASSERT_EQ(a.n(), b.n());
    double worst = 0;
    for (int i = 0; i < a.n(); ++i) worst = std::max(worst, (a.pos.row(i) - b.pos.row(i)).norm());
    // Measured: identical bits. The event queue orders ties by time only, and ties are what could
    // differ; on this scene none does.
    EXPECT_EQ(worst, 0.0) << (elastic ? "neighbour list" : "grid");
  }
}

// Renumbering every step in a settling pile of unequal balls (radii, masses, collision counters,
// scene order and warm-start keys all move). It changes the contact solve's order, so the runs are
// compared as piles (measured: energy 0.65% apart, deepest overlap 2.6e-5 m): the same energy to 1%,
// no overlap deeper than 1% of the radius sum. (A wrong warm-start key would only cost sweeps, the
// solve converges from any start: measured, this test does not see one.)
TEST(HomeReorder, SettlingPileSurvivesRenumbering) {
  const Scene scene = mixed(gas(400, "gravity = [0.0, -100.0]\nrestitution = 0.5"));
  HomeSettings never, every;
  never.reorder_steps = 0, every.reorder_steps = 1;
  const State a = run(scene, never, 100), b = run(scene, every, 100);
  auto energy = [&](const State& s) {
    double e = 0;
    for (int i = 0; i < s.n(); ++i) e += scene.mass(i) * (0.5 * s.vel.row(i).squaredNorm() + 100.0 * s.pos(i, 1));
    return e;
  };
  auto deepest = [&](const State& s) {
    double worst = 0;
    for (int i = 0; i < s.n(); ++i)
      for (int j = i + 1; j < s.n(); ++j)
        worst = std::max(worst, scene.radius(i) + scene.radius(j) - (s.pos.row(i) - s.pos.row(j)).norm());
    return worst;
  };
  EXPECT_NEAR(energy(b), energy(a), 0.01 * std::abs(energy(a)));
  EXPECT_LT(deepest(b), 0.01 * 0.5);  // 1% of the radius sum
}

}  // namespace
}  // namespace ballbench

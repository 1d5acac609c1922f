// The soft step (core/solver/soft_step.h) on plain data, and `home` with resting = "soft" on
// piles: what it must keep (no tunnelling, no sticking, a pile that comes to rest) and where it
// must not be taken (scenes without gravity run the exact event-driven path, bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "input_error.h"
#include "registry.h"
#include "runner.h"
#include "scene_loader.h"
#include "solver/soft_step.h"

namespace ballbench {
namespace {

struct Balls {
  std::vector<double> x, y, vx, vy;
  SoftBodies bodies() { return {x.data(), y.data(), vx.data(), vy.data(), nullptr, 1.0}; }
};

TEST(SoftStep, FreeBallFollowsSubsteppedSymplecticEuler) {
  // n substeps of h = dt / n: y = y0 + v0 dt + g h^2 (1 + 2 + ... + n) = y0 + v0 dt + g dt^2 (n + 1) / (2 n).
  Balls b{{0.0}, {1.0}, {0.5}, {2.0}};
  std::vector<SoftContact> none;
  SoftStepScratch scratch;
  SoftStepSettings s;
  s.substeps = 4;
  const double dt = 0.01, g = -9.81;
  soft_step(b.bodies(), 1, none, 0.0, g, dt, s, {}, scratch);
  EXPECT_NEAR(b.x[0], 0.5 * dt, 1e-15);
  EXPECT_NEAR(b.y[0], 1.0 + 2.0 * dt + g * dt * dt * 5.0 / 8.0, 1e-15);
  EXPECT_NEAR(b.vy[0], 2.0 + g * dt, 1e-15);
}

TEST(SoftStep, BallOnTheFloorStaysAtRest) {
  // A ball touching the floor (gap 0), carried by its contact: after a second it has settled where
  // the push-out's spring of 100 Hz holds its weight, g / omega^2 deep, and no longer moves.
  Balls b{{0.0}, {0.25}, {0.0}, {0.0}};
  std::vector<SoftContact> floor{{{0, wall_partner(1, 0), 0.0, 1.0, 1.0, 0.0}, 0.0, 0.0, 0.0}};
  SoftStepScratch scratch;
  for (int k = 0; k < 100; ++k) {
    floor[0].gap = b.y[0] - 0.25;  // the caller measures the gap at the start of each step
    soft_step(b.bodies(), 1, floor, 0.0, -9.81, 0.01, {}, {0.5, 0.2}, scratch);
  }
  const double omega = 2 * M_PI * 100;
  EXPECT_NEAR(b.y[0], 0.25 - 9.81 / (omega * omega), 1e-9);
  EXPECT_LT(std::abs(b.vy[0]), 1e-9);
  EXPECT_NEAR(floor[0].impulse, 9.81 * 0.01 / 4, 1e-9);  // its weight over one substep
}

TEST(SoftStep, ImpactLeavesAtTheRestitutionSpeed) {
  // Two touching balls approaching head-on at 2 m/s, no gravity: they part at e times that.
  Balls b{{-0.25, 0.25}, {0.0, 0.0}, {1.0, -1.0}, {0.0, 0.0}};
  std::vector<SoftContact> pair{{{1, 0, 1.0, 0.0, 0.5, 0.0}, 0.0, 0.0, 0.0}};
  SoftStepScratch scratch;
  soft_step(b.bodies(), 2, pair, 0.0, 0.0, 0.01, {}, {0.8, 0.1}, scratch);
  EXPECT_NEAR(b.vx[1] - b.vx[0], 0.8 * 2.0, 1e-12);
  EXPECT_NEAR(b.vx[0] + b.vx[1], 0.0, 1e-12);  // momentum
}

Result run_soft(Scene scene, nlohmann::json settings = nlohmann::json::object()) {
  RunOptions options;
  settings["resting"] = "soft";
  options.overrides = settings;
  return run_engine(scene, find_engine("home"), options);
}

TEST(HomeSoft, PileComesToRestWithoutTunnellingOrSticking) {
  const Scene scene = load_scene("pile");
  const Result r = run_soft(scene);
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_EQ(r.metrics.count(Metric::tunnelling_wall) + r.metrics.count(Metric::tunnelling_pair), 0);
  EXPECT_EQ(r.metrics.count(Metric::sticking_wall) + r.metrics.count(Metric::sticking_pair), 0);
  EXPECT_LT(r.metrics.value(Metric::energy_final), r.metrics.value(Metric::energy_initial));
  ASSERT_TRUE(r.metrics.has(Metric::jitter));
  EXPECT_LT(*r.metrics.number(Metric::jitter), 1e-3);  // the pile issue's bound; measured 3.5e-11 m/s at the defaults
  EXPECT_LT(r.metrics.value(Metric::penetration_max), 0.1);  // measured 0.056 of a radius (impacts on the pile)
}

TEST(HomeSoft, OtherPilesToo) {
  // Another count, radius, restitution and box than the pile scene's.
  const std::string text = R"(
dt = 0.01
duration = 6.0
gravity = [0.0, -9.81]
restitution = 0.2
[container]
min = [-3.0, 0.0]
max = [3.0, 12.0]
[random]
count = 300
radius = 0.12
pos_min = [-2.8, 0.2]
pos_max = [2.8, 11.8]
vel_min = [-1.0, -1.0]
vel_max = [1.0, 1.0]
seed = 11
)";
  const Scene scene = parse_scene(text, "other-pile");
  const Result r = run_soft(scene);
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_EQ(r.metrics.count(Metric::tunnelling_wall) + r.metrics.count(Metric::tunnelling_pair), 0);
  EXPECT_EQ(r.metrics.count(Metric::sticking_wall) + r.metrics.count(Metric::sticking_pair), 0);
  EXPECT_LT(r.metrics.value(Metric::energy_final), r.metrics.value(Metric::energy_initial));
  ASSERT_TRUE(r.metrics.has(Metric::jitter));
  EXPECT_LT(*r.metrics.number(Metric::jitter), 1e-3);  // the pile scene's bound; measured 2.1e-9 m/s
}

// With sleeping, the pile ends with every ball asleep (RMS speed exactly 0), and keeps what the
// soft path keeps without it.
TEST(HomeSoft, ASleepingPileEndsAtRestWithoutTunnellingOrSticking) {
  const Result r = run_soft(load_scene("pile"), {{"sleep_speed", 0.05}});
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_EQ(r.metrics.count(Metric::tunnelling_wall) + r.metrics.count(Metric::tunnelling_pair), 0);
  EXPECT_EQ(r.metrics.count(Metric::sticking_wall) + r.metrics.count(Metric::sticking_pair), 0);
  EXPECT_LT(r.metrics.value(Metric::energy_final), r.metrics.value(Metric::energy_initial));
  ASSERT_TRUE(r.metrics.has(Metric::jitter));
  EXPECT_EQ(*r.metrics.number(Metric::jitter), 0.0);
  EXPECT_LT(r.metrics.value(Metric::penetration_max), 0.1);  // as without sleeping: the overlaps come from the pour's impacts
}

// A sleeping ball wakes when another lands on it: B falls on A's shoulder a second after A fell
// asleep on the floor, and A is pushed aside (asleep, it would hold B as a wall does and not move).
TEST(HomeSoft, ABallLandingOnASleepingBallWakesIt) {
  const std::string text = R"(
dt = 0.01
duration = 2.5
gravity = [0.0, -9.81]
restitution = 0.5
[container]
min = [-3.0, 0.0]
max = [3.0, 12.0]
[[ball]]
pos = [0.0, 0.25]
radius = 0.25
[[ball]]
pos = [0.2, 8.0]
radius = 0.25
)";
  const Scene scene = parse_scene(text, "landing");
  const Result sleeping = run_soft(scene, {{"sleep_speed", 0.05}});
  ASSERT_EQ(sleeping.status, RunStatus::ok) << sleeping.error;
  EXPECT_EQ(sleeping.metrics.count(Metric::tunnelling_pair), 0);
  std::unique_ptr<Engine> e = find_engine("home").create(scene, "default", {{"resting", "soft"}, {"sleep_speed", 0.05}});
  State s;
  for (int k = 0; k < 250; ++k) e->step(scene.dt);
  e->read(s);
  // Asleep, A would stay at x = 0 exactly; 1 cm (4% of its radius) is far beyond round-off. B lands
  // right of A's centre, so it is pushed further right than it started (x = 0.2).
  EXPECT_LT(s.pos(0, 0), -0.01) << "the ball below was not pushed aside: it did not wake";
  EXPECT_GT(s.pos(1, 0), 0.21);
}

TEST(HomeSoft, SeedBowlEndsNearExactsEnergy) {
  const Scene scene = load_scene("seed-bowl");
  const Result soft = run_soft(scene);
  const Result exact = run_engine(scene, find_engine("exact"), {});
  ASSERT_EQ(soft.status, RunStatus::ok) << soft.error;
  EXPECT_EQ(soft.metrics.count(Metric::tunnelling_wall) + soft.metrics.count(Metric::tunnelling_pair), 0);
  EXPECT_EQ(soft.metrics.count(Metric::sticking_wall) + soft.metrics.count(Metric::sticking_pair), 0);
  // seed-bowl is chaotic: its final energy after 30 s moves by about 2% with any change to the
  // solver (measured 0.27% below exact's and 1.7% above, at two versions of the soft path), so one
  // run bounds it at 3%; the issue's 1% is for a mean over seeds.
  EXPECT_NEAR(soft.metrics.value(Metric::energy_final) / exact.metrics.value(Metric::energy_final), 1.0, 0.03);
}

// The soft path keeps its contact candidates while no ball can have moved beyond them: a ball
// that starts 15 m above another (no candidate between them at the first build) and falls onto it
// must be caught by a rebuild in time, and end resting on it. Candidates held too long would let
// it fall through.
TEST(HomeSoft, ABallFallingOntoARestingBallLandsOnIt) {
  const std::string text = R"(
dt = 0.01
duration = 4.0
gravity = [0.0, -9.81]
restitution = 0.5
[container]
min = [-2.0, 0.0]
max = [2.0, 20.0]
[[ball]]
pos = [0.0, 0.25]
radius = 0.25
[[ball]]
pos = [0.0, 15.0]
radius = 0.25
)";
  const Scene scene = parse_scene(text, "fall-onto");
  const Result r = run_soft(scene);
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_EQ(r.metrics.count(Metric::tunnelling_wall) + r.metrics.count(Metric::tunnelling_pair), 0);
  EXPECT_LT(r.metrics.value(Metric::penetration_max), 0.01);  // measured 0.0036 of a radius: the landing at 17 m/s compresses the spring
  std::unique_ptr<Engine> e = find_engine("home").create(scene, "default", {{"resting", "soft"}});
  for (long k = 0; k < scene.steps(); ++k) e->step(scene.dt);
  State s;
  e->read(s);
  // Measured 0.49990: the spring holds the upper ball's weight at 1e-4 m of overlap. Fallen
  // through, the difference would be negative.
  EXPECT_NEAR(s.pos(1, 1) - s.pos(0, 1), 0.5, 1e-3) << "the upper ball should rest on the lower one";
}

// A ball at rest on the floor is struck at 12 m/s by another and carries half that speed on,
// across a gap of 0.14 radii to the wall (or to a third ball at rest) that its own speed would not
// close within the step: it has a contact there, and stays out within 2% of its radius. Without
// one it would sink about 0.05 radii in by the end of the step.
TEST(HomeSoft, ABallStruckAcrossAGapMeetsWhatIsThere) {
  const auto overlap = [](double wall, const std::string& beyond) {
    const std::string text = fmt::format(R"(
dt = 0.01
duration = 0.05
gravity = [0.0, -9.81]
restitution = 0.5
[container]
min = [-2.0, 0.0]
max = [{}, 2.0]
[[ball]]
pos = [1.19, 0.25]
vel = [12.0, 0.0]
radius = 0.25
[[ball]]
pos = [1.715, 0.25]
radius = 0.25
{})",
                                         wall, beyond);
    const Result r = run_soft(parse_scene(text, "struck"), {{"contact_hertz", 1000}, {"substeps", 40}});
    EXPECT_EQ(r.status, RunStatus::ok) << r.error;
    EXPECT_EQ(r.metrics.count(Metric::tunnelling_wall) + r.metrics.count(Metric::tunnelling_pair), 0);
    return r.metrics.value(Metric::penetration_max);
  };
  EXPECT_LT(overlap(2.0, ""), 0.02);  // the wall 0.035 m beyond the struck ball
  EXPECT_LT(overlap(3.0, "[[ball]]\npos = [2.25, 0.25]\nradius = 0.25"), 0.02);  // a ball there
}

// A ball passing another at 50 m/s (10 radii per step), 2 cm clear of it, never touches it. A
// step taken whole fixes the contact's normal at the start, along which the passing ball seems to
// close 0.46 m, and pushes the other away; cut into parts of half a radius, it does not.
TEST(HomeSoft, AFastBallPassingCloseTouchesNothing) {
  const std::string text = R"(
dt = 0.01
duration = 0.01
gravity = [0.0, -1e-3]
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [0.0, 0.0]
vel = [50.0, 0.0]
radius = 0.05
[[ball]]
pos = [0.3, 0.12]
radius = 0.05
)";
  const Scene scene = parse_scene(text, "passing");
  const auto moved_by_contact = [&](nlohmann::json settings) {
    settings["resting"] = "soft";
    std::unique_ptr<Engine> e = find_engine("home").create(scene, "default", settings);
    e->step(scene.dt);
    State s;
    e->read(s);
    return std::abs(s.vel(1, 0)) + std::abs(s.vel(1, 1) + 1e-3 * scene.dt);  // beyond its free fall
  };
  // Untouched, its velocity is its free fall to round-off (1e-5 m/s of gravity's, so ~1e-21): 1e-12
  // is far above that. Pushed, it takes a share of the passing ball's 50 m/s (measured above 1 m/s).
  EXPECT_LT(moved_by_contact(nlohmann::json::object()), 1e-12);
  EXPECT_GT(moved_by_contact({{"max_stride", 1e9}}), 1.0) << "one whole step should have pushed it";
}

// The fluid (the seed-bowl's box and gravity with 1000 balls of radius 0.067, up to 4 radii per
// step): cut into parts, its steps keep the balls in the box; taken whole (fixed normals over 4
// radii of motion), the same scene blows apart (measured: a ball left the box at step 53). The
// springs still let the pile at the bottom compress (0.4 radii at the defaults): the pile issue.
TEST(HomeSoft, TheFluidStaysInTheBox) {
  const std::string text = R"(
dt = 0.01
duration = 1.0
gravity = [0.0, -100.0]
restitution = 0.99
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[lattice]
count = 1000
radius = 0.0670820393249937
spacing = 0.1609968943799849
origin = [-4.6, -4.6]
columns = 30
vel_min = [-2.5, -2.5]
vel_max = [2.5, 2.5]
seed = 2017
)";
  const Scene scene = parse_scene(text, "fluid-1000");
  const Result r = run_soft(scene);
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_LT(r.metrics.value(Metric::energy_final), r.metrics.value(Metric::energy_initial));
  EXPECT_EQ(run_soft(scene, {{"max_stride", 1e9}}).status, RunStatus::diverged);
}

TEST(HomeSoft, ScenesWithoutGravityKeepTheEventDrivenPath) {
  const Scene scene = load_scene("seed-box");
  const Result soft = run_soft(scene);
  const Result events = run_engine(scene, find_engine("home"), {});
  ASSERT_EQ(soft.status, RunStatus::ok) << soft.error;
  EXPECT_EQ(soft.checksum_trajectory, events.checksum_trajectory);
}

TEST(HomeSoft, RejectsBadSettings) {
  const Scene scene = load_scene("pile");
  for (const auto& [key, value] : {std::pair<const char*, nlohmann::json>{"substeps", 0},
                                   {"contact_hertz", 0.0},
                                   {"damping_ratio", -1.0},
                                   {"push_speed", 0.0},
                                   {"substep_iterations", 0},
                                   {"relax_iterations", -1},
                                   {"max_stride", 0.0},
                                   {"max_parts", 0},
                                   {"sleep_speed", -1.0},
                                   {"sleep_time", 0.0},
                                   {"resting", "hard"}}) {
    EXPECT_THROW(find_engine("home").create(scene, "default", {{key, value}}), InputError) << key;
  }
}

}  // namespace
}  // namespace ballbench

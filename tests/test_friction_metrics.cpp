// The metrics a scene asks for in its [metrics] table: the rolling closed forms, the angle of
// repose and the runout, on hand-made scenes and heaps with known answers, and the table's bad-input lines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "input_error.h"
#include "metrics/angle_of_repose.h"
#include "metrics/meter_set.h"
#include "metrics/rolling.h"
#include "metrics/runout.h"
#include "registry.h"
#include "runner.h"
#include "scene_loader.h"
#include "spec_verdict.h"

namespace ballbench {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Balls of radius r stacked in columns of width 2 r from the floor of `box`, each column's top at
// `top(x)` (its centre x), exactly: the heap's surface profile is top() at every column centre.
template <class Top>
State stacked_heap(const Container& box, double r, Top top, Eigen::VectorXd& radius) {
  std::vector<Eigen::Vector2d> at;
  for (double x = box.min.x() + r; x < box.max.x(); x += 2 * r) {
    const double h = top(x);
    if (h <= 0) continue;
    for (double y = box.min.y() + r; y + r < h; y += 2 * r) at.emplace_back(x, y);
    at.emplace_back(x, box.min.y() + h - r);
  }
  State s;
  s.resize(static_cast<int>(at.size()));
  for (int i = 0; i < s.n(); ++i) s.pos.row(i) = at[i].transpose(), s.vel.row(i).setZero();
  radius = Eigen::VectorXd::Constant(s.n(), r);
  return s;
}

Container box_of(double x0, double y0, double x1, double y1) {
  Container c;
  c.kind = ContainerKind::Box, c.min = {x0, y0}, c.max = {x1, y1};
  return c;
}

// A heap whose flanks are straight lines at 25 and 35 degrees: their mean, 30, to round-off (the
// column tops lie on the lines exactly, so the least-squares fits are exact).
TEST(AngleOfRepose, OfAStraightHeapIsTheMeanOfItsFlanks) {
  const Container box = box_of(-10, 0, 10, 10);
  const double r = 0.1, peak = 0.1, height = 3.0;  // peak: the centre of column 50
  const auto top = [&](double x) {
    return height - std::abs(x - peak) * std::tan((x < peak ? 25 : 35) * kDeg);
  };
  Eigen::VectorXd radius;
  const State s = stacked_heap(box, r, top, radius);
  const HeapProfile p = heap_profile(s, radius, box);
  ASSERT_EQ(p.height.size(), 100u);
  EXPECT_NEAR(p.height[50], height, 1e-12);
  const auto angle = angle_of_repose(p);
  ASSERT_TRUE(angle);
  EXPECT_NEAR(*angle, 30.0, 1e-9);  // exact fits: round-off only
}

// What the band leaves out does not move the angle: a rounded top above 0.8 H and balls rolled out
// beyond the toe (past an empty column, where the walk from the peak stops).
TEST(AngleOfRepose, IgnoresTheRoundedTopAndBallsRolledOut) {
  const Container box = box_of(-10, 0, 10, 10);
  const double r = 0.1, height = 3.0;
  const auto top = [&](double x) {
    const double line = height - std::abs(x - 0.1) * std::tan(30 * kDeg);
    if (std::abs(x - 0.1) < 0.5) return line + 0.2;  // a rounded cap, all above 0.8 H
    if (std::abs(x) > 8.5 && std::abs(x) < 9) return 2 * r;  // lone balls on the floor, past empty columns
    return line;
  };
  Eigen::VectorXd radius;
  const State s = stacked_heap(box, r, top, radius);
  const auto angle = angle_of_repose(heap_profile(s, radius, box));
  ASSERT_TRUE(angle);
  EXPECT_NEAR(*angle, 30.0, 1e-9);
}

// A single layer over the whole floor has no column between 0.2 H and 0.8 H: nothing to measure.
// A heap with one flank against a wall is measured on the other.
TEST(AngleOfRepose, AFlatLayerHasNoFlankAndAOneSidedHeapHasOne) {
  const Container box = box_of(-5, 0, 5, 5);
  Eigen::VectorXd radius;
  const State flat = stacked_heap(box, 0.1, [](double) { return 0.2; }, radius);
  EXPECT_FALSE(angle_of_repose(heap_profile(flat, radius, box)));
  // Peak at the left wall, one flank at 40 degrees.
  const State wedge = stacked_heap(box, 0.1, [](double x) { return 3.0 - (x + 4.9) * std::tan(40 * kDeg); }, radius);
  const auto angle = angle_of_repose(heap_profile(wedge, radius, box));
  ASSERT_TRUE(angle);
  EXPECT_NEAR(*angle, 40.0, 1e-9);
}

// A heap of discs quantised to whole balls (stacks of 2 r): the fit sees a staircase, so the angle
// is off by the staircase's scatter, well under a degree over the ~25 columns of each flank (a
// rise of 2 r in a run of 2 r / tan 30 = 0.35 m: every column is at most r off the line).
TEST(AngleOfRepose, OfAStaircaseHeapIsNearItsSlope) {
  const Container box = box_of(-10, 0, 10, 10);
  const double r = 0.1;
  const auto top = [&](double x) {
    const double line = 3.0 - std::abs(x - 0.1) * std::tan(30 * kDeg);
    return 2 * r * std::round(line / (2 * r));
  };
  Eigen::VectorXd radius;
  const State s = stacked_heap(box, r, top, radius);
  const auto angle = angle_of_repose(heap_profile(s, radius, box));
  ASSERT_TRUE(angle);
  EXPECT_NEAR(*angle, 30.0, 1.0);
}

// Slide to roll (scenarios/slide-to-roll.toml, v0 3 m/s, mu 0.5, a disk, k = 1/2): v0 / (1 + k)
// = 2 m/s from t = v0 k / ((1 + k) mu g) = 0.2039 s, the README's numbers.
// Balls at (x, y) of radius r.
State balls_at(std::initializer_list<Eigen::Vector2d> at) {
  State s;
  s.resize(static_cast<int>(at.size()));
  int i = 0;
  for (const Eigen::Vector2d& p : at) s.pos.row(i) = p.transpose(), s.vel.row(i++).setZero();
  return s;
}

// The deposit is the run of balls, each within a mean diameter of the ones before, that holds the
// highest ball: a ball that rolled away is not in it, one a diameter's gap away is, and a lower
// heap elsewhere is not the heap.
TEST(Runout, IsTheLengthOfTheDepositThatHoldsTheHighestBall) {
  const double r = 0.1;
  const State heap = balls_at({{0.1, 0.1}, {0.3, 0.1}, {0.5, 0.1}, {0.2, 0.27}, {0.4, 0.27}, {0.3, 0.44}, {0.7, 0.1},
                               {3.0, 0.1}});  // the last rolled away
  EXPECT_NEAR(*runout(heap, Eigen::VectorXd::Constant(heap.n(), r)), 0.8, 1e-12);
  // A ball whose left edge lies within a diameter of the deposit's right edge joins it; one farther does not.
  EXPECT_NEAR(*runout(balls_at({{0.1, 0.3}, {0.49, 0.1}}), Eigen::VectorXd::Constant(2, r)), 0.59, 1e-12);
  EXPECT_NEAR(*runout(balls_at({{0.1, 0.3}, {0.51, 0.1}}), Eigen::VectorXd::Constant(2, r)), 0.2, 1e-12);
  // The highest ball's run, wherever it is: here the right one.
  const State two = balls_at({{0.1, 0.1}, {0.3, 0.1}, {0.5, 0.1}, {2.0, 0.1}, {2.2, 0.1}, {2.1, 0.27}});
  EXPECT_NEAR(*runout(two, Eigen::VectorXd::Constant(two.n(), r)), 0.4, 1e-12);
  EXPECT_FALSE(runout(State{}, Eigen::VectorXd()));
}

TEST(RollingClosedForm, SlideToRoll) {
  const RollingClosedForm c = rolling_closed_form(load_scene("slide-to-roll"), 0);
  EXPECT_DOUBLE_EQ(c.speed, 2.0);
  ASSERT_TRUE(c.time_to_roll);
  EXPECT_NEAR(*c.time_to_roll, 3.0 * 0.5 / (1.5 * 0.5 * 9.81), 1e-12);
}

// The spin drop (scenarios/spin-drop.toml: v0 1 m/s, w0 20 rad/s, r 0.25, m 1, dropped 1 m,
// restitution 0, mu 0.2), stepped through by hand as the conformance suite describes it: the
// impact's normal impulse m v_i, v_i = sqrt(2 g 1), is too small to stop the 6 m/s slip, so the
// friction impulse is mu m v_i: v = 1 - mu v_i, w = 20 - mu m v_i r / I. Then sliding friction
// mu m g: v falls at mu g, w at mu m g r / I, until v = -w r.
TEST(RollingClosedForm, SpinDropSlidesOffTheImpactThenRolls) {
  const Scene s = load_scene("spin-drop");
  const double g = 9.81, mu = 0.2, r = 0.25, I = 0.5 * r * r;
  const double vi = std::sqrt(2 * g * 1.0), t_land = std::sqrt(2 * 1.0 / g);
  const double v = 1 - mu * vi, w = 20 - mu * vi * r / I;  // 0.114 m/s, 12.9 rad/s
  const double t_slide = (v + w * r) / (mu * g + mu * g * r * r / I);
  const RollingClosedForm c = rolling_closed_form(s, 0);
  EXPECT_NEAR(c.speed, -1.0, 1e-12);
  EXPECT_NEAR(c.speed, v - mu * g * t_slide, 1e-12);  // the hand-stepped ball ends at the same speed
  ASSERT_TRUE(c.time_to_roll);
  EXPECT_NEAR(*c.time_to_roll, t_land + t_slide, 1e-12);
}

// With mu 0.8 the impact stops the slip (sticking needs mu above 0.45): it rolls as it lands. A
// ball that bounces (restitution above 0, dropped) has no closed-form time.
TEST(RollingClosedForm, StickingImpactRollsAtOnceAndABounceHasNoTime) {
  std::string text = R"(
dt = 0.01
duration = 2.0
gravity = [0.0, -9.81]
restitution = 0.0
friction = 0.8
[container]
min = [-5.0, 0.0]
max = [5.0, 4.0]
[[ball]]
pos = [0.0, 1.25]
vel = [1.0, 0.0]
spin = 20.0
radius = 0.25
[metrics]
rolling = true
)";
  const RollingClosedForm sticking = rolling_closed_form(parse_scene(text, "s.toml"), 0);
  ASSERT_TRUE(sticking.time_to_roll);
  EXPECT_NEAR(*sticking.time_to_roll, std::sqrt(2 / 9.81), 1e-12);
  text.replace(text.find("restitution = 0.0"), 17, "restitution = 0.5");
  const RollingClosedForm bouncing = rolling_closed_form(parse_scene(text, "s.toml"), 0);
  EXPECT_FALSE(bouncing.time_to_roll);
  EXPECT_NEAR(bouncing.speed, -1.0, 1e-12);
}

// Two balls sliding on the floor (a disk, mu 0.5): one at 3 m/s, one dropped 0.5 m at 1.5 m/s with
// restitution 0; each has its own closed form, from its own row of the scene.
const char* kTwoBalls = R"(dt = 0.01
duration = 1.0
gravity = [0.0, -9.81]
restitution = 0.0
friction = 0.5
[container]
min = [0.0, 0.0]
max = [20.0, 4.0]
[[ball]]
pos = [4.0, 0.25]
vel = [3.0, 0.0]
radius = 0.25
[[ball]]
pos = [1.0, 0.8]
vel = [1.5, 0.0]
radius = 0.3
mass = 2.0
[metrics]
rolling = true
)";

TEST(RollingClosedForm, IsEachBallsOwn) {
  const Scene s = parse_scene(kTwoBalls, "s.toml");
  ASSERT_EQ(s.n(), 2);
  const double g = 9.81, mu = 0.5, k = 0.5;
  const RollingClosedForm first = rolling_closed_form(s, 0), second = rolling_closed_form(s, 1);
  EXPECT_DOUBLE_EQ(first.speed, 2.0);
  ASSERT_TRUE(first.time_to_roll);
  EXPECT_NEAR(*first.time_to_roll, 3.0 * k / ((1 + k) * mu * g), 1e-12);
  // The second falls 0.5 m onto the floor (its own radius: 0.8 - 0.3), meets it at sqrt(2 g 0.5),
  // whose Coulomb impulse (mu vi (1 + 1 / k) = 4.7 m/s of slip) stops the 1.5 m/s slip: it rolls
  // as it lands.
  EXPECT_DOUBLE_EQ(second.speed, 1.0);
  ASSERT_TRUE(second.time_to_roll);
  EXPECT_NEAR(*second.time_to_roll, std::sqrt(2 * 0.5 / g), 1e-12);
}

// The meter judges each ball against its own closed form and reports the one farthest from it:
// ball 1 ends 2% off its 1 m/s, ball 0 0.5% off its 2 m/s, so ball 1's speed and closed form, and
// the error 0.02, which is the spec's `rolling` figure. The time to roll is the later ball's: the
// dropped one's, which rolls as it lands (0.319 s; the other from 0.204 s).
TEST(RollingMeter, ReportsTheBallFarthestFromItsClosedForm) {
  const Scene s = parse_scene(kTwoBalls, "s.toml");
  State end = s.initial;
  end.vel(0, 0) = 2.01, end.vel(1, 0) = 1.02;
  MeterSet meters(s, {});
  meters.final_state(end);
  Result r;
  r.metrics = meters.values();
  r.steps_done = 100;
  EXPECT_DOUBLE_EQ(*r.metrics.number(Metric::rolling_speed), 1.02);
  EXPECT_DOUBLE_EQ(*r.metrics.number(Metric::rolling_expected_speed), 1.0);
  EXPECT_NEAR(*r.metrics.number(Metric::rolling_error), 0.02, 1e-12);
  EXPECT_NEAR(*r.metrics.number(Metric::rolling_expected_time_to_roll), std::sqrt(2 * 0.5 / 9.81), 1e-12);
  EXPECT_EQ(spec_figure(SpecTerm::rolling, r), r.metrics.number(Metric::rolling_error));
  // The other way round, ball 0 is the farther, and below the ball that is exact.
  end.vel(0, 0) = 1.9, end.vel(1, 0) = 1.0;
  MeterSet again(s, {});
  again.final_state(end);
  EXPECT_DOUBLE_EQ(*again.values().number(Metric::rolling_speed), 1.9);
  EXPECT_DOUBLE_EQ(*again.values().number(Metric::rolling_expected_speed), 2.0);
  EXPECT_NEAR(*again.values().number(Metric::rolling_error), 0.05, 1e-12);
}

// A ball whose closed form is 0 (at rest on the floor) has no relative error: the scene's error is
// none, and the spec reports it not measured rather than met.
TEST(RollingMeter, AClosedFormOfZeroLeavesTheErrorNone) {
  std::string text = kTwoBalls;
  text.replace(text.find("vel = [1.5, 0.0]"), 16, "vel = [0.0, 0.0]");
  const Scene s = parse_scene(text, "s.toml");
  State end = s.initial;
  end.vel(0, 0) = 2.0;
  MeterSet meters(s, {});
  meters.final_state(end);
  const MetricValues v = meters.values();
  EXPECT_FALSE(v.number(Metric::rolling_error));
  EXPECT_DOUBLE_EQ(*v.number(Metric::rolling_expected_speed), 0.0);  // the ball that has none
}

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kOneBallOnAFloor = R"(dt = 0.01
duration = 1.0
gravity = [0.0, -9.81]
friction = 0.5
[container]
min = [0.0, 0.0]
max = [4.0, 4.0]
[[ball]]
pos = [1.0, 0.25]
radius = 0.25
)";

TEST(RequestedMetrics, AreReadAndCheckedAgainstWhatTheyNeed) {
  const std::string base = kOneBallOnAFloor;
  const Scene s = parse_scene(base + "[metrics]\nrolling = true\nangle_of_repose = true\n", "s.toml");
  EXPECT_TRUE(s.metrics.rolling && s.metrics.angle_of_repose);
  EXPECT_FALSE(parse_scene(base, "s.toml").metrics.rolling);
  EXPECT_EQ(error_of(base + "[metrics]\nroling = true\n"), "s.toml:12: metrics.roling: unknown key, did you mean 'rolling'?");
  EXPECT_EQ(error_of(base + "[metrics]\nrolling = 1\n"), "s.toml:12: metrics.rolling: expected true or false, got an integer");
  EXPECT_EQ(error_of("metrics = 3\n" + base), "s.toml:1: metrics: expected a table [metrics], got an integer");
  std::string tilted = base + "[metrics]\nrolling = true\n";
  tilted.replace(tilted.find("[0.0, -9.81]"), 12, "[1.0, -9.81]");
  EXPECT_EQ(error_of(tilted), "s.toml:12: metrics.rolling: needs a floor: a box container and gravity straight down [0, -g]");
  std::string smooth = base + "[metrics]\nrolling = true\n";
  smooth.replace(smooth.find("friction = 0.5"), 14, "friction = 0.0");
  EXPECT_EQ(error_of(smooth), "s.toml:12: metrics.rolling: needs friction above 0 (a frictionless ball never rolls)");
  // Any number of balls, each on its own closed form.
  const Scene many = parse_scene(base + "[[ball]]\npos = [2.0, 0.25]\nvel = [1.0, 0.0]\nradius = 0.25\n[metrics]\nrolling = true\n", "s.toml");
  EXPECT_TRUE(many.metrics.rolling);
  EXPECT_EQ(many.n(), 2);
  std::string sideways = base + "[metrics]\nangle_of_repose = true\n";
  sideways.replace(sideways.find("[0.0, -9.81]"), 12, "[9.81, 0.0]");
  EXPECT_EQ(error_of(sideways),
            "s.toml:12: metrics.angle_of_repose: needs a floor: a box container and gravity straight down [0, -g]");
  EXPECT_TRUE(parse_scene(base + "[metrics]\nrunout = true\n", "s.toml").metrics.runout);
  sideways.replace(sideways.find("angle_of_repose"), 15, "runout");
  EXPECT_EQ(error_of(sideways), "s.toml:12: metrics.runout: needs a floor: a box container and gravity straight down [0, -g]");
}

// The runner computes them only where the scene asks, from the states: Box2D's ball sliding to
// roll ends within 0.5% of v0 / (1 + k) (issue 21's bound for every engine), and a scene that asks
// for nothing gets nulls.
TEST(RequestedMetrics, AreComputedOnlyWhereAsked) {
  RunOptions o;
  const Result roll = run_engine(load_scene("slide-to-roll"), find_engine("box2d"), o);
  ASSERT_EQ(roll.status, RunStatus::ok) << roll.error;
  ASSERT_TRUE(roll.metrics.number(Metric::rolling_speed) && roll.metrics.number(Metric::rolling_expected_speed) && roll.metrics.number(Metric::rolling_expected_time_to_roll));
  EXPECT_NEAR(*roll.metrics.number(Metric::rolling_speed), 2.0, 0.005 * 2.0);
  ASSERT_TRUE(roll.metrics.number(Metric::rolling_error));
  EXPECT_DOUBLE_EQ(*roll.metrics.number(Metric::rolling_error), std::abs(*roll.metrics.number(Metric::rolling_speed) - 2.0) / 2.0);
  EXPECT_FALSE(roll.metrics.number(Metric::angle_of_repose));
  const Result plain = run_engine(load_scene("corridor"), find_engine("box2d"), o);
  EXPECT_FALSE(plain.metrics.number(Metric::rolling_speed) || plain.metrics.number(Metric::rolling_expected_speed) || plain.metrics.number(Metric::angle_of_repose));
}

}  // namespace
}  // namespace ballbench

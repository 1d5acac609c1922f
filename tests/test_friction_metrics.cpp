// The metrics a scene asks for in its [metrics] table: the rolling closed forms and the angle of
// repose, on hand-made scenes and heaps with known answers, and the table's bad-input lines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "input_error.h"
#include "metrics/angle_of_repose.h"
#include "metrics/rolling.h"
#include "registry.h"
#include "runner.h"
#include "scene_loader.h"

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
TEST(RollingClosedForm, SlideToRoll) {
  const RollingClosedForm c = rolling_closed_form(load_scene("slide-to-roll"));
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
  const RollingClosedForm c = rolling_closed_form(s);
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
  const RollingClosedForm sticking = rolling_closed_form(parse_scene(text, "s.toml"));
  ASSERT_TRUE(sticking.time_to_roll);
  EXPECT_NEAR(*sticking.time_to_roll, std::sqrt(2 / 9.81), 1e-12);
  text.replace(text.find("restitution = 0.0"), 17, "restitution = 0.5");
  const RollingClosedForm bouncing = rolling_closed_form(parse_scene(text, "s.toml"));
  EXPECT_FALSE(bouncing.time_to_roll);
  EXPECT_NEAR(bouncing.speed, -1.0, 1e-12);
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
  std::string two = base + "[[ball]]\npos = [2.0, 0.25]\nradius = 0.25\n[metrics]\nrolling = true\n";
  EXPECT_EQ(error_of(two), "s.toml:15: metrics.rolling: needs exactly one ball, the scene has 2");
  std::string smooth = base + "[metrics]\nrolling = true\n";
  smooth.replace(smooth.find("friction = 0.5"), 14, "friction = 0.0");
  EXPECT_EQ(error_of(smooth), "s.toml:12: metrics.rolling: needs friction above 0 (a frictionless ball never rolls)");
  std::string sideways = base + "[metrics]\nangle_of_repose = true\n";
  sideways.replace(sideways.find("[0.0, -9.81]"), 12, "[9.81, 0.0]");
  EXPECT_EQ(error_of(sideways),
            "s.toml:12: metrics.angle_of_repose: needs a floor: a box container and gravity straight down [0, -g]");
}

// The runner computes them only where the scene asks, from the states: Box2D's ball sliding to
// roll ends within 0.5% of v0 / (1 + k) (issue 21's bound for every engine), and a scene that asks
// for nothing gets nulls.
TEST(RequestedMetrics, AreComputedOnlyWhereAsked) {
  RunOptions o;
  const Result roll = run_engine(load_scene("slide-to-roll"), find_engine("box2d"), o);
  ASSERT_EQ(roll.status, RunStatus::ok) << roll.error;
  ASSERT_TRUE(roll.metrics.number("rolling.speed") && roll.metrics.number("rolling.expected_speed") && roll.metrics.number("rolling.expected_time_to_roll"));
  EXPECT_NEAR(*roll.metrics.number("rolling.speed"), 2.0, 0.005 * 2.0);
  EXPECT_FALSE(roll.metrics.number("angle_of_repose"));
  const Result plain = run_engine(load_scene("corridor"), find_engine("box2d"), o);
  EXPECT_FALSE(plain.metrics.number("rolling.speed") || plain.metrics.number("rolling.expected_speed") || plain.metrics.number("angle_of_repose"));
}

}  // namespace
}  // namespace ballbench

// The report's friction section on a rolling scene: of one ball it states that ball's closed form;
// of several, that each ball has its own, and its table shows each run's ball farthest from it
// beside that ball's closed form. From hand-made results: no engine runs.
#include <gtest/gtest.h>

#include <cmath>

#include "friction_section.h"
#include "made_run.h"
#include "metrics/meter_set.h"
#include "result.h"

namespace ballbench {
namespace {

Result rolling_run(std::string engine, std::string scene, int n, double speed, double expected) {
  Result r = made_run(std::move(engine), std::move(scene), n, 150);
  r.metrics.set(Metric::rolling_speed, speed);
  r.metrics.set(Metric::rolling_expected_speed, expected);
  r.metrics.set(Metric::rolling_error, std::abs(speed - expected) / std::abs(expected));
  r.metrics.set(Metric::rolling_expected_time_to_roll, 0.204);
  r.metrics.set(Metric::slip_time_to_roll, 0.21);
  r.metrics.set(Metric::slip_final_max, 0.0);
  return r;
}

TEST(FrictionSection, OneBallStatesItsClosedForm) {
  const std::string md = friction_section({rolling_run("a", "roll", 1, 2.01, 2.0)}, {"roll"});
  EXPECT_NE(md.find("it ends rolling at **2 m/s** from t = **0.204 s**"), std::string::npos) << md;
  EXPECT_NE(md.find("| engine | status | final speed (m/s) | vs closed form |"), std::string::npos) << md;
  EXPECT_NE(md.find("| a | ok | 2.0100 | +0.50% | 0.21 | +0.006 s | 0 |"), std::string::npos) << md;
}

// Two engines whose farthest balls differ: each row has its own ball's closed form.
TEST(FrictionSection, ManyBallsShowEachRunsBallFarthestFromItsClosedForm) {
  const std::string md = friction_section(
      {rolling_run("a", "rolls", 100, 1.98, 2.0), rolling_run("b", "rolls", 100, 0.7, 2.0 / 3)}, {"rolls"});
  EXPECT_NE(md.find("100 balls; closed forms from the scene (core/metrics/rolling.h): each ball ends rolling at its "
                    "own (v0_i - k r_i w0_i) / (1 + k) (v0_i / (1 + k) without spin), every one by t = **0.204 s**. "
                    "The table shows the ball farthest from its closed form."),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| engine | status | farthest ball's final speed (m/s) | its closed form (m/s) | vs "
                    "closed form |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| a | ok | 1.9800 | 2.0000 | -1.00% |"), std::string::npos) << md;
  EXPECT_NE(md.find("| b | ok | 0.7000 | 0.6667 | +5.00% |"), std::string::npos) << md;
  EXPECT_EQ(md.find("it ends rolling at"), std::string::npos) << md;
}

}  // namespace
}  // namespace ballbench

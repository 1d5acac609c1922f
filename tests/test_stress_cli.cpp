// `ballbench stress`: one frontier table; our continuous solvers survive the bullet scene at every
// level, and a discrete engine's frontier names why it failed.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include "cli_runner.h"

namespace {

// stdout and stderr together: the table, or the one-line error.
std::string capture(const std::string& args) {
  const auto o = ballbench::testing::run_cli(args);
  return o.out + o.err;
}

TEST(StressCli, PrintsOneFrontierTable) {
  const std::string out = capture("stress --scene bullet --engine home,home-seed --knobs dt,speed --levels 3");
  EXPECT_NE(out.find("frontier"), std::string::npos) << out;
  // home: continuous collision, nothing passes through at 4 x dt or 4 x speed.
  EXPECT_NE(out.find("home               dt                0.01       0.04  (passed all 3 levels)"), std::string::npos) << out;
  // home-seed: the thesis's discrete checks let the bullet through already at the base level.
  EXPECT_NE(out.find("home-seed          dt                0.01       none"), std::string::npos) << out;
}

TEST(StressCli, RejectsAnUnknownKnob) {
  const std::string out = capture("stress --scene bullet --engine home --knobs gravity");
  EXPECT_NE(out.find("unknown knob 'gravity'"), std::string::npos) << out;
}

}  // namespace

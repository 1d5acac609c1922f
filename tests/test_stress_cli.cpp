// `ballbench stress`: one frontier table; our continuous solvers survive the bullet scene at every
// level, and a discrete engine's frontier names why it failed.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include <filesystem>

#include "cli_runner.h"
#include "frontier_result.h"

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

// An engine that refuses the scene has no frontier: home's soft profile, in the bullet scene
// without gravity, reads "refused" with the reason, where an engine that ran and failed reads "none".
TEST(StressCli, AnEngineThatRefusesTheSceneIsRefusedNotNone) {
  const std::string out = capture("stress --scene bullet --engine home --profile soft --knobs dt --levels 2");
  EXPECT_NE(out.find("refused  unsupported: home (soft): the soft step is for scenes with gravity"), std::string::npos)
      << out;
  EXPECT_EQ(out.find("none"), std::string::npos) << out;
}

TEST(StressCli, RejectsAnUnknownKnob) {
  const std::string out = capture("stress --scene bullet --engine home --knobs gravity");
  EXPECT_NE(out.find("unknown knob 'gravity'"), std::string::npos) << out;
}

}  // namespace

namespace ballbench {
namespace {

TEST(StressCli, WritesTheFrontierAsJson) {
  const std::string path = std::filesystem::temp_directory_path() / ("bb_stress." + std::to_string(::getpid()) + ".json");
  const auto o = testing::run_cli("stress --scene bullet --engine home,home-seed --knobs dt --levels 2 --quiet --json " + path);
  ASSERT_EQ(o.status, 0) << o.err;
  const FrontierResult f = read_frontier_file(path);
  std::filesystem::remove(path);
  EXPECT_EQ(f.scene, "bullet");
  EXPECT_EQ(f.levels, 2);
  ASSERT_EQ(f.rows.size(), 2u);
  // In the order of --engine.
  EXPECT_EQ(f.rows[0].engine, "home");
  EXPECT_EQ(f.rows[0].levels_passed, 2);
  EXPECT_EQ(f.rows[0].factor, 2);
  EXPECT_EQ(f.rows[0].failed_next, "");
  EXPECT_EQ(f.rows[1].engine, "home-seed");
  EXPECT_EQ(f.rows[1].levels_passed, 0);
  EXPECT_EQ(f.rows[1].factor, 0);
  EXPECT_NE(f.rows[1].failed_next, "");
}

}  // namespace
}  // namespace ballbench

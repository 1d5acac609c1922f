// `ballbench stress`: one frontier table; our continuous solvers survive the bullet scene at every
// level, and a discrete engine's frontier names why it failed.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace {

std::string capture(const std::string& args) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen((std::string(BALLBENCH_CLI) + " " + args + " 2>&1").c_str(), "r"), pclose);
  char buf[4096];
  while (p && fgets(buf, sizeof buf, p.get())) out += buf;
  return out;
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

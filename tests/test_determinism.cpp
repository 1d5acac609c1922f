// Determinism: the same scene, engine, settings and build give bit-identical trajectories for our
// double-precision solvers, seen through the checksums the runner computes from every state it
// reads (Result::checksum_*, core/runner.h).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>

#include "isolated_run.h"
#include "registry.h"
#include "runner.h"
#include "scene_loader.h"
#include "trajectory_csv.h"

namespace ballbench {
namespace {

Result run(const Scene& scene, const std::string& engine, long steps, TrajectoryCsv* csv = nullptr) {
  RunOptions o;
  o.steps = steps;
  o.trajectory = csv;
  return run_engine(scene, find_engine(engine), o);
}

struct Case {
  const char* engine;
  const char* scene;
  long steps;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.engine << " on " << c.scene << ", " << c.steps << " steps"; }

class Deterministic : public ::testing::TestWithParam<Case> {};

TEST_P(Deterministic, TwoRunsGiveTheSameChecksums) {
  const auto [engine, scene_name, steps] = GetParam();
  const Scene scene = load_scene(scene_name);
  const Result a = run(scene, engine, steps), b = run(scene, engine, steps);
  ASSERT_EQ(a.status, RunStatus::ok) << a.error;
  ASSERT_EQ(a.checksum_trajectory.size(), 16u);
  EXPECT_EQ(a.checksum_final, b.checksum_final);
  EXPECT_EQ(a.checksum_trajectory, b.checksum_trajectory);
  // A fresh scene object (parsed again) and a run in a child process change nothing either.
  const Result c = run_engine_isolated(load_scene(scene_name), find_engine(engine), [&] {
    RunOptions o;
    o.steps = steps;
    return o;
  }(), {});
  EXPECT_EQ(a.checksum_trajectory, c.checksum_trajectory);
  // Nor does writing the trajectory as it runs.
  const std::string csv_path = ::testing::TempDir() + "bb_determinism." + std::to_string(::getpid()) + ".csv";
  TrajectoryCsv csv(csv_path, false);
  EXPECT_EQ(a.checksum_trajectory, run(scene, engine, steps, &csv).checksum_trajectory);
  csv.close();
  std::filesystem::remove(csv_path);
}

// `exact` is event-driven and `home` iterates contacts: both must still repeat themselves exactly.
// Step counts keep each case well under a second.
INSTANTIATE_TEST_SUITE_P(OurSolvers, Deterministic,
                         ::testing::Values(Case{"home", "seed-box", 500}, Case{"home", "seed-bowl", 300},
                                           Case{"exact", "seed-box", 500}, Case{"exact", "seed-bowl", 300},
                                           Case{"home-seed", "seed-box", 100}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = std::string(info.param.engine) + "_" + info.param.scene;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(Checksum, DiffersForADifferentTrajectory) {
  const Scene scene = load_scene("seed-box");
  const Result a = run(scene, "home", 200), b = run(scene, "home", 201);
  EXPECT_NE(a.checksum_trajectory, b.checksum_trajectory);
  EXPECT_NE(a.checksum_final, b.checksum_final);
}

TEST(Checksum, SeesEveryBitOfEveryNumber) {
  State s;
  s.resize(3);
  s.pos.setConstant(1.0), s.vel.setConstant(-2.0);
  const uint64_t base = state_checksum(s);
  for (int col = 0; col < 2; ++col)
    for (int i = 0; i < 3; ++i)
      for (Eigen::MatrixX2d* m : {&s.pos, &s.vel}) {
        State t = s;
        double& v = (m == &s.pos ? t.pos : t.vel)(i, col);
        v = std::nextafter(v, std::numeric_limits<double>::infinity());  // one ulp
        EXPECT_NE(state_checksum(t), base);
      }
  State z;
  z.resize(1);
  z.pos.setZero(), z.vel.setZero();
  State nz = z;
  nz.vel(0, 1) = -0.0;  // equal as numbers, different bits: a determinism check must see it
  EXPECT_NE(state_checksum(z), state_checksum(nz));
  s.t = 5.0;  // time is not part of it
  EXPECT_EQ(state_checksum(s), base);
  EXPECT_EQ(checksum_hex(0x1234), "0000000000001234");
}

TEST(Checksum, TellsFloat32StatesApartInEveryBit) {
  // A float engine's state read as doubles has 29 zero mantissa bits per value. Two such states
  // one float ulp apart must differ in the low bits of their checksums too, not only the high ones
  // (each bit of the checksum flips for about half of the single-value changes).
  State s;
  s.resize(50);
  for (int i = 0; i < 50; ++i) s.pos(i, 0) = 0.1f * i, s.pos(i, 1) = -0.3f * i, s.vel(i, 0) = 1.5f, s.vel(i, 1) = 0.25f * i;
  const uint64_t base = state_checksum(s);
  uint64_t flipped = 0;  // bits of the checksum that some one-ulp change flipped
  for (int i = 0; i < 50; ++i) {
    State t = s;
    t.pos(i, 0) = std::nextafter(static_cast<float>(t.pos(i, 0)), 1e9f);
    const uint64_t h = state_checksum(t);
    EXPECT_NE(h, base);
    flipped |= h ^ base;
  }
  EXPECT_EQ(flipped & ((1ull << 29) - 1), (1ull << 29) - 1);  // every low bit moved for some change
}

TEST(Checksum, IsInTheResultJson) {
  const Result a = run(load_scene("seed-box"), "home", 10);
  const nlohmann::json j = to_json(a);
  EXPECT_EQ(j["checksum"]["final"], a.checksum_final);
  EXPECT_EQ(j["checksum"]["trajectory"], a.checksum_trajectory);
  const Result back = result_from_json(j);
  EXPECT_EQ(back.checksum_final, a.checksum_final);
  EXPECT_EQ(back.checksum_trajectory, a.checksum_trajectory);
}

}  // namespace
}  // namespace ballbench

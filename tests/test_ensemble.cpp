// Seed ensembles: the bootstrap interval of a mean, the paired comparison with our solver, and
// `run --seeds K` drawing K placements.
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "ensemble.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

TEST(Ensemble, TheBootstrapIntervalHoldsTheMeanAndShrinksToAConstant) {
  const Interval c = bootstrap_mean({2.5, 2.5, 2.5, 2.5});
  EXPECT_EQ(c.mean, 2.5);
  EXPECT_EQ(c.lo, 2.5);
  EXPECT_EQ(c.hi, 2.5);
  const Interval s = bootstrap_mean({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  EXPECT_DOUBLE_EQ(s.mean, 5.5);
  EXPECT_LT(s.lo, 5.5);
  EXPECT_GT(s.hi, 5.5);
  EXPECT_GT(s.lo, 3.0);  // the standard error is 0.96: a 95% interval is about +-1.9
  EXPECT_LT(s.hi, 8.0);
  EXPECT_EQ(bootstrap_mean({}).n, 0);
}

Result run_of(const std::string& engine, int64_t seed, double ns) {
  Result r;
  r.engine = engine, r.profile = "default", r.scene = "s", r.seed_offset = seed, r.ns_per_ball_step = ns;
  return r;
}

TEST(Ensemble, DifferencesOnTheSamePlacementsAreJudgedPaired) {
  // "slow" is 10 above ours on every placement although the placements spread far more than that;
  // "same" differs from ours by +-1 in turn.
  std::vector<Result> runs;
  for (int k = 0; k < 6; ++k) {
    const double base = 100.0 * (k + 1);
    runs.push_back(run_of("ours", k, base));
    runs.push_back(run_of("slow", k, base + 10));
    runs.push_back(run_of("same", k, base + (k % 2 ? 1 : -1)));
  }
  for (int k = 0; k < 2; ++k) {  // failed on two placements: one row, with no runs
    runs.push_back(run_of("broken", k, 1));
    runs.back().status = RunStatus::failed;
  }
  const auto rows = summarise_ensemble(runs, "ours");
  const auto& names = ensemble_metrics();
  const size_t ns = std::find_if(names.begin(), names.end(), [](const EnsembleMetric& m) { return m.name == "ns/ball-step"; }) -
                    names.begin();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].label, "ours");
  EXPECT_EQ(rows[0].versus_ours[ns], "");
  EXPECT_EQ(rows[1].versus_ours[ns], "+");
  EXPECT_EQ(rows[2].versus_ours[ns], "=");
  EXPECT_EQ(rows[3].placements, 0);  // failed runs are left out of the means
  EXPECT_FALSE(rows[3].metrics[ns]);
  EXPECT_DOUBLE_EQ(rows[1].metrics[ns]->mean, 360);
}

TEST(Ensemble, SeedOffsetsDrawAnotherPlacementOfTheSameRules) {
  const Scene a = load_scene("seed-box"), b = load_scene("seed-box", 1), c = load_scene("seed-box", 1);
  EXPECT_TRUE(a.random_placement);
  EXPECT_EQ(b.seed_offset, 1);
  EXPECT_NE(a.initial.pos, b.initial.pos);
  EXPECT_EQ(b.initial.pos, c.initial.pos);
  EXPECT_EQ(a.n(), b.n());
}

TEST(Ensemble, RunWithSeedsPrintsIntervalsAndRefusesAFixedScene) {
  const auto o = testing::run_cli("run --scene seed-box --engine home,exact --steps 50 --seeds 3 --quiet");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("3 placements of seed-box"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("exact                3"), std::string::npos) << o.out;
  const auto fixed = testing::run_cli("run --scene newtons-cradle --engine home --seeds 2 --quiet");
  EXPECT_EQ(fixed.status, 2) << fixed.err;
  EXPECT_NE(fixed.err.find("has no random placement"), std::string::npos) << fixed.err;
}

}  // namespace
}  // namespace ballbench

// The reference recorded once and replayed beside each run (core/recorded_reference.h) gives every
// run the figures it had with the reference stepped beside it, for `exact` and for a converged
// stand-in; a recording of another scene is not replayed, and one past its time limit is not made.
#include <gtest/gtest.h>

#include "recorded_reference.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

RunOptions referenced(long steps) {
  RunOptions o;
  use_reference(o);
  o.steps = steps;
  o.series_points = 50;
  return o;
}

// The error against the reference and its label, as the results file holds them.
nlohmann::json reference_part(const Result& r) {
  const nlohmann::json j = to_json(r);
  return {j.at("error_vs_reference"), j.value("series", nlohmann::json())};
}

void expect_replay_matches(const std::string& scene_name, long steps, const std::string& reference, int substeps) {
  const Scene scene = load_scene(scene_name);
  const RunOptions lockstep = referenced(steps);
  const auto recorded = record_reference(scene, lockstep, 120);
  ASSERT_TRUE(recorded) << scene_name;
  EXPECT_EQ(recorded->engine, reference);
  EXPECT_EQ(recorded->substeps, substeps);
  EXPECT_EQ(long(recorded->states.size()), steps + 1);
  RunOptions replayed = lockstep;
  replayed.recorded_reference = recorded;
  for (const char* engine : {"home", "chipmunk"}) {
    const Result a = run_engine(scene, find_engine(engine), lockstep);
    const Result b = run_engine(scene, find_engine(engine), replayed);
    ASSERT_EQ(a.status, RunStatus::ok) << engine << ": " << a.error;
    EXPECT_EQ(reference_part(a), reference_part(b)) << engine << " on " << scene_name;
    EXPECT_EQ(to_json(a).at("error_vs_reference").at("reference"), to_json(b).at("error_vs_reference").at("reference"));
  }
}

TEST(RecordedReference, ReplayingExactGivesTheFiguresOfExactSteppedBesideTheRun) {
  expect_replay_matches("seed-box", 300, "exact", 1);
}

TEST(RecordedReference, ReplayingAConvergedRunGivesTheFiguresOfItSteppedBesideTheRun) {
  // Rough balls: exact refuses them, a converged run at dt / 64 stands in.
  expect_replay_matches("rough-box", 60, converged_reference_engine()->info.name, kConvergedSubsteps);
}

TEST(RecordedReference, ARecordingOfAnotherPlacementIsNotReplayed) {
  const RunOptions o = referenced(200);
  RunOptions other = o;
  other.recorded_reference = record_reference(load_scene("seed-box", 1), o, 120);
  ASSERT_TRUE(other.recorded_reference);
  const Scene scene = load_scene("seed-box");
  EXPECT_EQ(reference_part(run_engine(scene, find_engine("home"), o)),
            reference_part(run_engine(scene, find_engine("home"), other)));
}

TEST(RecordedReference, ARecordingPastItsTimeLimitIsNotMadeAndRunsStepTheirOwn) {
  // A converged run of rough-box's 500 steps takes about a second, far past a millisecond.
  const Scene scene = load_scene("rough-box");
  EXPECT_FALSE(record_reference(scene, referenced(-1), 1e-3));
  RunOptions none;
  EXPECT_FALSE(record_reference(scene, none, 120)) << "no reference asked for, none recorded";
}

TEST(RecordedReference, RunAllReplaysOneRecordingInEveryIsolatedRun) {
  const Scene scene = load_scene("rough-box");
  const RunOptions o = referenced(40);
  const std::vector<const EngineEntry*> engines{&find_engine("home"), &find_engine("box2d")};
  const auto together = cli::run_all(scene, engines, "all", o, true, cli::Isolation{true, 120});
  ASSERT_EQ(together.size(), cli::run_count(engines, "all"));
  for (const Result& r : together) {
    RunOptions alone = o;
    alone.profile = r.profile;
    EXPECT_EQ(reference_part(r), reference_part(run_engine(scene, find_engine(r.engine), alone)))
        << r.engine << "/" << r.profile;
  }
}

}  // namespace
}  // namespace ballbench

#pragma once
// A run's meters: one per metric family that applies to its scene (metrics/meter.h), fed by the
// run's stages (run_stages.h) at the stage each watches. Engine-agnostic: it sees states and the
// scene only.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "metrics/meter.h"

namespace ballbench {

class MeterSet {
 public:
  MeterSet(const Scene& scene, const MetricsConfig& config);

  // A sampled state; the first one is the initial state. `interruptible`: asked to stop
  // (interrupt.h) between two meters, it throws Interrupted, this sample unused (the initial state
  // of millions of balls takes seconds to measure, and the run ends before its first step).
  void sample(const State& s, bool interruptible = false);
  // One step of motion, from `prev` to `cur` (every step the engine provides a state for).
  void motion(const State& prev, const State& cur);
  // The last good state, once.
  void final_state(const State& s);
  // Why the run cannot go on after the last sample or motion (a meter of that stage says it
  // diverged), or none.
  std::optional<std::string> stop_after_sample() const { return first_stop(sample_); }
  std::optional<std::string> stop_after_motion() const { return first_stop(motion_); }

  // The values of the meter that measures `m`, as measured so far (only that meter writes, at each
  // sample: the spec's stop and the figures' series read one or two values).
  MetricValues values_of(Metric m) const;
  // One value as measured so far, or none.
  std::optional<double> now(Metric m) const { return values_of(m).number(m); }
  void write(MetricValues& out) const;
  MetricValues values() const {
    MetricValues v;
    write(v);
    return v;
  }
  const std::vector<Event>& events() const { return events_.events(); }
  // The families' notes for the result's `skipped` list: why one does not run, how to read one
  // that does, what one could not measure.
  std::vector<std::string> notes() const;

 private:
  const Scene& scene_;
  std::vector<std::unique_ptr<Meter>> sample_, motion_, final_;
  std::vector<std::pair<const MetricFamily*, const Meter*>> meters_;  // every one, in catalog order
  std::vector<std::string> family_notes_;
  EventLog events_;
  long motion_steps_ = 0, samples_ = 0;
  OverlapScratch scratch_;
  std::vector<Overlap> overlaps_;
  std::vector<NearestWall> walls_;

  static std::optional<std::string> first_stop(const std::vector<std::unique_ptr<Meter>>& meters);
};

// The metrics of a run that watched one ball at rest in open space: every metric every scene
// measures, each at its value for nothing happening (counts 0, drifts 0, vectors (0, 0)). The
// shape of a results file, and a run made by hand in a test.
MetricValues resting_values();

}  // namespace ballbench

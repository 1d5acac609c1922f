#pragma once
// A benchmark's run judged against its scene's accuracy spec, from states the benchmark reads
// outside its timing: the timed steps are not only fast, they compute what the scene asks. The
// terms judged are those a few states show: the overlap (penetration after the first state read,
// metrics/penetration_metric.cpp), the rest speed of a pile (the final RMS speed, jitter), and no
// ball beyond a wall. Tunnelling between two balls lasts a step and needs every step's motion, which
// a timed loop does not read: `ballbench run` judges it.
#include <string>

#include "accuracy_spec.h"
#include "metrics/meter_set.h"
#include "scene.h"
#include "state.h"

namespace ballbench::bench {

class SpecCheck {
 public:
  explicit SpecCheck(const Scene& scene);
  // A state read between timed steps; the first is where the timing starts.
  void sample(const State& s);
  // The last state read: the verdict so far, as "met: overlap 0.0041 <= 0.01, rest_speed ..." or
  // "not met: overlap 0.031 > 0.02".
  std::string verdict(const State& last);
  bool met() const { return met_; }
  double overlap() const { return overlap_; }  // the spec's overlap figure, as of the last verdict

 private:
  const Scene& scene_;
  AccuracySpec spec_;  // the scene's, the terms a few states show
  MeterSet meters_;
  bool left_box_ = false, met_ = false;
  long samples_ = 0;
  double overlap_ = 0;
};

// A centre beyond a wall by more than the largest diameter: the runner's divergence rule (the
// tunnelling meter's stop, core/metrics/tunnelling_metric.cpp), which `ballbench run` reports as diverged.
bool left_the_box(const Scene& scene, const State& s);

}  // namespace ballbench::bench

#pragma once
// Slip of balls touching a wall: the speed of the ball's contact point along the wall,
//   s = |v . t - w r|,   t = z x n (the wall's inward normal n turned a quarter counter-clockwise),
// zero when the ball rolls (Goldstein, Classical Mechanics, rolling without slipping). A ball
// touches a wall when its centre is within r (1 + contact tolerance) of it. Only for scenes that
// rotate and have walls: slip_metric.cpp builds a tracker there alone.
#include <optional>

#include "scene.h"
#include "state.h"

namespace ballbench {

struct SlipSummary {
  // The largest slip of a ball touching a wall in the last sample (m/s); 0 when none touches.
  double final_max = 0;
  // The time from which on no ball touching a wall slips faster than the roll tolerance (s): the
  // time to roll. None when the last sample still slips or no ball ever touched a wall.
  std::optional<double> time_to_roll;
};

class SlipTracker {
 public:
  // contact_tolerance: as MetricsConfig's; roll_tolerance: the slip (m/s) below which a ball rolls.
  SlipTracker(const Scene& scene, double contact_tolerance, double roll_tolerance);
  void observe(const State& s);
  SlipSummary summary() const;

 private:
  const Scene& scene_;
  double contact_tolerance_, roll_tolerance_;
  bool touched_ = false;
  double final_max_ = 0;
  std::optional<double> rolling_since_;
};

}  // namespace ballbench

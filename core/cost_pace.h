#pragma once
// How a run's engine time accrues over the scene (its pace), and what a run stopped part way would
// cost in whole. A pile's steps grow costlier as it forms, a gas's stay alike: time so far over
// the share of steps done projects a pile low and stops its costly tries late. A search records the
// pace of one whole run of each engine and profile (its first try, at the scene's own step: 1/2^k of
// a try at dt/2^k) and projects every later try of that engine from the same point of the scene.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace ballbench {

// A pace's points: the engine time at each 1/kPacePoints of the run's steps.
inline constexpr int kPacePoints = 32;

// A run is projected from this share of its steps on: before it, its time is mostly the engine's
// start (allocations, a JIT's first compilations), which says little of its steps.
inline constexpr double kPaceFrom = 1.0 / 16;

// A run stops on its projection only past this multiple of its cost limit: a knob can change the
// pace a little (more iterations weigh on contacts, which grow as a pile forms), and a configuration
// that would have stayed under the limit must not stop on the projection's error. One past its limit
// by less runs on until its time so far passes it.
inline constexpr double kPaceMargin = 1.25;

class CostPace {
 public:
  CostPace() = default;
  // The engine time (s) at each 1/kPacePoints of a whole run; anything else (a run that stopped
  // short, a time that falls or is not positive) is no pace.
  static std::optional<CostPace> from_points(const std::vector<double>& seconds);

  // The whole run's engine time projected from `spent` (s) at `share` of its steps (0 .. 1): as
  // much more as the pace's run spent after that share, proportionally.
  double project(double spent, double share) const;

  const std::vector<double>& points() const { return s_; }

 private:
  std::vector<double> s_;
};

// The points of a pace a run of `steps` steps has reached by step k: one per 1/kPacePoints.
inline size_t pace_points_reached(long k, long steps) {
  return steps > 0 ? size_t(std::min<long>(kPacePoints, k * kPacePoints / steps)) : 0;
}

}  // namespace ballbench

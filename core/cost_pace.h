#pragma once
// How a run's engine time accrues over the scene (its pace), and what a run stopped part way would
// cost in whole. A pile's steps grow costlier as it forms, a gas's stay alike: time so far over
// the share of steps done projects a pile low and stops its costly tries late. A search records
// each try's pace, to its end or to where it stopped, and projects a later try with the nearest
// one in configuration and step (match.cpp, pace_for), from the same point of the scene.
#include <algorithm>
#include <cstddef>
#include <map>
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
  // The engine time (s) at each 1/kPacePoints of a run's steps, as far as it went: a run stopped
  // at a cost limit is the pace of what it covered, at least kPaceFrom of the run. Times that fall,
  // or a last one that is not positive, are no pace.
  static std::optional<CostPace> from_points(const std::vector<double>& seconds);

  // The whole run's engine time projected from `spent` (s) at `share` of its steps (0 .. 1): as
  // much more as the pace's run spent after that share, proportionally. Past the share its points
  // cover, the pace goes on at the rate of its last quarter: the rate a pile's steps only grow from
  // as it forms, so the projection errs low, never stopping a run that would have stayed under.
  double project(double spent, double share) const;

  const std::vector<double>& points() const { return s_; }

 private:
  double at(double share) const;  // the pace's time at `share`, 0 at the start
  std::vector<double> s_;
};

// What a run that spent `spent` (s) by `share` of its steps costs in whole: at `pace` where there
// is one, else in proportion to its steps (which projects a forming pile low). None before kPaceFrom
// of its steps: its time is mostly the engine's start then (a JIT's first compilations), which
// would project far too high.
std::optional<double> whole_run_cost(double spent, double share, const CostPace* pace);

// The pace a search projects a try at dt / 2^k with, of the paces its tries recorded (`paces`, by
// try index): its own configuration's at the nearest coarser step (`own`: halvings -> try index),
// else the profile as it is at the nearest step no finer (`as_is`), else `first` (the profile's run
// at the scene's step). A pile at dt may explode where it forms at dt / 16, its time accruing along
// another curve; one halving apart, one configuration forms the same pile at twice the steps. A
// pace that ended early (its try stopped where it missed) goes on at its last quarter's rate, which
// errs low on a forming pile.
const CostPace* nearest_pace(const std::map<int, int>& own, const std::map<int, int>& as_is,
                             const std::map<int, CostPace>& paces, int k, const CostPace* first);

// The points of a pace a run of `steps` steps has reached by step k: one per 1/kPacePoints.
inline size_t pace_points_reached(long k, long steps) {
  return steps > 0 ? size_t(std::min<long>(kPacePoints, k * kPacePoints / steps)) : 0;
}

}  // namespace ballbench

#pragma once
// Sticking: a pair that stays overlapping deeper than a tolerance, or a ball that stays in a wall
// deeper than a tolerance, for more than K consecutive samples and is not moving out at a sample
// past K. One event per episode (the run of samples). A real bounce resolves its overlap within a
// step or two; a pair that was placed overlapping (the thesis's random placement) and is moving
// apart is leaving, not stuck, however deep it started (measured: seed-box's pair 4-5 starts 0.12 m
// deep and parts at 0.85 m/s, 11 samples, in `exact` too).
#include <array>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "overlap.h"

namespace ballbench {

class StickingTracker {
 public:
  StickingTracker(int n, int max_samples) : max_samples_(max_samples), wall_run_(n, 0) {}

  // One sample: the pairs overlapping deeper than the tolerance with, for each, whether it is
  // moving apart (relative velocity along the line of centres > 0); for each ball whether it is in
  // a wall deeper than the tolerance and whether it is moving out of that wall.
  void observe(const std::vector<Overlap>& deep_pairs, const std::vector<char>& pair_leaving,
               const std::vector<char>& deep_in_wall, const std::vector<char>& wall_leaving);

  int pair_events() const { return pair_events_; }
  int wall_events() const { return wall_events_; }
  // The episodes the last observe() counted: pairs (i < j, in the order of deep_pairs) and balls
  // (in ball order).
  const std::vector<std::array<int, 2>>& counted_pairs() const { return counted_pairs_; }
  const std::vector<int>& counted_walls() const { return counted_walls_; }

 private:
  int max_samples_;
  // Consecutive samples so far; negative once the episode was counted (-length).
  std::unordered_map<long long, int> pair_run_, next_run_;  // pair key -> run
  std::vector<int> wall_run_;
  // Advances one run by a sample; counts the episode when it is due.
  int advance(int run, bool leaving, int& events) const;
  int pair_events_ = 0, wall_events_ = 0;
  std::vector<std::array<int, 2>> counted_pairs_;
  std::vector<int> counted_walls_;
};

}  // namespace ballbench

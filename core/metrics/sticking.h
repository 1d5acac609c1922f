#pragma once
// Sticking: a pair that stays overlapping deeper than a tolerance, or a ball that stays in a wall
// deeper than a tolerance, for more than K consecutive samples. One event per episode (the run of
// samples), counted when the run passes K. A real bounce resolves its overlap within a step or two.
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "overlap.h"

namespace ballbench {

class StickingTracker {
 public:
  StickingTracker(int n, int max_samples) : max_samples_(max_samples), wall_run_(n, 0) {}

  // One sample: the pairs overlapping deeper than the tolerance, and for each ball whether it is
  // in a wall deeper than the tolerance.
  void observe(const std::vector<Overlap>& deep_pairs, const std::vector<char>& deep_in_wall);

  int pair_events() const { return pair_events_; }
  int wall_events() const { return wall_events_; }

 private:
  int max_samples_;
  std::unordered_map<long long, int> pair_run_, next_run_;  // pair key -> consecutive samples
  std::vector<int> wall_run_;
  int pair_events_ = 0, wall_events_ = 0;
};

}  // namespace ballbench

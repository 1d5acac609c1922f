#pragma once
// Sleeping: without it a settled pile keeps micro-bouncing for ever. After a slow impact, a ball
// slower than rest_velocity whose weight the walls and sleeping balls within support_gap carry
// (-g in the cone of their contact normals: frictionless contacts push along their normals) is
// fixed at zero velocity; so is a group of slow balls that carry one another down to such
// supports, and a jammed ball. An impact of at least wake_velocity wakes a sleeping ball and,
// transitively, every sleeping ball resting on it; a slower one meets it as a fixed obstacle.
#include <cstdint>
#include <vector>

namespace ballbench {

struct ExactSim;

struct SleepScratch {
  std::vector<uint32_t> in_group;  // per ball: the group round it is a member of
  uint32_t group_round = 0;
  std::vector<int> group;          // the group being put to sleep
  std::vector<int> to_wake;        // stack of wake()

  explicit SleepScratch(int n) : in_group(n, 0) {}
};

// Do the walls and sleeping balls within support_gap of ball i carry its weight? `with_group`:
// balls of the group being put to sleep together count as well.
bool supported(const ExactSim& sim, int i, bool with_group = false);
// Ball i, after a slow impact, sleeps if it is slow and supported, or jammed.
void try_sleep(ExactSim& sim, int i);
// The slow awake balls among `candidates` that carry one another's weight fall asleep together.
void sleep_group(ExactSim& sim, const std::vector<int>& candidates);
// Wakes sleeping ball i and every sleeping ball resting on one that woke.
void wake(ExactSim& sim, int i);

}  // namespace ballbench

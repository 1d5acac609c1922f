#pragma once
// Sleeping by islands, as Box2D does it (b2BodyDef sleepThreshold, b2_timeToSleep): the balls that
// contacts pushing apart (impulse > 0) join form an island, and an island whose every ball has been
// slower than `speed` for `time` falls asleep whole: its balls stop and are not stepped. One ball
// frozen at a time would be a wall under the balls still settling on it, which would keep a pile's
// surface awake. An island wakes whole when a ball that can touch one of its balls within the step
// moves faster than `speed` relative to it: one landing on it, or one it rests on moving away.
//
// The state is per ball, indexed as the solver numbers its balls; `permute` follows a renumbering.
#include <cstdint>
#include <vector>

#include "solver/soft_step.h"

namespace ballbench {

class SleepIslands {
 public:
  enum State : uint8_t { kAwake = 0, kAsleep = 1, kWoken = 2 };  // kWoken: woken in this step

  SleepIslands() = default;
  SleepIslands(int n, double speed, double time);

  bool enabled() const { return !state_.empty(); }
  int sleeping() const { return sleeping_; }
  bool all_asleep() const { return sleeping_ == n_ && n_ > 0; }
  State state(int i) const { return static_cast<State>(state_[i]); }
  bool asleep(int i) const { return state_[i] != kAwake; }

  // Marks kWoken, and lists in woken(), every ball asleep in an island that one of `contacts`
  // joins to a ball awake moving faster than `speed` relative to it.
  void wake_touched(const std::vector<SoftContact>& contacts, const double* vx, const double* vy);
  const std::vector<int>& woken() const { return woken_; }
  // The woken balls' contacts are gathered: they are awake from here on.
  void finish_waking();

  // The balls awake (ascending) while some sleep, else none; then held_inv_mass() holds each
  // ball's inverse mass, 0 for the balls asleep (held still by the step). inv_mass may be null
  // (every ball has inv_mass0).
  const std::vector<int>& awake(const double* inv_mass, double inv_mass0);
  const std::vector<double>& held_inv_mass() const { return held_inv_mass_; }

  // After a step of dt: the islands whose every ball has been slow for `time` fall asleep, their
  // velocities set to 0. `awake` balls only are looked at (all of them when none sleeps).
  void fall_asleep(const std::vector<SoftContact>& contacts, double* vx, double* vy, double dt);

  // Renumbering: permute(array) moves each per-ball array with the balls.
  template <class F>
  void permute(F&& permute) {
    if (!enabled()) return;
    permute(state_.data()), permute(still_for_.data()), permute(island_of_.data());
  }

 private:
  template <class F>
  void for_awake(F&& f) const;

  int n_ = 0;
  double speed_ = 0, time_ = 0;
  std::vector<uint8_t> state_;      // State per ball
  std::vector<double> still_for_;   // how long each ball has been slower than speed_ (s)
  std::vector<int64_t> island_of_;  // per ball asleep: the island it fell asleep with (a label)
  int64_t islands_ = 0;             // labels used so far
  int sleeping_ = 0;                // balls asleep
  std::vector<int> woken_;          // the balls woken this step
  std::vector<int> awake_;          // the balls awake, while some sleep
  std::vector<double> held_inv_mass_;  // per ball while some sleep: 0 for a ball asleep
  // Scratch of wake_touched and fall_asleep.
  std::vector<int64_t> waking_islands_;
  std::vector<int> root_;           // union-find parents
  std::vector<double> island_still_;  // an island's least still time (s), at its root
  std::vector<int> falling_;
};

}  // namespace ballbench

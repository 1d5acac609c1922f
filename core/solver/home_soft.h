#pragma once
// `home`'s resting contact by the soft step (HomeSettings::resting = "soft", scenes with gravity).
// A step is cut into parts in which the fastest ball moves at most max_stride of the smallest
// radius (the soft step fixes each contact's normal for its step); each part gathers every pair
// and wall that can touch within it on home's grid, runs the soft step (soft_step.h) warm started
// from the last part's impulses, and lets islands sleep (sleep_islands.h).
#include <functional>
#include <vector>

#include "fork_join.h"
#include "solver/home.h"
#include "solver/home_grid.h"
#include "solver/home_world.h"
#include "solver/sleep_islands.h"
#include "solver/soft_step.h"
#include "solver/warm_start.h"

namespace ballbench {

class SoftResting {
 public:
  SoftResting() = default;
  SoftResting(const HomeSettings& s, int n);

  // Advances the world by dt; v_rest: the approach speed below which a contact does not bounce.
  // `grid` and `pool` are home's; `renumber_if_due` is called right after each build of the grid
  // (it may renumber the balls, and then calls permute_per_ball and renumbered).
  void step(HomeWorld& w, double dt, double v_rest, bool no_pairs, HomeGrid& grid, ForkJoin& pool,
            const std::function<void()>& renumber_if_due);

  // Renumbering: permute(array) moves each per-ball array with the balls; renumbered(new_number)
  // re-keys the stored impulses (new_number[old ball]).
  template <class F>
  void permute_per_ball(F&& permute) {
    sleep_.permute(permute);
  }
  void renumbered(const int* new_number) { warm_.renumber(new_number, true, warm_entries_); }

 private:
  void part(HomeWorld& w, double dt, double v_rest, bool no_pairs, const StartScan& start, HomeGrid& grid,
            ForkJoin& pool, const std::function<void()>& renumber_if_due);

  SoftStepSettings soft_;
  double max_stride_ = 0.5;
  int max_parts_ = 64;
  std::vector<SoftContact> contacts_;
  WarmStart warm_;  // each contact's impulse at the end of the last part, a pair keyed lower ball first
  std::vector<WarmStart::Entry> warm_entries_;  // for rebuilding warm_
  double warm_h_ = 0;  // the substep the warm start's impulses were accumulated over (s)
  SleepIslands sleep_;  // enabled with sleep_speed > 0
  SoftStepScratch scratch_;
};

}  // namespace ballbench

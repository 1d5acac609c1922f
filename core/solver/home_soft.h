#pragma once
// `home`'s resting contact by the soft step (HomeSettings::resting = "soft", scenes with gravity).
// A step is cut into parts in which the fastest ball moves at most max_stride of the smallest
// radius (the soft step fixes each contact's normal for its step); each part gathers every pair
// and wall that can touch within it on home's grid, runs the soft step (soft_step.h) warm started
// from the last part's impulses, and lets islands sleep (sleep_islands.h).
#include <algorithm>
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
  // (The candidates are built right after a renumbering, from the re-keyed warm start.)

 private:
  void part(HomeWorld& w, double dt, double v_rest, bool no_pairs, const StartScan& start, HomeGrid& grid,
            ForkJoin& pool, const std::function<void()>& renumber_if_due);
  // The part's contacts from the candidates, rebuilt first on the grid if a ball may have moved
  // beyond them (without sleeping).
  void gather_from_candidates(const HomeWorld& w, double dt, bool no_pairs, const StartScan& start, HomeGrid& grid,
                              ForkJoin& pool, const std::function<void()>& renumber_if_due);
  void build_candidates(const HomeWorld& w, double reach, bool no_pairs, const StartScan& start, HomeGrid& grid,
                        ForkJoin& pool, const std::function<void()>& renumber_if_due);
  // Every contact gathered afresh on the grid, around the balls awake (with sleeping).
  void gather_awake(HomeWorld& w, double dt, bool no_pairs, const StartScan& start, HomeGrid& grid, ForkJoin& pool,
                    const std::function<void()>& renumber_if_due);
  // A contact of this part, starting from the impulses it ended the last part with (a substep's
  // of that part: scaled to this part's substep).
  SoftContact warm_contact(int i, int j, double nx, double ny, double gap, double impulse, double tangent) const {
    SoftContact c{{i, j, nx, ny, 0.0, std::max(impulse, 0.0) * warm_scale_}, gap, 0.0, 0.0};
    c.tangent_impulse = impulse > 0 ? tangent * warm_scale_ : 0.0;
    return c;
  }

  SoftStepSettings soft_;
  double max_stride_ = 0.5;
  int max_parts_ = 64;
  std::vector<SoftContact> contacts_;
  // Without sleeping, the contacts come from candidates (Verlet's idea, as home's neighbour list):
  // every pair and wall within reach of touching at the build plus a skin (none while balls move
  // too fast for it to pay), kept while no ball can have moved beyond them, each with the impulse
  // its contact ended the last part with.
  struct Candidate {
    int i, j;  // j < 0: a wall (wall_partner)
    double impulse, tangent;  // normal and friction impulse (N s)
  };
  std::vector<Candidate> candidates_;
  std::vector<int> candidate_of_;  // per contact of the part: its candidate
  std::vector<Candidate> near_;    // with sleeping: this part's pairs within reach of touching
  std::vector<double> own_speed_, reach_speed_;  // per ball (m/s): its speed; its reach speed
  Eigen::MatrixX2d built_at_;      // positions at the candidates' build
  double built_reach_ = -1;        // the reach they were built for (m); negative: none built
  double built_skin_ = 0;          // and the skin (m)
  WarmStart warm_;  // each contact's impulse at the end of the last part, a pair keyed lower ball first
  std::vector<WarmStart::Entry> warm_entries_;  // for rebuilding warm_
  double warm_h_ = 0;  // the substep the warm start's impulses were accumulated over (s)
  double warm_scale_ = 1;  // this part's substep over warm_h_'s
  SleepIslands sleep_;  // enabled with sleep_speed > 0
  SoftStepScratch scratch_;
};

}  // namespace ballbench

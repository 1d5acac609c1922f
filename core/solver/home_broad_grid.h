#pragma once
// The events path's broad phase (home_events.h) in scenes with a contact pass: a uniform grid over
// the positions at the start of every step (home_grid.h), with cells wide enough that any two balls
// which can touch during the step are in adjacent cells (cell = 2 r_max + 2 x 1.5 v_max dt). Its
// screen marks the balls that can have an event this step and finds the contacts within reach of
// resting speeds, in the grid's cell order, which the contact pass's solve depends on.
// It models the BroadPhase concept (home_broad_phase.h), as ListBroadPhase does.
#include <functional>
#include <utility>
#include <vector>

#include "fork_join.h"
#include "solver/home.h"
#include "solver/home_broad_phase.h"
#include "solver/home_contacts.h"
#include "solver/home_grid.h"
#include "solver/home_step.h"
#include "solver/home_world.h"

namespace ballbench {

class GridBroadPhase {
 public:
  GridBroadPhase(const HomeShortcuts& sc, const HomeSettings& s, int n, int parts);

  // The last step's final advance (left to here by end_step), the kick v += g dt, the largest
  // speed and the positions' bounds, and the wall screen, in one parallel pass over the balls
  // (start_pass); then the grid over the positions now, for the step, and the balls renumbered in
  // its cell order if `renumber_if_due` says so.
  void start_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, bool renumber_due,
                  const std::function<bool()>& renumber_if_due);
  // Marks `active` every ball that may have an event this step (approaching a neighbour closely
  // enough, or able to reach a wall) and adds to `contacts` every contact within reach of resting
  // speeds (v_rest dt): the walls', then the pairs' in cell order, with their warm-start impulses.
  void screen(HomeWorld& w, EventStep& s, const HomeGrid& grid, ForkJoin& pool, RestingContacts& contacts);

  // The grid's screen gives no first events: next_event finds each active ball's.
  static FirstPair first_pair(int) { return {kNever, kAsk}; }
  static void first_events_queued() {}
  // Calls f(j) for every ball j that may touch ball i within the step (i itself among them).
  template <class F>
  void for_each_near(const HomeGrid& grid, int i, F&& f) const {
    if (!sc_.no_pairs) grid.for_each_near(i, std::forward<F>(f));
  }
  // Every ball's walls are looked at.
  static bool may_reach_wall(int) { return true; }
  // Ball i, just brought to time t with a new velocity, is faster than the grid allows for.
  bool too_fast(const HomeWorld& w, const EventStep&, int i, double) const { return w.v.row(i).squaredNorm() > vbound_ * vbound_; }
  // Resting impulses are far below the grid's speed bound: a cluster solve is not checked.
  static bool too_fast_after_rest(const HomeWorld&, const EventStep&, int, double) { return false; }
  // Every ball brought to time t (s) and the grid rebuilt from there for the rest of the step.
  void rebuild_mid_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, double t);
  // The final advance of the step is left to the next start_step, in the same pass as the kick.
  void end_step(HomeWorld&, const EventStep& s, ForkJoin&) { unfinished_ = s.dt; }
  // How long the last step still has to move each ball from its clock (s; 0: none).
  double unfinished() const { return unfinished_; }

 private:
  // What a pass of scan_range over balls does; each set is its own compiled loop.
  struct Scan {
    bool equal_radii = false;  // every ball has radius w.r0 (scan sets it from the shortcut)
    // A contact pass follows: a ball touching a wall is active and listed. False for the elastic
    // shortcut: no contact pass, so touching a wall is no reason to be predicted and no ball is
    // listed; an approach within the step still is.
    bool contacts = true;
    // start_pass: each ball is first brought to the end of the last step (if unfinished) and
    // kicked, and the speeds and positions are returned (else an empty StartScan).
    bool start = false;
    bool screen = false;  // the wall screen (screen_walls)
  };
  template <Scan kScan>
  StartScan scan(HomeWorld& w, EventStep& s, int b, int e, double reach, std::vector<int>& near);
  template <Scan kScan>
  StartScan scan_range(HomeWorld& w, EventStep& s, int b, int e, double reach, std::vector<int>& near);
  void start_pass(HomeWorld& w, EventStep& s, ForkJoin& pool, bool renumber_due);
  void build(const HomeWorld& w, HomeGrid& grid, ForkJoin& pool, double horizon, bool mid_step);
  void screen_walls(HomeWorld& w, EventStep& s, ForkJoin& pool, double reach);
  template <bool kEqualRadii>
  void screen_pairs(const HomeWorld& w, EventStep& s, const HomeGrid& grid, ForkJoin& pool,
                    const RestingContacts& contacts, double reach);
  HomeShortcuts sc_;
  StartScan start_;              // this step's start_pass, merged
  bool walls_screened_ = false;  // start_pass did this step's wall screen
  double vbound_ = 0;            // speed the grid allows for this step (m/s)
  double unfinished_ = 0;        // > 0: the last step (this long) awaits its final advance
  // Per part of the thread team (ForkJoin), filled in parallel, read in part order.
  std::vector<StartScan> start_parts_;                       // each part's share of start_pass
  std::vector<std::vector<int>> wall_hits_;                  // balls within contact reach of a wall
  std::vector<std::vector<std::pair<int, int>>> pair_hits_;  // ball pairs within contact reach
  std::vector<std::vector<PassContact>> pair_contacts_;      // their contacts
};

static_assert(BroadPhase<GridBroadPhase>);

}  // namespace ballbench

#pragma once
// The events path's broad phase (home_events.h) in elastic scenes (restitution 1, no resting
// speed): no contact pass, so the order of candidate pairs does not matter, and a neighbour list
// with a skin (neighbour_list.h; Verlet 1967) replaces the grid of every step. The list is kept
// while every ball stays within half the skin of where it was at the build, rebuilt when one may
// not (at the start of a step, or in mid-step when a collision takes a ball beyond it). Its screen
// computes the approaching pairs' collision times, which give the balls' first events.
// It models the BroadPhase concept (home_broad_phase.h), as GridBroadPhase does.
#include <array>
#include <functional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "fork_join.h"
#include "solver/home.h"
#include "solver/home_broad_phase.h"
#include "solver/home_contacts.h"
#include "solver/home_grid.h"
#include "solver/home_step.h"
#include "solver/home_world.h"
#include "solver/neighbour_list.h"

namespace ballbench {

class ListBroadPhase {
 public:
  ListBroadPhase(const HomeShortcuts& sc, const HomeSettings& s, int n, int parts);

  // The kick v += g dt (scenes with gravity and a resting speed of 0), then the list kept if it
  // covers the step, else built afresh from the positions now, the balls renumbered in its grid's
  // cell order if `renumber_if_due` says so.
  void start_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, bool renumber_due,
                  const std::function<bool()>& renumber_if_due);
  // Marks `active` every ball that may have an event this step (in a listed pair that approaches
  // closely enough, or near a wall at the build and able to reach it) and finds the approaching
  // pairs' collision times, for first_pair. Adds no contacts: an elastic scene has no contact pass.
  void screen(HomeWorld& w, EventStep& s, const HomeGrid& grid, ForkJoin& pool, RestingContacts& contacts);

  FirstPair first_pair(int i) const { return {first_t_[i], first_j_[i]}; }
  // The first events are queued: the screen's times are cleared for the next step.
  void first_events_queued();
  // The grid of the list's build: its cells, at least 2 r_max + skin wide, hold every listed
  // partner of ball i in the 3 x 3 block around i's.
  template <class F>
  void for_each_near(const HomeGrid& grid, int i, F&& f) const {
    grid.for_each_near(i, std::forward<F>(f));
  }
  // A ball not near a wall at the build cannot reach one while the list holds, even after
  // collisions (too_fast): its walls are not looked at.
  bool may_reach_wall(int i) const { return near_wall_mark_[i]; }
  // Ball i, at time t with a new velocity, may leave half the skin around where it was at the
  // build before the step ends.
  bool too_fast(const HomeWorld& w, const EventStep& s, int i, double t) const {
    return (w.p.row(i) - built_at_.row(i)).norm() + w.v.row(i).norm() * (s.dt - t) > half_skin_;
  }
  bool too_fast_after_rest(const HomeWorld& w, const EventStep& s, int i, double t) const { return too_fast(w, s, i, t); }
  // The list rebuilt from where each ball's line has taken it at time t (s), the balls left where
  // they are, so a rebuild changes no trajectory.
  void rebuild_mid_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, double t);
  // Every ball to the end of the step, its clock set back to 0; the same pass measures what the
  // next step's list check needs.
  void end_step(HomeWorld& w, EventStep& s, ForkJoin& pool);
  // end_step finishes every step.
  static double unfinished() { return 0; }

 private:
  // A pair the screen found approaching, and when it meets (kTouching: it touches now).
  struct Approach {
    int a, b;
    double t;
  };
  bool covers(double horizon) const;
  double start_speed(const HomeWorld& w) const;
  void rebuild(HomeWorld& w, HomeGrid& grid, ForkJoin& pool, double dt, double horizon, const Eigen::MatrixX2d& at,
               double vmax, const std::function<bool()>* renumber_if_due);
  template <bool kEqualRadii>
  void screen_list(const HomeWorld& w, EventStep& s, ForkJoin& pool);
  void first_pair_events();
  static std::array<double, 4> wall_gaps(const HomeWorld& w, double x, double y, double r);

  HomeShortcuts sc_;
  double list_steps_;           // the skin lets the fastest ball move this many steps
  NeighbourList list_;
  Eigen::MatrixX2d built_at_;   // positions when the list was built
  double half_skin_ = -1;       // how far a ball may move from there (m; negative: no list yet)
  std::vector<int> near_wall_;  // balls that can reach a wall before the list expires
  std::vector<uint8_t> near_wall_mark_;  // 1 for the balls in near_wall_
  // Per part: the largest squared displacement since the build and the largest squared speed,
  // measured by a step's end_step for the next step's check.
  std::vector<std::pair<double, double>> extent_;
  std::vector<std::vector<Approach>> approaches_;  // per part: the screen's approaching pairs
  std::vector<double> first_t_;  // each ball's first pair event at the start of the step (s; kNever: none)
  std::vector<int> first_j_;     // its partner (-1: none, kAsk: next_event decides)
  Eigen::MatrixX2d rebuild_at_;  // positions at a rebuild in mid-step
};

static_assert(BroadPhase<ListBroadPhase>);

}  // namespace ballbench

#pragma once
// home's events path: one step of dt in scenes the soft step does not run (core/solver/README.md,
// steps 1 to 6, and "Elastic scenes"), as stages:
//   1. the broad phase's start (start_step): the kick, and the broad phase for the step;
//   2. its screen and the contact pass (contact_pass): the balls that can have an event this step,
//      and the contacts within reach of resting speeds solved together;
//   3. event-driven drift (drift): each active ball's first event, then every event in time order,
//      each resting impact solved with its touching cluster (resolve_resting_cluster);
//   4. the broad phase's end of the step (end_step).
// One event loop serves both broad phases (the BroadPhase concept, home_broad_phase.h):
// EventPath<GridBroadPhase> (home_broad_grid.h: a grid every step, the scenes with a contact pass)
// and EventPath<ListBroadPhase> (home_broad_list.h: a neighbour list, elastic scenes). Each is
// compiled on its own, so the hot loops (the first predictions, next_event's walk over the near
// balls) call their broad phase inline, with no indirect call per pair or per event.
#include <cstdint>
#include <functional>
#include <vector>

#include "fork_join.h"
#include "solver/contact.h"
#include "solver/home.h"
#include "solver/home_broad_phase.h"
#include "solver/home_contacts.h"
#include "solver/home_grid.h"
#include "solver/home_step.h"
#include "solver/home_world.h"

namespace ballbench {

template <BroadPhase B>
class EventPath {
 public:
  // The world, grid and thread team are the engine's (Home), which outlives the path.
  EventPath(HomeWorld& w, HomeGrid& grid, ForkJoin& pool, const HomeSettings& settings, const HomeShortcuts& sc);

  // Advances the world by dt (s). v_rest: impacts slower than this are resting contact (m/s); t:
  // the simulated time at the step's end (s), for a failure's message. `renumber_if_due` renumbers
  // the balls in the grid's cell order right after the step's first grid build, if `renumber_due`.
  void step(double dt, double v_rest, double t, bool renumber_due, const std::function<bool()>& renumber_if_due);

  // How long the last step still has to move each ball from its clock (s; 0: every ball is at the
  // step's end), and the clocks: read() computes the end positions from them.
  double unfinished() const { return broad_.unfinished(); }
  const double* clocks() const { return step_.clock.data(); }

  // Renumbering: permute(array) moves each per-ball array with the balls; renumbered(new_number)
  // re-keys what is stored by ball number (new_number[old ball]).
  template <class F>
  void permute_per_ball(F&& permute) {
    permute(count_.data());
  }
  void renumbered(const int* new_number) { contacts_.renumbered(new_number); }

 private:
  void contact_pass();
  void drift(double t);
  // The two entries to the event search, one call per ball: flattened, so the search over the near
  // balls (next_event, its walk and its pair test) is one loop without calls, at -O2 as at -O3.
  [[gnu::flatten]] bool first_event(int i, PredictedEvent& best) const;
  void resolve_resting_cluster(int i, int j, double t);
  void rebuild_mid_step(double t);
  void end_angles();
  void push_event(const PredictedEvent& ev);
  PredictedEvent pop_event();
  double impact_speed(const PredictedEvent& ev) const;
  [[gnu::flatten]] void predict(int i);
  template <bool kAtStart = false>
  bool next_event(int i, PredictedEvent& best) const;
  template <bool kAtStart = false>
  void wall_event(int i, PredictedEvent& best) const;
  void collide_pair(int i, int j);
  void collide_wall(int i, int code);

  HomeWorld& w_;
  HomeGrid& grid_;
  ForkJoin& pool_;
  int contact_iterations_;   // most sweeps of the contact pass
  int max_events_per_ball_;  // more events per ball in a step is a failure
  bool elastic_;             // no contact pass (HomeShortcuts::elastic)
  EventStep step_;           // this step's clocks, active balls and constants
  B broad_;
  RestingContacts contacts_;
  std::vector<uint32_t> count_;  // collisions so far per ball, to recognise stale events
  // The event queue: a min-heap on t (see push_event), and per part of the thread team the active
  // balls' first events, queued in part order.
  std::vector<PredictedEvent> queue_;
  std::vector<std::vector<PredictedEvent>> first_events_;
  std::vector<int> cluster_;         // the balls of the resting cluster being solved
  std::vector<uint8_t> in_cluster_;  // per ball: 1 while in that cluster; 0 between clusters
};

}  // namespace ballbench

#pragma once
// What the events path's event loop (home_events.h) asks of its broad phase, stated once as a
// concept: GridBroadPhase (home_broad_grid.h: a grid every step, scenes with a contact pass) and
// ListBroadPhase (home_broad_list.h: a neighbour list, elastic scenes) each model it, and
// EventPath<B> is compiled for each, so the hot loops call their broad phase inline.
#include <concepts>
#include <functional>

#include "fork_join.h"
#include "solver/home.h"
#include "solver/home_contacts.h"
#include "solver/home_grid.h"
#include "solver/home_step.h"
#include "solver/home_world.h"

namespace ballbench {

template <class B>
concept BroadPhase =
    std::constructible_from<B, const HomeShortcuts&, const HomeSettings&, int, int> &&  // (shortcuts, settings, n, parts)
    requires(B& b, const B& cb, HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, RestingContacts& contacts,
             const std::function<bool()>& renumber_if_due, int i, double t, void (*each)(int)) {
      // The step's start: the kick and the broad phase for the step (renumbering the balls in the
      // grid's cell order if renumber_if_due says so, right after a build).
      b.start_step(w, s, grid, pool, bool{}, renumber_if_due);
      // Marks `active` every ball that may have an event this step and adds to `contacts` the
      // contacts within reach of resting speeds (none in an elastic scene).
      b.screen(w, s, grid, pool, contacts);
      // Ball i's first pair event as the screen found it, or {kNever, kAsk}: next_event decides.
      { cb.first_pair(i) } -> std::same_as<FirstPair>;
      b.first_events_queued();
      // Calls each(j) for every ball j that may touch ball i within the step (i among them).
      cb.for_each_near(grid, i, each);
      // Whether ball i's walls need looking at.
      { cb.may_reach_wall(i) } -> std::same_as<bool>;
      // Ball i, at time t (s) with a new velocity from a collision (or a resting solve), may leave
      // what the broad phase covers before the step ends: then rebuild_mid_step(t).
      { cb.too_fast(w, s, i, t) } -> std::same_as<bool>;
      { cb.too_fast_after_rest(w, s, i, t) } -> std::same_as<bool>;
      b.rebuild_mid_step(w, s, grid, pool, t);
      // The step's end; unfinished(): how long the last step still has to move each ball from its
      // clock (s; 0: every ball is at the step's end).
      b.end_step(w, s, pool);
      { cb.unfinished() } -> std::same_as<double>;
    };

}  // namespace ballbench

#include "solver/home_events.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/home_broad_grid.h"
#include "solver/home_broad_list.h"
#include "solver/home_impulse.h"
#include "solver/rough_impact.h"

namespace ballbench {
namespace {

// Sweeps the cluster solve may take to bring every contact within the velocity tolerance; a
// cluster that needs more is left to the event loop, which finishes the job one event at a time.
constexpr int kClusterIterations = 200;

}  // namespace

template <BroadPhase B>
EventPath<B>::EventPath(HomeWorld& w, HomeGrid& grid, ForkJoin& pool, const HomeSettings& settings,
                        const HomeShortcuts& sc)
    : w_(w),
      grid_(grid),
      pool_(pool),
      contact_iterations_(settings.contact_iterations),
      max_events_per_ball_(settings.max_events_per_ball),
      elastic_(sc.elastic),
      step_(w.n, settings.contact_slop),
      broad_(sc, settings, w.n, pool.parts()),
      contacts_(w.n),
      count_(w.n, 0),
      first_events_(pool.parts()) {
  // Sized in elastic scenes too: a grazing event whose approach rounds to 0 is a resting impact
  // there as well (impact_speed <= v_rest = 0), and its cluster solve needs the marks.
  in_cluster_.assign(w.n, 0);
}

// Symplectic Euler: velocity first (thesis eq. 3, in the bowl program's order), then the positions
// move along straight lines for the whole step, which the event loop follows exactly.
template <BroadPhase B>
void EventPath<B>::step(double dt, double v_rest, double t, bool renumber_due,
                        const std::function<bool()>& renumber_if_due) {
  step_.dt = dt;
  step_.v_rest = v_rest;
  broad_.start_step(w_, step_, grid_, pool_, renumber_due, renumber_if_due);
  // Approach speeds that close less than the contact slop over a step are round-off, not motion.
  step_.v_tol = step_.slop * w_.rmax / dt;
  contact_pass();
  drift(t);
}

// Resting contact at the start of the step: every contact within reach of resting speeds
// (v_rest dt) is solved together, so a pile settles in one pass instead of through a cascade of
// zero-time events. The broad phase's screen finds the contacts and marks the balls that may have
// an event this step (`active`); only active balls are predicted, the rest just move dt along
// their lines.
template <BroadPhase B>
void EventPath<B>::contact_pass() {
  contacts_.clear();
  broad_.screen(w_, step_, grid_, pool_, contacts_);
  if (elastic_) return;  // no contact pass: every impact is the event loop's
  contacts_.solve_pass(w_, step_, contact_iterations_);
}

// Event-driven motion over [0, dt]: every ball moves on its straight line until its next
// collision, found as the root of a quadratic, in time order (Alder & Wainwright 1959; event
// invalidation by per-ball collision counters as in Rapaport, "The Art of Molecular Dynamics").
template <BroadPhase B>
void EventPath<B>::drift(double t) {
  // Every ball's clock is 0 here: the last step's end (or this one's start) left it so.
  queue_.clear();
  // The active balls' predictions read only the state at the start of the step: on several
  // parts each predicts its fixed range of balls, and the events are queued in ball order, as
  // predicting one ball after the other would queue them.
  const int parts = pool_.parts();
  const uint8_t* active = step_.active.data();
  if (parts == 1) {
    PredictedEvent ev;
    for (int i = 0; i < w_.n; ++i)
      if (active[i] && first_event(i, ev)) push_event(ev);
  } else {
    pool_.run([&](int p) {
      first_events_[p].clear();
      const int b = static_cast<int>(ForkJoin::range_begin(w_.n, p, parts));
      const int e = static_cast<int>(ForkJoin::range_begin(w_.n, p + 1, parts));
      PredictedEvent ev;
      for (int i = b; i < e; ++i)
        if (active[i] && first_event(i, ev)) first_events_[p].push_back(ev);
    });
    for (const auto& events : first_events_)
      for (const PredictedEvent& ev : events) push_event(ev);
  }
  broad_.first_events_queued();
  const int64_t budget = static_cast<int64_t>(max_events_per_ball_) * w_.n + 1000;
  int64_t events = 0;
  while (!queue_.empty()) {
    const PredictedEvent ev = pop_event();
    if (count_[ev.i] != ev.ci) continue;  // i collided since: its new event is queued
    if (ev.j >= 0 && count_[ev.j] != ev.cj) {
      predict(ev.i);  // the partner changed course: look again
      continue;
    }
    if (++events > budget)
      throw std::runtime_error(fmt::format("home: more than {} collision events in one step at t = {} s "
                                           "(an inelastic collapse the contact solves did not resolve)",
                                           budget, t));
    step_.advance(w_, ev.i, ev.t);
    if (ev.j >= 0) step_.advance(w_, ev.j, ev.t);
    if (impact_speed(ev) <= step_.v_rest) {
      resolve_resting_cluster(ev.i, ev.j, ev.t);
      continue;
    }
    ev.j >= 0 ? collide_pair(ev.i, ev.j) : collide_wall(ev.i, ev.j);
    ++count_[ev.i];
    if (ev.j >= 0) ++count_[ev.j];
    if (broad_.too_fast(w_, step_, ev.i, ev.t) || (ev.j >= 0 && broad_.too_fast(w_, step_, ev.j, ev.t))) {
      rebuild_mid_step(ev.t);
      continue;
    }
    predict(ev.i);
    if (ev.j >= 0) predict(ev.j);
  }
  if (w_.rotation) end_angles();
  broad_.end_step(w_, step_, pool_);
}

// Ball i's earliest event from the start of the step: its walls (next_event's own loop), then its
// pair event as the broad phase's screen found it, or next_event itself where the screen cannot
// tell (kAsk).
template <BroadPhase B>
bool EventPath<B>::first_event(int i, PredictedEvent& best) const {
  const FirstPair pair = broad_.first_pair(i);
  if (pair.j == kAsk) return next_event<true>(i, best);
  best = {kNever, i, 0, count_[i], 0};
  wall_event<true>(i, best);
  // A pair event earlier than the wall's is never pruned in next_event (its bound holds until then).
  if (pair.j >= 0 && pair.t < best.t) best = {pair.t, i, pair.j, count_[i], count_[pair.j]};
  return best.t <= step_.dt;
}

// Every ball's angle from its own clock to the end of the step, before the clocks are set back
// for the next step (with the positions, at the broad phase's end of this step or start of the
// next): the angle is kept at the ball's clock, and from here on at the step's end.
template <BroadPhase B>
void EventPath<B>::end_angles() {
  for (int i = 0; i < w_.n; ++i) w_.angle(i) += w_.w(i) * (step_.dt - step_.clock[i]);
}

// A resting impact (slower than v_rest) at time t inside a pile: solve every contact of the
// touching cluster around it at once (the same sequential impulses, to the velocity tolerance),
// rather than one zero-time event at a time (an inelastic collapse of round-off otherwise).
template <BroadPhase B>
void EventPath<B>::resolve_resting_cluster(int i, int j, double t) {
  cluster_.clear();
  contacts_.clear();
  auto enter = [&](int b) {
    if (in_cluster_[b]) return;
    in_cluster_[b] = 1;
    step_.advance(w_, b, t);
    cluster_.push_back(b);
  };
  enter(i);
  if (j >= 0) enter(j);
  const double horizon = step_.dt - t;
  for (size_t k = 0; k < cluster_.size(); ++k) {
    const int a = cluster_[k];
    contacts_.add_wall_contacts(w_, step_, a, 0.0, horizon, false);
    broad_.for_each_near(grid_, a, [&](int b) {
      if (b == a) return;
      if (in_cluster_[b]) {
        if (b > a) return;  // both in the cluster: the pair is added once, from the larger index
      } else {
        step_.advance(w_, b, t);  // along its own line: its queued prediction stays valid
      }
      if (contacts_.add_pair_contact(w_, step_, a, b, 0.0, horizon, false)) enter(b);
    });
  }
  // Sequential impulses need not converge within the cluster's sweeps (a jammed pile converges
  // slowly); then the step's round-off tolerance rises to twice what the solve left,
  // so the same residual cannot fire the same cluster again. Overlap stays below residual x dt,
  // and the next contact pass closes it.
  for (int b : cluster_) in_cluster_[b] = 0;
  const double left = contacts_.solve(w_, kClusterIterations, 0.5 * step_.v_tol);
  step_.v_tol = std::max(step_.v_tol, 2.0 * left);
  for (int b : cluster_) ++count_[b];
  for (int b : cluster_)
    if (broad_.too_fast_after_rest(w_, step_, b, t)) return rebuild_mid_step(t);
  for (int b : cluster_) predict(b);
}

// A collision made a ball faster than the broad phase allows for: rebuild it for the rest of the
// step from time t and predict every ball afresh. Rare (large mass ratios, chains of impacts).
template <BroadPhase B>
void EventPath<B>::rebuild_mid_step(double t) {
  broad_.rebuild_mid_step(w_, step_, grid_, pool_, t);
  queue_.clear();
  for (int i = 0; i < w_.n; ++i) {
    ++count_[i];
    predict(i);
  }
}

// The event queue is a binary heap kept in a vector that keeps its capacity between steps,
// operated exactly as std::priority_queue does (so the order of simultaneous events is too).
template <BroadPhase B>
void EventPath<B>::push_event(const PredictedEvent& ev) {
  queue_.push_back(ev);
  std::push_heap(queue_.begin(), queue_.end(), std::greater<>());
}
template <BroadPhase B>
PredictedEvent EventPath<B>::pop_event() {
  std::pop_heap(queue_.begin(), queue_.end(), std::greater<>());
  const PredictedEvent ev = queue_.back();
  queue_.pop_back();
  return ev;
}

// Normal approach speed of an event's pair (or ball and wall) at the event time.
template <BroadPhase B>
double EventPath<B>::impact_speed(const PredictedEvent& ev) const {
  if (ev.j < 0) return std::abs(w_.v(ev.i, wall_axis(ev.j)));
  const double dx = w_.p(ev.i, 0) - w_.p(ev.j, 0), dy = w_.p(ev.i, 1) - w_.p(ev.j, 1);
  const double d = std::sqrt(dx * dx + dy * dy);
  return d > 0 ? -relative_normal_velocity(w_, ev.i, ev.j, dx / d, dy / d) : 0.0;
}

// Queues ball i's earliest collision before the end of the step, if any. A touching pair (or
// ball and wall) approaching so slowly that it would close less than the slop over the step is
// not an event: that is round-off, and the next contact pass takes care of it.
template <BroadPhase B>
void EventPath<B>::predict(int i) {
  PredictedEvent best;
  if (next_event(i, best)) push_event(best);
}

// Ball i's earliest collision before the end of the step, in `best`; false if there is none.
// Reads the state only, so the first predictions of a step may run in parallel (see drift).
// kAtStart: every ball's clock is 0 (the start of drift), so no clock is read and no ball is
// brought to a common time (x + v 0 is x): the same events, one array fewer to read per partner
// and less arithmetic.
template <BroadPhase B>
template <bool kAtStart>
bool EventPath<B>::next_event(int i, PredictedEvent& best) const {
  best = {kNever, i, 0, count_[i], 0};
  const double* clock = step_.clock.data();
  const double ti = kAtStart ? 0.0 : clock[i];
  const double v_tol = step_.v_tol, dt = step_.dt;
  wall_event<kAtStart>(i, best);
  broad_.for_each_near(grid_, i, [&](int j) {
    if (j == i) return;
    const double tj = kAtStart ? 0.0 : clock[j];
    const double t0 = std::max(ti, tj);
    double dx, dy;  // i - j at t0
    if constexpr (kAtStart) {
      dx = w_.p(i, 0) - w_.p(j, 0), dy = w_.p(i, 1) - w_.p(j, 1);
    } else {
      dx = on_line(w_.p(i, 0), w_.v(i, 0), t0, ti) - on_line(w_.p(j, 0), w_.v(j, 0), t0, tj);
      dy = on_line(w_.p(i, 1), w_.v(i, 1), t0, ti) - on_line(w_.p(j, 1), w_.v(j, 1), t0, tj);
    }
    const double wx = w_.v(i, 0) - w_.v(j, 0), wy = w_.v(i, 1) - w_.v(j, 1);
    const double b = dx * wx + dy * wy;  // < 0: approaching
    const double d2 = dx * dx + dy * dy;
    const double rs = w_.radius(i) + w_.radius(j);
    const double c = d2 - rs * rs;
    // Not approaching, or: |d(t)|^2 = d2 + 2 b t + a t^2 >= d2 + 2 b t (a >= 0), and even that
    // stays above rs^2 until the earliest event found so far (or the step's end): no root is
    // needed. One branch for both (| not ||): the sign of b is a coin toss per pair.
    if ((b >= 0) | (c + 2.0 * b * (std::min(best.t, dt) - t0) > 0)) return;
    const double touch = rs + step_.touching_gap(rs);
    double t;
    if (d2 < touch * touch) {
      if (b * b < v_tol * v_tol * d2) return;  // -b / |d| < v_tol: round-off, not an approach
      t = t0;  // touching (or overlapping by round-off) and approaching: collide now
    } else {
      t = t0 + approach_root(b, c, wx, wy);
    }
    if (t < best.t) best = {t, i, j, count_[i], count_[j]};
  });
  return best.t <= dt;
}

// Ball i's earliest wall event (from its own time), into `best` if earlier.
template <BroadPhase B>
template <bool kAtStart>
void EventPath<B>::wall_event(int i, PredictedEvent& best) const {
  if (!w_.walls || !broad_.may_reach_wall(i)) return;
  const double ti = kAtStart ? 0.0 : step_.clock[i];
  for (int axis = 0; axis < 2; ++axis) {
    const double v = w_.v(i, axis);
    if (v == 0) continue;
    const int side = v < 0 ? 0 : 1;
    const double gap = w_.wall_gap(i, axis, side);
    if (gap < step_.touching_gap(w_.radius(i)) && std::abs(v) < step_.v_tol) continue;
    // Touching or overlapping by round-off and approaching: collide now (Bannerman et al.,
    // "Stable algorithms for event-driven molecular dynamics", J. Comput. Phys. 2014).
    const double t = ti + std::max(gap, 0.0) / std::abs(v);
    if (t < best.t) best = {t, i, wall_partner(axis, side), count_[i], 0};
  }
}

// Restitution on the normal component; without friction the tangential velocity is untouched,
// with it the rough-disk impulse law (rough_impact.h) stops or slows the slip.
template <BroadPhase B>
void EventPath<B>::collide_pair(int i, int j) {
  double nx = w_.p(i, 0) - w_.p(j, 0), ny = w_.p(i, 1) - w_.p(j, 1);
  const double d = std::sqrt(nx * nx + ny * ny);
  if (d == 0) return;  // coincident centres: no normal exists
  nx /= d, ny /= d;
  const double vn = relative_normal_velocity(w_, i, j, nx, ny);
  if (vn >= 0) return;
  const double inv_sum = w_.inv_mass(i) + w_.inv_mass(j);
  if (!w_.rough()) return apply_impulse(w_, i, j, nx, ny, -(1.0 + w_.e) * vn / inv_sum);
  const RoughImpulse P = rough_impact(vn, slip(w_, i, j, nx, ny), w_.e, w_.mu, 1.0 / inv_sum,
                                      tangent_mass(w_.inv_mass(i), w_.inv_mass(j), w_.k));
  apply_impulse(w_, i, j, nx, ny, P.normal);
  apply_tangent_impulse(w_, i, j, nx, ny, P.tangent);
}

template <BroadPhase B>
void EventPath<B>::collide_wall(int i, int code) {
  const int axis = wall_axis(code);
  if (!w_.rough()) {
    w_.v(i, axis) = -w_.e * w_.v(i, axis);
    return;
  }
  const double sign = wall_side(code) == 0 ? 1.0 : -1.0;  // the normal points into the box
  const double nx = axis == 0 ? sign : 0.0, ny = axis == 1 ? sign : 0.0;
  const double vn = relative_normal_velocity(w_, i, code, nx, ny);
  if (vn >= 0) return;
  const double inv_m = w_.inv_mass(i);
  const RoughImpulse P = rough_impact(vn, slip(w_, i, code, nx, ny), w_.e, w_.mu, 1.0 / inv_m, tangent_mass(inv_m, 0.0, w_.k));
  apply_impulse(w_, i, code, nx, ny, P.normal);
  apply_tangent_impulse(w_, i, code, nx, ny, P.tangent);
}

template class EventPath<GridBroadPhase>;
template class EventPath<ListBroadPhase>;

}  // namespace ballbench

#include "solver/home_contacts.h"

#include <algorithm>
#include <cmath>

#include "solver/home_impulse.h"
#include "solver/rough_impact.h"

namespace ballbench {
namespace {

// Fraction of its gap a speculative contact may close in one step (see make_contact).
constexpr double kSpeculativeFraction = 0.5;

}  // namespace

RestingContacts::RestingContacts(int n) : degree_(n, 0) {}

// The velocity constraint of one contact, for the sequential-impulse solve:
// - approaching faster than v_rest, touching or not: an impact, left to the exact event loop (a
//   touching pair that approaches is collided at once there, pair by pair, each impact losing
//   energy to restitution). Bounce targets (-e vn) inside the solve cannot all be met in a jammed
//   cluster, and then the cluster solves of one step feed on each other (seed-bowl's pile, in
//   some ball orders, escalates to ~10^5 m/s within one step: HomeOnTheBowl.HoldsInAnyBallOrder);
// - touching and slower: resting contact, target 0 (do not approach). Not a small separation:
//   a jammed chain (seed-bowl's row of 20 balls spans its 10 m box exactly, wall to wall) cannot
//   separate everywhere at once, and an infeasible target keeps the solve from converging. What
//   the solve leaves over is below the velocity tolerance, which predict ignores. A small
//   overlap is closed within the step when `close_overlap`, but never faster than v_rest: the
//   push is kinetic energy put in, and an overlap the scene starts with (allow_overlap, seed-box)
//   pushed apart at overlap / dt gained energy as 1/dt (measured: 18% at dt 0.0025 on
//   seed-box). Without gravity v_rest = 0 and overlapping balls part by their own motion, as in
//   `exact` (an approaching overlapping pair is an impact at once, in predict);
// - not touching: a speculative contact (Catto, "Speculative Contacts", 2013): the pair may close
//   part of its gap within `horizon` but not overlap, target -f gap / horizon (f < 1, so that
//   it lands as touching over a few steps instead of as an impact event at the end of this one).
// make_contact writes the contact into `c` from the relative normal velocity vn, or returns false
// (fast); it reads the state only, so the screen's parts call it too.
bool RestingContacts::make_contact(const HomeWorld& w, const EventStep& s, int i, int j, double nx, double ny,
                                   double vn, double gap, double touch, double horizon, bool close_overlap,
                                   PassContact& c) const {
  const bool touching = gap < touch, fast = -vn > s.v_rest;
  if (fast) return false;
  double target;
  if (touching) target = close_overlap ? std::min(std::max(-gap, 0.0) / horizon, s.v_rest) : 0.0;
  else target = -kSpeculativeFraction * gap / horizon;
  // Kept even when satisfied now: an impulse on a neighbour can push the pair together.
  const double inv_j = j >= 0 ? w.inv_mass(j) : 0.0, eff = 1.0 / (w.inv_mass(i) + inv_j);
  c = {{i, j, nx, ny, eff, 0.0}, target, false};
  if (w.rough()) c.tangent_mass = tangent_mass(w.inv_mass(i), inv_j, w.k);
  return true;
}

void RestingContacts::add_contact(const HomeWorld& w, const EventStep& s, int i, int j, double nx, double ny,
                                  double gap, double touch, double horizon, bool close_overlap) {
  PassContact c;
  if (make_contact(w, s, i, j, nx, ny, relative_normal_velocity(w, i, j, nx, ny), gap, touch, horizon, close_overlap, c))
    contacts_.push_back(c);
}

bool RestingContacts::make_pair_contact(const HomeWorld& w, const EventStep& s, int i, int j, double dx, double dy,
                                        double d2, double wx, double wy, double rs, double horizon,
                                        bool close_overlap, PassContact& c) const {
  const double d = std::sqrt(d2), nx = dx / d, ny = dy / d;
  return make_contact(w, s, i, j, nx, ny, wx * nx + wy * ny, d - rs, s.touching_gap(rs), horizon, close_overlap, c);
}

void RestingContacts::add_wall_contacts(const HomeWorld& w, const EventStep& s, int i, double reach, double horizon,
                                        bool close_overlap) {
  if (!w.walls) return;
  for (int axis = 0; axis < 2; ++axis)
    for (int side = 0; side < 2; ++side) {
      const double gap = w.wall_gap(i, axis, side), touch = s.touching_gap(w.radius(i));
      if (gap >= std::max(touch, reach)) continue;
      const double sign = side == 0 ? 1.0 : -1.0;  // the normal points into the box
      add_contact(w, s, i, wall_partner(axis, side), axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, gap, touch,
                  horizon, close_overlap);
    }
}

bool RestingContacts::add_pair_contact(const HomeWorld& w, const EventStep& s, int i, int j, double reach,
                                       double horizon, bool close_overlap) {
  const double dx = w.p(i, 0) - w.p(j, 0), dy = w.p(i, 1) - w.p(j, 1);
  const double rs = w.radius(i) + w.radius(j), limit = rs + std::max(s.touching_gap(rs), reach);
  const double d2 = dx * dx + dy * dy;
  if (d2 >= limit * limit || d2 == 0) return false;  // squared first: most candidates are far
  PassContact c;
  if (make_pair_contact(w, s, i, j, dx, dy, d2, w.v(i, 0) - w.v(j, 0), w.v(i, 1) - w.v(j, 1), rs, horizon,
                        close_overlap, c))
    contacts_.push_back(c);
  return true;
}

// The friction update of contact c after its normal one (Catto 2005): the tangential impulse that
// stops the slip, clamped to the friction cone |Jt| <= mu Jn of this sweep's normal impulse.
// Returns how much it changed the slip (m/s).
double RestingContacts::solve_friction(HomeWorld& w, PassContact& c) {
  const double bound = w.mu * c.impulse, old = c.tangent_impulse;
  c.tangent_impulse = std::clamp(old - slip(w, c.i, c.j, c.nx, c.ny) * c.tangent_mass, -bound, bound);
  if (c.tangent_impulse == old) return 0.0;
  apply_tangent_impulse(w, c.i, c.j, c.nx, c.ny, c.tangent_impulse - old);
  c.moved = true;
  return std::abs(c.tangent_impulse - old) / c.tangent_mass;
}

// A contact that shares no ball with another (isolated) sees velocities only it changes, so its
// first update solves it: it ends at its target with a positive impulse (the update's algebra
// gives the relative normal velocity exactly the target, up to round-off), or with none and
// separating faster. Later sweeps skip it. Visited again, it would only move by round-off (an
// ulp-level walk of its impulse), far below any tolerance, so it cannot decide whether another
// sweep is needed. In a falling gas most contacts are isolated pairs, close but parting (10^6
// bowl balls: ~25 000 contacts, half of them such).
double RestingContacts::solve(HomeWorld& w, int sweeps, double tolerance) {
  double worst = kNever;  // largest violation seen in the last sweep (m/s)
  const bool rough = w.rough();
  // Normal first, then friction against the normal impulse just found: for disks the two do
  // not couple (the contact point lies on the normal), so an isolated contact is still solved
  // by its first update.
  const auto update = [&](PassContact& c) {
    const double vn = relative_normal_velocity(w, c.i, c.j, c.nx, c.ny);
    const double old = c.impulse;
    c.impulse = std::max(0.0, old + (c.target - vn) * c.mass);
    apply_impulse(w, c.i, c.j, c.nx, c.ny, c.impulse - old);
    c.moved |= c.impulse != old;
    if (c.impulse > 0 || vn < c.target) worst = std::max(worst, std::abs(c.target - vn));
    if (rough) worst = std::max(worst, solve_friction(w, c));
  };
  live_.clear();
  if (sweeps <= 0) {
    for (size_t k = 0; k < contacts_.size(); ++k) live_.push_back(static_cast<int>(k));
  } else {
    // Balls' contact counts (saturating at 2), all zero between solves and left so.
    uint8_t* degree = degree_.data();
    const auto bump = [&](int b) { degree[b] = static_cast<uint8_t>(std::min(degree[b] + 1, 2)); };
    for (const PassContact& c : contacts_) {
      bump(c.i);
      if (c.j >= 0) bump(c.j);
    }
    worst = 0;
    for (size_t k = 0; k < contacts_.size(); ++k) {
      PassContact& c = contacts_[k];
      const bool isolated = degree[c.i] == 1 && (c.j < 0 || degree[c.j] == 1);
      update(c);
      if (!isolated) live_.push_back(static_cast<int>(k));
    }
    for (const PassContact& c : contacts_) {
      degree[c.i] = 0;
      if (c.j >= 0) degree[c.j] = 0;
    }
  }
  for (int it = 1; it < sweeps && worst > tolerance; ++it) {
    worst = 0;
    for (int k : live_) update(contacts_[k]);
  }
  if (worst <= tolerance) return 0.0;
  // The isolated contacts were solved by their one update.
  double left = 0;
  for (int k : live_) {
    const PassContact& c = contacts_[k];
    left = std::max(left, c.target - relative_normal_velocity(w, c.i, c.j, c.nx, c.ny));
  }
  return left;
}

// Warm started (Catto 2005): each contact begins with the impulse it ended the last step with, so
// a pile at rest needs a sweep or two instead of as many as it is high.
void RestingContacts::solve_pass(HomeWorld& w, EventStep& s, int sweeps) {
  for (const PassContact& c : contacts_)
    if (c.moved) {
      apply_impulse(w, c.i, c.j, c.nx, c.ny, c.impulse);
      if (c.tangent_impulse != 0) apply_tangent_impulse(w, c.i, c.j, c.nx, c.ny, c.tangent_impulse);
    }
  solve(w, sweeps, 0.5 * s.v_tol);
  // A contact that moved its balls changed velocities the screen could not know: predict both.
  // One that applied nothing (most, in a gas: close but parting) leaves them to the screen, which
  // saw their velocities as they still are (a partner that changed is predicted, and finds them).
  for (const PassContact& c : contacts_)
    if (c.moved) {
      s.active[c.i] = 1;
      if (c.j >= 0) s.active[c.j] = 1;
    }
  warm_entries_.clear();
  for (const PassContact& c : contacts_)
    if (c.impulse > 0) warm_entries_.push_back({c.i, c.j, c.impulse, c.tangent_impulse});
  warm_.assign(warm_entries_);
}

}  // namespace ballbench

#pragma once
// The roots behind exact's events. Every event is the first moment a "gap function" q(tau) >= 0
// reaches zero while decreasing, tau >= 0 measured from now: a quadratic for a ball and a wall (or a
// cell face) under constant acceleration, a quartic for two balls whose accelerations differ. A
// state with q(0) <= 0 is invalid (left by round-off): following Bannerman, Strobl, Formella &
// Poschel (Comput. Part. Mech. 1, 191, 2014) it is an event now if q is decreasing, and no event
// while q increases (touching and separating).
#include <cmath>

#include "solver/contact.h"

namespace ballbench {

// q(tau) = q0 + q1 tau + q2 tau^2: a ball and a wall, or a coordinate and a cell face, under
// constant acceleration. `noise`: |q1| up to this counts as zero at q0 <= 0; such a slow
// closing may go on until q = -cap, where only closing slower than `fine` (round-off) is ignored.
inline double gap_closing_time(double q0, double q1, double q2, double noise, double fine, double cap) {
  if (q0 <= 0) {
    if (q1 < -noise) return 0;               // touching and closing
    if (q1 <= noise && q2 < 0) return 0;     // touching at rest and pushed in
    if (q1 < 0) return gap_closing_time(q0 + cap, q1, q2, fine, fine, 0);  // creeping: event at the cap
    if (q2 >= 0) return kNever;              // opening, or at rest with nothing pushing
    // Opening but pulled back (a bounce under gravity): the descending root.
    const double disc = q1 * q1 - 4 * q0 * q2;  // <= q1^2, as q0 q2 >= 0
    if (disc < 0) return q1 / (-2 * q2);        // turns back before it is clear: event at the turn
    return (q1 + std::sqrt(disc)) / (-2 * q2);
  }
  const double disc = q1 * q1 - 4 * q0 * q2;
  if (q1 < 0) {
    if (disc < 0) return kNever;                   // decelerates and turns back before contact
    return 2 * q0 / (-q1 + std::sqrt(disc));       // smaller root, free of cancellation
  }
  if (q2 < 0) return (q1 + std::sqrt(disc)) / (-2 * q2);  // moving away now, pulled back later
  return kNever;
}

// f(tau) = c0 + c1 tau + c2 tau^2 + c3 tau^3 + c4 tau^4, c4 > 0: |d + w tau + A tau^2 / 2|^2 - R^2
// for two balls whose accelerations differ by A (one resting on a wall or asleep, the other free).
struct Quartic {
  double c0, c1, c2, c3, c4;
  double f(double t) const { return (((c4 * t + c3) * t + c2) * t + c1) * t + c0; }
  double df(double t) const { return ((4 * c4 * t + 3 * c3) * t + 2 * c2) * t + c1; }
  double ddf(double t) const { return (12 * c4 * t + 6 * c3) * t + 2 * c2; }
};

// First tau in [0, horizon] with f(tau) <= 0 and f decreasing: the event of a general overlap
// function, as in Bannerman, Lue and Lue's event detection for DEM, section 4. `noise`: |f'(0)| up to this counts as zero; a touching
// pair (f(0) <= cap) closing no faster may creep on until f = -cap, where only `fine` (round-off)
// counts as zero. `pressed`: the relative acceleration pushes the pair together (exact_world.h's
// pressed). kNever if there is none.
double first_contact(const Quartic& q, double horizon, double noise, double fine, bool pressed, double cap);

}  // namespace ballbench

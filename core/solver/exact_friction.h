#pragma once
// Friction in exact, where it has a closed form: the tangential impulse of a rough impact (ball on
// wall, ball on ball: rough_impact.h), and a rough ball on a wall under gravity, which slides with
// Coulomb friction until its slip reaches zero (the roll event) and then rolls. A ball's motion on
// the walls is set here (set_motion: its accelerations and spin rate); the normal parts of impacts
// are the event handlers' (exact_events.cpp). Two rough contacts at once (a corner) have no closed
// form: the run fails with the reason.
namespace ballbench {

struct ExactSim;

// The rough part of ball i's impact on the wall of `axis` with inward normal `sign` (approach
// speed u, restitution e).
void wall_friction(ExactSim& sim, int i, int axis, double sign, double e, double u);
// The rough part of the impact of balls i and j (normal n from j to i, normal velocity wn < 0,
// inverse masses wi, wj: 0 for a sleeping ball).
void pair_friction(ExactSim& sim, int i, int j, const double* n, double wn, double wi, double wj);
// Ball i's accelerations and spin rate for its state on the walls (rough walls only).
void set_motion(ExactSim& sim, int i);
// When ball i's slip on the wall it slides on reaches zero, from now (s), or kNever.
double roll_time(const ExactSim& sim, int i);
// The slip reached zero: ball i rolls from here (set_motion decides whether it can).
void start_rolling(ExactSim& sim, int i);

}  // namespace ballbench

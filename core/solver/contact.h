#pragma once
// What the solvers share: the time of an event that never comes, how a contact or an event names
// a wall, a contact of an impulse solve, and a predicted collision.
#include <cstdint>
#include <limits>

namespace ballbench {

// The time of an event that never happens (s).
inline constexpr double kNever = std::numeric_limits<double>::infinity();

// A partner j < 0 of a contact or an event is a wall of the box: side 0 (min) or 1 (max) of axis 0
// (x) or 1 (y). A partner j >= 0 is a ball.
constexpr int wall_partner(int axis, int side) { return -1 - (2 * axis + side); }
constexpr int wall_axis(int j) { return (-1 - j) >> 1; }
constexpr int wall_side(int j) { return (-1 - j) & 1; }

// A contact of a normal-impulse solve (sequential impulses: Catto, "Iterative Dynamics with Temporal
// Coherence", GDC 2005). Each solve adds what it needs by deriving from it.
struct Contact {
  int i, j;        // balls; j < 0: a wall (wall_partner) or a ball held still
  double nx, ny;   // unit normal, from j (or the wall) towards i
  double mass;     // effective mass along the normal, 1 / (1 / m_i + 1 / m_j) (kg)
  double impulse;  // accumulated (N s), >= 0
};

// A predicted collision of ball i with partner j (a ball, a wall, or what a solver adds below -4).
struct PredictedEvent {
  double t = kNever;        // when (s)
  int i = -1, j = 0;        // ball and partner
  uint32_t ci = 0, cj = 0;  // collision counters of i and j when predicted: stale once either moved on
  bool operator>(const PredictedEvent& o) const { return t > o.t; }
};

}  // namespace ballbench

#pragma once
// Impulses at a contact of ball i with partner j (a ball, or a wall when j < 0: wall_partner) along
// the unit normal n from j towards i, and what they act on: the relative normal velocity and, in
// rotating scenes, the slip of the contact points (rough_impact.h's sign conventions). The contact
// solves (home_contacts.h) and the event loop's impacts (home_events.cpp) apply them.
#include "solver/home_world.h"

namespace ballbench {

inline double relative_normal_velocity(const HomeWorld& w, int i, int j, double nx, double ny) {
  double wx = w.v(i, 0), wy = w.v(i, 1);
  if (j >= 0) wx -= w.v(j, 0), wy -= w.v(j, 1);
  return wx * nx + wy * ny;
}

// A normal impulse J (N s) on i, its opposite on j.
inline void apply_impulse(HomeWorld& w, int i, int j, double nx, double ny, double J) {
  const double mi = w.inv_mass(i);
  w.v(i, 0) += J * mi * nx, w.v(i, 1) += J * mi * ny;
  if (j >= 0) {
    const double mj = w.inv_mass(j);
    w.v(j, 0) -= J * mj * nx, w.v(j, 1) -= J * mj * ny;
  }
}

// The velocity of i's contact point relative to j's along the tangent (-n_y, n_x) (m/s).
inline double slip(const HomeWorld& w, int i, int j, double nx, double ny) {
  double wx = w.v(i, 0), wy = w.v(i, 1), spin = w.w(i) * w.radius(i);
  if (j >= 0) wx -= w.v(j, 0), wy -= w.v(j, 1), spin += w.w(j) * w.radius(j);
  return wy * nx - wx * ny - spin;
}

// A tangential impulse Jt (N s) along (-n_y, n_x) at the contact on i, its opposite on j: it moves
// and turns both (w -= r Jt / I, I = k m r^2).
inline void apply_tangent_impulse(HomeWorld& w, int i, int j, double nx, double ny, double Jt) {
  const double mi = w.inv_mass(i) * Jt;
  w.v(i, 0) -= mi * ny, w.v(i, 1) += mi * nx;
  w.w(i) -= mi / (w.k * w.radius(i));
  if (j >= 0) {
    const double mj = w.inv_mass(j) * Jt;
    w.v(j, 0) += mj * ny, w.v(j, 1) -= mj * nx;
    w.w(j) -= mj / (w.k * w.radius(j));
  }
}

}  // namespace ballbench

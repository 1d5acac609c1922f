#pragma once
// The impact of two rough disks (or a rough disk and a wall): the Coulomb impulse law that `home`
// and `exact` share, and the contact frame it works in.
//
// Sign conventions: n is the unit normal from partner j to ball i, t = (-n_y, n_x) the tangent;
// angular velocities are counter-clockwise. Ball i's contact point sits at -r_i n, ball j's at
// +r_j n, so the slip (the tangential velocity of i's contact point relative to j's) is
//   u_t = (v_i - v_j).t - (w_i r_i + w_j r_j).
// An impulse P = P_n n + P_t t on i (and -P on j) changes
//   v_i += P / m_i,  v_j -= P / m_j,  w_i -= r_i P_t / I_i,  w_j -= r_j P_t / I_j,
// so u_n moves by P_n / m_n and u_t by P_t / m_t with the effective masses
//   1 / m_n = 1 / m_i + 1 / m_j,   1 / m_t = 1 / m_i + 1 / m_j + r_i^2 / I_i + r_j^2 / I_j
// (for a disk r^2 / I = 1 / (k m), I = k m r^2). Normal and tangent decouple: a disk's contact
// point lies on its normal.
//
// The law (Walton, "Numerical simulation of inelastic, frictional particle-particle interactions",
// in Particulate Two-Phase Flow, 1993, with tangential restitution 0; Brach, "Rigid body
// collisions", J. Appl. Mech. 56, 1989): the normal impulse gives restitution e,
// P_n = -(1 + e) u_n m_n; the tangential impulse stops the slip, P_t = -u_t m_t (sticking), unless
// that needs more than mu P_n, and then it is mu P_n against the slip (sliding). Either way the
// slip keeps its sign or stops, so the impact never gains energy.
#include <algorithm>
#include <cmath>

namespace ballbench {

struct RoughImpulse {
  double normal;   // P_n (N s), >= 0
  double tangent;  // P_t (N s), |P_t| <= mu P_n
};

// u_n < 0: approaching (m/s); u_t: slip (m/s); e: restitution; mu: Coulomb coefficient; mass_n,
// mass_t: the effective masses above (kg).
inline RoughImpulse rough_impact(double u_n, double u_t, double e, double mu, double mass_n, double mass_t) {
  const double normal = -(1.0 + e) * u_n * mass_n;
  const double bound = mu * normal;
  return {normal, std::clamp(-u_t * mass_t, -bound, bound)};
}

// The effective tangential mass of a contact (kg): inv_m_i, inv_m_j are the inverse masses (0 for
// a wall, which neither moves nor turns), k the scene's inertia factor (I = k m r^2).
inline double tangent_mass(double inv_m_i, double inv_m_j, double k) {
  return 1.0 / ((inv_m_i + inv_m_j) * (1.0 + 1.0 / k));
}

}  // namespace ballbench

#include "solver/soft_step.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ballbench {
namespace {

// A soft constraint's coefficients for one substep h (Catto, "Solver2D", 2024, "soft step"; Box2D
// v3's b2MakeSoft): a spring of `hertz` with damping ratio `zeta`, solved implicitly.
struct Softness {
  double bias_rate, mass_scale, impulse_scale;
};

Softness make_soft(double hertz, double zeta, double h) {
  if (hertz == 0) return {0, 1, 0};
  const double omega = 2 * std::numbers::pi * hertz;
  const double a1 = 2 * zeta + h * omega, a2 = h * omega * a1, a3 = 1 / (1 + a2);
  return {omega / a1, a2 * a3, a3};
}

// The solve's view of the balls: each ball's velocity and displacement since the start of the
// step in one record (a contact update reads both balls' four values, so one cache line per ball
// instead of four), and the inverse masses.
struct Kernel {
  SoftStepScratch::Motion* __restrict m;
  const double* inv_masses;  // null: every ball has inv_mass0
  double inv_mass0;
  // Friction: as SoftBodies (w null or mu 0: none).
  double* w;
  const double* radii;
  double r0, k, mu;

  double inv_mass(int i) const { return inv_masses ? inv_masses[i] : inv_mass0; }
  double radius(int i) const { return radii ? radii[i] : r0; }

  double normal_velocity(const SoftContact& c) const {
    double wx = m[c.i].vx, wy = m[c.i].vy;
    if (c.j >= 0) wx -= m[c.j].vx, wy -= m[c.j].vy;
    return wx * c.nx + wy * c.ny;
  }

  // The separation now: the gap at the start plus the balls' displacements along the fixed normal.
  double separation(const SoftContact& c) const {
    double ux = m[c.i].dx, uy = m[c.i].dy;
    if (c.j >= 0) ux -= m[c.j].dx, uy -= m[c.j].dy;
    return c.gap + ux * c.nx + uy * c.ny;
  }

  void apply(const SoftContact& c, double impulse) const {
    const double mi = inv_mass(c.i) * impulse;
    m[c.i].vx += mi * c.nx, m[c.i].vy += mi * c.ny;
    if (c.j >= 0) {
      const double mj = inv_mass(c.j) * impulse;
      m[c.j].vx -= mj * c.nx, m[c.j].vy -= mj * c.ny;
    }
  }

  // The velocity of i's contact point relative to j's along the tangent (-n_y, n_x).
  double slip(const SoftContact& c) const {
    double wx = m[c.i].vx, wy = m[c.i].vy, spin = w[c.i] * radius(c.i);
    if (c.j >= 0) wx -= m[c.j].vx, wy -= m[c.j].vy, spin += w[c.j] * radius(c.j);
    return wy * c.nx - wx * c.ny - spin;
  }

  // A tangential impulse on i (its opposite on j): it moves and turns both, w -= r Jt / I.
  void apply_tangent(const SoftContact& c, double impulse) const {
    const double mi = inv_mass(c.i) * impulse;
    m[c.i].vx -= mi * c.ny, m[c.i].vy += mi * c.nx;
    w[c.i] -= mi / (k * radius(c.i));
    if (c.j >= 0) {
      const double mj = inv_mass(c.j) * impulse;
      m[c.j].vx += mj * c.ny, m[c.j].vy -= mj * c.nx;
      w[c.j] -= mj / (k * radius(c.j));
    }
  }

  // Friction after the normal update: the impulse that stops the slip, within mu times the
  // normal impulse of this substep.
  void solve_friction(SoftContact& c) const {
    const double bound = mu * c.impulse;
    const double total = std::clamp(c.tangent_impulse - slip(c) * c.tangent_mass, -bound, bound);
    apply_tangent(c, total - c.tangent_impulse);
    c.tangent_impulse = total;
  }

  // One sequential-impulse update (Catto 2005) of contact c. Not touching: speculative, the pair
  // may close its separation within the substep h, no more. Touching: do not approach, and with
  // `push` move out of an overlap through the soft constraint, at most push_speed.
  void solve(SoftContact& c, double inv_h, const Softness& soft, bool push, double push_speed) const {
    const double s = separation(c);
    double bias = 0, mass_scale = 1, impulse_scale = 0;
    if (s > 0) {
      bias = s * inv_h;
    } else if (push) {
      bias = std::max(soft.bias_rate * s, -push_speed);
      mass_scale = soft.mass_scale, impulse_scale = soft.impulse_scale;
    }
    const double vn = normal_velocity(c);
    const double delta = -c.mass * mass_scale * (vn + bias) - impulse_scale * c.impulse;
    const double total = std::max(c.impulse + delta, 0.0);
    apply(c, total - c.impulse);
    c.impulse = total;
    c.max_impulse = std::max(c.max_impulse, total);
    if (mu > 0) solve_friction(c);
  }
};

}  // namespace

void soft_step(const SoftBodies& b, int n, std::vector<SoftContact>& contacts, double gx, double gy, double dt,
               const SoftStepSettings& s, Restitution restitution, SoftStepScratch& scratch) {
  const int substeps = std::max(s.substeps, 1);
  const double h = dt / substeps, inv_h = 1 / h;
  // A contact spring stiffer than a quarter of the substep rate is not resolved by the substeps.
  const Softness soft = make_soft(std::min(s.contact_hertz, 0.25 * inv_h), s.damping_ratio, h);
  // The velocities into the records, displacements 0; back after the last substep.
  scratch.motion.resize(n);
  SoftStepScratch::Motion* __restrict m = scratch.motion.data();
  for (int i = 0; i < n; ++i) m[i] = {b.vx[i], b.vy[i], 0.0, 0.0};
  const double mu = b.w ? b.mu : 0.0;
  const Kernel k{m, b.inv_mass, b.inv_mass0, b.w, b.radius, b.r0, b.k, mu};
  for (SoftContact& c : contacts) c.vn0 = k.normal_velocity(c), c.max_impulse = 0;
  const double gxh = gx * h, gyh = gy * h;
  // Over every ball, or only over those that move (the others have inverse mass 0).
  const auto for_moving = [&](auto&& f) {
    if (b.moving)
      for (int q = 0; q < b.moving_count; ++q) f(b.moving[q]);
    else
      for (int i = 0; i < n; ++i) f(i);
  };
  for (int step = 0; step < substeps; ++step) {
    for_moving([&](int i) { m[i].vx += gxh, m[i].vy += gyh; });
    for (const SoftContact& c : contacts) k.apply(c, c.impulse);
    if (mu > 0)
      for (const SoftContact& c : contacts) k.apply_tangent(c, c.tangent_impulse);
    for (int it = 0; it < s.substep_iterations; ++it)
      for (SoftContact& c : contacts) k.solve(c, inv_h, soft, true, s.push_speed);
    for_moving([&](int i) {
      const double mx = m[i].vx * h, my = m[i].vy * h;
      b.x[i] += mx, b.y[i] += my, m[i].dx += mx, m[i].dy += my;
    });
    if (b.angle) for_moving([&](int i) { b.angle[i] += b.w[i] * h; });
    for (int it = 0; it < s.relax_iterations; ++it)
      for (SoftContact& c : contacts) k.solve(c, inv_h, soft, false, s.push_speed);
  }
  // Restitution (Box2D v3's b2ApplyRestitution): a contact that approached faster than the
  // threshold at the start and pushed during the step leaves at e times that speed.
  if (restitution.e != 0)
    for (SoftContact& c : contacts) {
      if (c.vn0 > -restitution.threshold || c.max_impulse == 0) continue;
      const double vn = k.normal_velocity(c);
      const double total = std::max(c.impulse - c.mass * (vn + restitution.e * c.vn0), 0.0);
      k.apply(c, total - c.impulse);
      c.impulse = total;
    }
  for_moving([&](int i) { b.vx[i] = m[i].vx, b.vy[i] = m[i].vy; });
}

}  // namespace ballbench

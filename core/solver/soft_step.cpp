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

struct Kernel {
  const SoftBodies& b;
  const double* dx;
  const double* dy;

  double inv_mass(int i) const { return b.inv_mass ? b.inv_mass[i] : b.inv_mass0; }

  double normal_velocity(const SoftContact& c) const {
    double wx = b.vx[c.i], wy = b.vy[c.i];
    if (c.j >= 0) wx -= b.vx[c.j], wy -= b.vy[c.j];
    return wx * c.nx + wy * c.ny;
  }

  // The separation now: the gap at the start plus the balls' displacements along the fixed normal.
  double separation(const SoftContact& c) const {
    double ux = dx[c.i], uy = dy[c.i];
    if (c.j >= 0) ux -= dx[c.j], uy -= dy[c.j];
    return c.gap + ux * c.nx + uy * c.ny;
  }

  void apply(const SoftContact& c, double impulse) const {
    const double mi = inv_mass(c.i) * impulse;
    b.vx[c.i] += mi * c.nx, b.vy[c.i] += mi * c.ny;
    if (c.j >= 0) {
      const double mj = inv_mass(c.j) * impulse;
      b.vx[c.j] -= mj * c.nx, b.vy[c.j] -= mj * c.ny;
    }
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
  }
};

}  // namespace

void soft_step(const SoftBodies& b, int n, std::vector<SoftContact>& contacts, double gx, double gy, double dt,
               const SoftStepSettings& s, Restitution restitution, SoftStepScratch& scratch) {
  const int substeps = std::max(s.substeps, 1);
  const double h = dt / substeps, inv_h = 1 / h;
  // A contact spring stiffer than a quarter of the substep rate is not resolved by the substeps.
  const Softness soft = make_soft(std::min(s.contact_hertz, 0.25 * inv_h), s.damping_ratio, h);
  if (scratch.dx.size() != static_cast<size_t>(n)) scratch.dx.assign(n, 0.0), scratch.dy.assign(n, 0.0);
  const Kernel k{b, scratch.dx.data(), scratch.dy.data()};
  for (SoftContact& c : contacts) c.vn0 = k.normal_velocity(c), c.max_impulse = 0;
  const double gxh = gx * h, gyh = gy * h;
  double* __restrict ux = scratch.dx.data();
  double* __restrict uy = scratch.dy.data();
  // Over every ball, or only over those that move (the others have inverse mass 0).
  const auto for_moving = [&](auto&& f) {
    if (b.moving)
      for (int m = 0; m < b.moving_count; ++m) f(b.moving[m]);
    else
      for (int i = 0; i < n; ++i) f(i);
  };
  for (int step = 0; step < substeps; ++step) {
    for_moving([&](int i) { b.vx[i] += gxh, b.vy[i] += gyh; });
    for (const SoftContact& c : contacts) k.apply(c, c.impulse);
    for (int it = 0; it < s.substep_iterations; ++it)
      for (SoftContact& c : contacts) k.solve(c, inv_h, soft, true, s.push_speed);
    for_moving([&](int i) {
      const double mx = b.vx[i] * h, my = b.vy[i] * h;
      b.x[i] += mx, b.y[i] += my, ux[i] += mx, uy[i] += my;
    });
    for (int it = 0; it < s.relax_iterations; ++it)
      for (SoftContact& c : contacts) k.solve(c, inv_h, soft, false, s.push_speed);
  }
  for_moving([&](int i) { ux[i] = uy[i] = 0; });  // zero for the next step, as the held balls are
  // Restitution (Box2D v3's b2ApplyRestitution): a contact that approached faster than the
  // threshold at the start and pushed during the step leaves at e times that speed.
  if (restitution.e == 0) return;
  for (SoftContact& c : contacts) {
    if (c.vn0 > -restitution.threshold || c.max_impulse == 0) continue;
    const double vn = k.normal_velocity(c);
    const double total = std::max(c.impulse - c.mass * (vn + restitution.e * c.vn0), 0.0);
    k.apply(c, total - c.impulse);
    c.impulse = total;
  }
}

}  // namespace ballbench

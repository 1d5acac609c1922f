#include "solver/exact_friction.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/exact_sim.h"
#include "solver/rough_impact.h"

namespace ballbench {
namespace {

// The wall of axis `ax` that gravity presses a ball against: its inward normal's sign along ax.
double inward(const ExactModel& model, int ax) { return model.gravity[ax] < 0 ? 1.0 : -1.0; }
// The sign along the other axis of the tangent t = (-n_y, n_x) of a wall of axis `ax` whose
// inward normal has sign `sign` (rough_impact.h's convention, the wall as partner j).
double tangent_sign(int ax, double sign) { return ax == 1 ? -sign : sign; }

}  // namespace

// rough_impact's tangential impulse against the slip u_t = v.t - w r (the wall has infinite mass
// and does not turn). Under gravity an impulse along the other axis that drives the ball into a
// wall it touches there needs both walls at once (a corner): no closed form, so the run fails with
// the reason. One that lifts it off a wall it slides on frees it.
void wall_friction(ExactSim& sim, int i, int axis, double sign, double e, double u) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  const double k = model.inertia_factor, mu = model.friction;
  const int b = 1 - axis;
  const double ts = tangent_sign(axis, sign);
  const double r = balls.radius[i], m = 1.0 / balls.inv_mass[i];
  const double u_t = balls.vel[b][i] * ts - balls.spin[i] * r;
  const RoughImpulse P = rough_impact(-u, u_t, e, mu, m, tangent_mass(balls.inv_mass[i], 0.0, k));
  balls.vel[b][i] += P.tangent * ts * balls.inv_mass[i];
  balls.spin[i] -= P.tangent * balls.inv_mass[i] / (k * r);  // r P_t / I with I = k m r^2
  if (!model.rough_walls) return;
  const double noise = velocity_noise(model, balls.speed(i));
  const double vb = balls.vel[b][i];
  const int toward = vb < 0 ? 0 : 1;  // the wall on axis b the ball now moves towards
  const double gap = toward == 0 ? balls.pos[b][i] - r - model.box_lo[b] : model.box_hi[b] - r - balls.pos[b][i];
  if (std::abs(vb) > noise && gap <= kTouch * r)
    throw std::runtime_error(fmt::format(
        "exact: ball {} at t = {} s is struck by a rough wall into the wall it touches across it (a corner): two "
        "rough contacts at once have no closed form",
        i, sim.now));
  if (balls.held_axes[i] & (1 << b)) {
    if (std::abs(vb) > noise) {
      balls.held_axes[i] &= static_cast<uint8_t>(~(1 << b));  // lifted off
      balls.acc[b][i] = model.gravity[b];
    } else {
      balls.vel[b][i] = 0;
    }
  }
}

// rough_impact's tangential impulse P_t t on i, -P_t t on j, against the slip u_t = (v_i - v_j).t -
// (w_i r_i + w_j r_j). Normal and tangent decouple for disks.
void pair_friction(ExactSim& sim, int i, int j, const double* n, double wn, double wi, double wj) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  const double k = model.inertia_factor;
  const double t[2] = {-n[1], n[0]};
  const double u_t = (balls.vel[0][i] - balls.vel[0][j]) * t[0] + (balls.vel[1][i] - balls.vel[1][j]) * t[1] -
                     (balls.spin[i] * balls.radius[i] + balls.spin[j] * balls.radius[j]);
  const double P = rough_impact(wn, u_t, model.restitution, model.friction, 1.0 / (wi + wj), tangent_mass(wi, wj, k)).tangent;
  for (int d = 0; d < 2; ++d) balls.vel[d][i] += P * wi * t[d], balls.vel[d][j] -= P * wj * t[d];
  balls.spin[i] -= P * wi / (k * balls.radius[i]);  // r P_t / I with I = k m r^2
  balls.spin[j] -= P * wj / (k * balls.radius[j]);
}

// Free (gravity, spin constant), or held on one wall by gravity, where Coulomb friction mu N
// (N = m G, G the part of gravity into the wall) acts at the contact point against the slip
// s = v_t - w r:
//   sliding (s != 0): a_t = g_t - mu G sgn(s),  dw/dt = mu G sgn(s) / (k r),
//     so ds/dt = g_t - mu G sgn(s) (1 + k) / k, linear in time (the roll event);
//   rolling (s = 0, w = v_t / r): a_t = g_t / (1 + k), dw/dt = a_t / r, which needs the static
//     friction m g_t k / (1 + k); beyond mu m G it slides in the direction of g_t.
// (Newton's laws for the centre and the rotation about it, torque -r F for a force F t at the
// contact point -r n; Goldstein, Classical Mechanics, ch. 1 and 5.) Held on both walls of a
// corner it is at rest; spinning there it would need both walls' friction at once: the run fails.
void set_motion(ExactSim& sim, int i) {
  const ExactModel& model = sim.model;
  if (!model.rough_walls) return;
  ExactBalls& balls = sim.balls;
  const double k = model.inertia_factor, mu = model.friction;
  const double* g = model.gravity;
  const int held = balls.held_axes[i];
  if (held == 0) {
    for (int d = 0; d < 2; ++d) balls.acc[d][i] = g[d];
    balls.spin_rate[i] = 0, balls.slip_sign[i] = 0;
    return;
  }
  if (held == 3) {
    if (std::abs(balls.spin[i]) * balls.radius[i] > kRestSlop * model.rest_velocity)
      throw std::runtime_error(fmt::format(
          "exact: ball {} at t = {} s rests in a corner spinning at {} rad/s: friction at two walls at once has no "
          "closed form",
          i, sim.now, balls.spin[i]));
    balls.spin[i] = 0, balls.spin_rate[i] = 0, balls.slip_sign[i] = 0;
    return;
  }
  const int ax = held == 1 ? 0 : 1, b = 1 - ax;
  const double sign = inward(model, ax), ts = tangent_sign(ax, sign);
  const double G = -g[ax] * sign, gt = g[b] * ts, r = balls.radius[i];
  const double vt = balls.vel[b][i] * ts;
  const double slip = vt - balls.spin[i] * r;
  const double noise = kVelocityNoise * (std::abs(vt) + std::abs(balls.spin[i]) * r);
  double at, alpha;
  int s = 0;
  if (std::abs(slip) <= noise && std::abs(gt) * k <= mu * G * (1 + k)) {
    balls.spin[i] = vt / r;
    at = gt / (1 + k);
    alpha = at / r;
  } else {
    s = std::abs(slip) <= noise ? (gt > 0 ? 1 : -1) : (slip > 0 ? 1 : -1);
    at = gt - mu * G * s;
    alpha = mu * G * s / (k * r);
  }
  balls.acc[ax][i] = 0;
  balls.acc[b][i] = at * ts;
  balls.spin_rate[i] = alpha, balls.slip_sign[i] = static_cast<int8_t>(s);
  // Standing against a wall across the slide, pushed into it by friction alone: a corner.
  const double push = balls.acc[b][i];
  if (push != 0 && std::abs(balls.vel[b][i]) <= velocity_noise(model, balls.speed(i))) {
    const int side = push < 0 ? 0 : 1;
    const double gap = side == 0 ? balls.pos[b][i] - r - model.box_lo[b] : model.box_hi[b] - r - balls.pos[b][i];
    const bool gravity_presses = side == 0 ? g[b] < 0 : g[b] > 0;  // then it is held there next
    if (gap <= kTouch * r && !gravity_presses)
      throw std::runtime_error(fmt::format(
          "exact: ball {} at t = {} s is driven by friction into the wall it touches across its slide (a corner): "
          "two rough contacts at once have no closed form",
          i, sim.now));
  }
}

// s(tau) = s0 + (ds/dt) tau (set_motion). The rate is a sum of the closed-form terms, never a
// difference of nearly equal velocities; s0 is the slip itself.
double roll_time(const ExactSim& sim, int i) {
  const ExactModel& model = sim.model;
  const ExactBalls& balls = sim.balls;
  const double k = model.inertia_factor, mu = model.friction;
  const int ax = balls.held_axes[i] == 1 ? 0 : 1, b = 1 - ax;
  const double sign = inward(model, ax), ts = tangent_sign(ax, sign);
  const double G = -model.gravity[ax] * sign, gt = model.gravity[b] * ts, s = balls.slip_sign[i];
  const double s0 = (balls.vel[b][i] * ts - balls.spin[i] * balls.radius[i]) * s;  // |slip| while it keeps its sign
  const double closing = mu * G * (1 + k) / k - gt * s;                                // -d|s|/dt
  if (!(closing > 0)) return kNever;
  return s0 <= 0 ? 0.0 : s0 / closing;
}

void start_rolling(ExactSim& sim, int i) {
  ExactBalls& balls = sim.balls;
  const int ax = balls.held_axes[i] == 1 ? 0 : 1, b = 1 - ax;
  // The event is the moment the slip is zero.
  balls.spin[i] = balls.vel[b][i] * tangent_sign(ax, inward(sim.model, ax)) / balls.radius[i];
  set_motion(sim, i);
}

}  // namespace ballbench

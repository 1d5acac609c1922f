#include "solver/exact_events.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "interrupt.h"
#include "solver/exact_friction.h"
#include "solver/exact_roots.h"
#include "solver/exact_sim.h"

namespace ballbench {

ExactSim::ExactSim(const Scene& scene, const ExactSettings& settings)
    : model(scene, settings),
      balls(scene, model),
      queue(model.ball_count),
      repredict(model.ball_count),
      cluster(model.ball_count),
      sleep(model.ball_count) {
  model.settings.cell_size = grid.build(scene, model, balls);
  // Millions of balls take seconds to predict: asked to stop meanwhile, the building ends
  // (run_engine marks the run interrupted before its first step).
  for (int i = 0; i < model.ball_count; ++i) {
    if ((i & 0xffff) == 0 && interrupt_signal()) throw Interrupted{"building the exact solver's world"};
    predict(*this, i);
  }
}

namespace {

// When balls i (at now) and j first touch while approaching, or kNever; `horizon` (absolute)
// only prunes.
double pair_time(const ExactSim& sim, int i, int j, double horizon) {
  const ExactBalls& balls = sim.balls;
  const double now = sim.now;
  const double h = now - balls.clock[j];
  double d[2], w[2], A[2];
  for (int k = 0; k < 2; ++k) {
    d[k] = balls.pos[k][i] - (balls.pos[k][j] + (balls.vel[k][j] + 0.5 * balls.acc[k][j] * h) * h);
    w[k] = balls.vel[k][i] - (balls.vel[k][j] + balls.acc[k][j] * h);
    A[k] = balls.acc[k][i] - balls.acc[k][j];
  }
  const double R = balls.radius[i] + balls.radius[j];
  const double d2 = d[0] * d[0] + d[1] * d[1];
  const double b = d[0] * w[0] + d[1] * w[1];  // < 0: approaching
  const double c = d2 - R * R;                  // <= 0: touching or overlapping
  const double speeds = balls.speed(i) + norm2(balls.vel[0][i] - w[0], balls.vel[1][i] - w[1]);  // |v_i| + |v_j|
  const double noise = velocity_noise(sim.model, speeds), fine = kVelocityNoise * speeds;
  const double dist = std::sqrt(d2);
  const double cap = R * R - (R * (1 - kOverlapCap)) * (R * (1 - kOverlapCap));  // in units of c
  if (A[0] == 0 && A[1] == 0) {
    // Same acceleration: the relative motion is a straight line, the contact a quadratic root.
    if (b >= 0) return kNever;
    const double a = w[0] * w[0] + w[1] * w[1];
    double cc = c;
    if (c <= cap && b >= -noise * dist) {  // touching, closing slower than noise: creep to the cap
      if (b >= -fine * dist) return kNever;
      cc += cap;
    }
    if (cc <= 0) return now;
    const double disc = b * b - a * cc;
    if (disc < 0) return kNever;
    return now + cc / (-b + std::sqrt(disc));
  }
  const double tau_max = horizon - now;
  if (tau_max < kNever) {
    const double gap = dist - R;
    const double reach = (norm2(w[0], w[1]) + 0.5 * norm2(A[0], A[1]) * tau_max) * tau_max;
    if (gap > reach * (1 + 1e-12)) return kNever;  // cannot close the gap before the best so far
  }
  const Quartic q{c, 2 * b, w[0] * w[0] + w[1] * w[1] + d[0] * A[0] + d[1] * A[1], w[0] * A[0] + w[1] * A[1],
                  0.25 * (A[0] * A[0] + A[1] * A[1])};
  const double press = dist > 0 ? -(d[0] * A[0] + d[1] * A[1]) / dist : 0.0;
  const bool is_pressed = pressed(sim.model, press, A[0], A[1], fine);
  const double tau = first_contact(q, tau_max, 2 * dist * noise, 2 * dist * fine, is_pressed, cap);
  return tau < kNever ? now + tau : kNever;
}

// Counts an event of ball i against the per-step budget and the jam window.
void count_event(ExactSim& sim, int i) {
  ExactBalls& balls = sim.balls;
  const int budget = sim.model.settings.max_events_per_ball;
  if (++balls.step_events[i] > budget)
    throw std::runtime_error(fmt::format(
        "exact: ball {} took part in more than {} events in one step at t = {} s (an inelastic collapse the "
        "rest rules did not resolve; see settings contact_time, rest_velocity, max_events_per_ball)",
        i, budget, sim.now));
  if (sim.now - balls.jam_window_start[i] > sim.model.contact_time) balls.jam_window_start[i] = sim.now, balls.jam_events[i] = 0;
  ++balls.jam_events[i];
}

void predict_pending(ExactSim& sim) {
  Repredictions& r = sim.repredict;
  for (size_t k = 0; k < r.pending.size(); ++k) predict(sim, r.pending[k]);
  r.pending.clear();
  ++r.round;
}

// Same trajectory, new neighbours: predictions against i stay valid.
void on_cell(ExactSim& sim, int i, int axis, int up) {
  count_event(sim, i);
  sim.grid.cross(i, axis, up);
  predict(sim, i);
}

void on_wall(ExactSim& sim, int i, int axis, int side) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  count_event(sim, i);
  balls.advance(i, sim.now, model.rotation);
  sim.repredict.changed_course(balls, i);
  const double sign = side == 0 ? 1.0 : -1.0;  // wall normal, into the box
  // Put the ball exactly on the wall: the event is the contact, and this keeps round-off from
  // accumulating in the normal coordinate (bounce heights stay exact to the last bounce).
  balls.pos[axis][i] = side == 0 ? model.box_lo[axis] + balls.radius[i] : model.box_hi[axis] - balls.radius[i];
  double& v = balls.vel[axis][i];
  const double u = std::max(-v * sign, 0.0);  // approach speed
  if (balls.jam_events[i] > kJamEvents && u >= model.rest_velocity) {
    settle_cluster(sim, i, -1, true);
    return predict_pending(sim);
  }
  // The tangential impulse of a rough wall, from the slip at impact (the normal impulse leaves it).
  if (model.friction > 0) wall_friction(sim, i, axis, sign, u < model.rest_velocity ? 0.0 : model.restitution, u);
  if (u < model.rest_velocity) {
    // Too slow to be a bounce: the normal motion stops. The ball sleeps if the walls and
    // sleeping balls it touches carry its weight; pressed against this wall by gravity it
    // slides along it (the axis is held: no normal velocity or acceleration).
    v = 0;
    if (-model.gravity[axis] * sign > 0) {
      balls.acc[axis][i] = 0;
      if (model.rough_walls) balls.held_axes[i] |= static_cast<uint8_t>(1 << axis);
    }
    try_sleep(sim, i);
    set_motion(sim, i);
    return predict_pending(sim);
  }
  v = model.restitution * u * sign;
  set_motion(sim, i);
  predict_pending(sim);
}

// The slip of a sliding ball reached zero.
void on_roll(ExactSim& sim, int i) {
  count_event(sim, i);
  sim.balls.advance(i, sim.now, sim.model.rotation);
  sim.repredict.changed_course(sim.balls, i);
  start_rolling(sim, i);
  predict_pending(sim);
}

void on_pair(ExactSim& sim, int i, int j) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  count_event(sim, i), count_event(sim, j);
  balls.advance(i, sim.now, model.rotation), balls.advance(j, sim.now, model.rotation);
  sim.repredict.add(i), sim.repredict.add(j);
  double n[2] = {balls.pos[0][i] - balls.pos[0][j], balls.pos[1][i] - balls.pos[1][j]};  // from j to i
  const double dist = norm2(n[0], n[1]);
  if (dist > 0) {
    n[0] /= dist, n[1] /= dist;
    const double wn = (balls.vel[0][i] - balls.vel[0][j]) * n[0] + (balls.vel[1][i] - balls.vel[1][j]) * n[1];  // < 0: approaching
    const double u = std::max(-wn, 0.0);
    if (balls.asleep[i] && u >= model.wake_velocity) wake(sim, i);
    if (balls.asleep[j] && u >= model.wake_velocity) wake(sim, j);
    if (u < model.rest_velocity) {
      settle_cluster(sim, i, j, false);
    } else if (balls.jam_events[i] > kJamEvents || balls.jam_events[j] > kJamEvents) {
      settle_cluster(sim, i, j, true);
    } else if (!balls.asleep[i] || !balls.asleep[j]) {
      // A sleeping ball is a fixed obstacle: infinite mass, no acceleration.
      const double wi = balls.asleep[i] ? 0.0 : balls.inv_mass[i], wj = balls.asleep[j] ? 0.0 : balls.inv_mass[j];
      const double Ax = balls.acc[0][i] - balls.acc[0][j], Ay = balls.acc[1][i] - balls.acc[1][j];
      const double press = -(Ax * n[0] + Ay * n[1]);  // relative acceleration into the contact
      // Restitution on the normal component only (thesis eq. 11-12 generalised):
      // J = -(1 + e) vn / (1/m1 + 1/m2), written as the wanted separation speed `out`.
      double out = model.restitution * u;
      if (pressed(model, press, Ax, Ay, kVelocityNoise * (balls.speed(i) + balls.speed(j))))
        out = std::max(out, 0.5 * press * model.contact_time);
      const double J = (out - wn) / (wi + wj);
      if (J > 0) {
        if (model.friction > 0) pair_friction(sim, i, j, n, wn, wi, wj);
        for (int k = 0; k < 2; ++k) balls.vel[k][i] += J * wi * n[k], balls.vel[k][j] -= J * wj * n[k];
        for (int b : {i, j})
          if (!balls.asleep[b]) sim.repredict.changed_course(balls, b), after_impulse(model, balls, b);
      }
    }
  }
  for (int b : {i, j})
    if (balls.is_jammed(b)) try_sleep(sim, b);
  predict_pending(sim);
}

}  // namespace

void predict(ExactSim& sim, int i) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  const ExactGrid& grid = sim.grid;
  const double now = sim.now;
  balls.advance(i, now, model.rotation);
  PredictedEvent best;
  auto offer = [&](const PredictedEvent& c) {
    if (sooner(c, best)) best = c;
  };
  if (!balls.asleep[i]) {
    const double noise = velocity_noise(model, balls.speed(i)), fine = kVelocityNoise * balls.speed(i);
    for (int k = 0; k < 2; ++k) {
      const double x = balls.pos[k][i], v = balls.vel[k][i], a = balls.acc[k][i];
      if (model.has_walls) {
        const double r = balls.radius[i];
        const double cap = kOverlapCap * r;
        const double t0 = gap_closing_time(x - r - model.box_lo[k], v, 0.5 * a, noise, fine, cap);
        if (t0 < kNever) offer({now + t0, i, wall_partner(k, 0)});
        const double t1 = gap_closing_time(model.box_hi[k] - r - x, -v, -0.5 * a, noise, fine, cap);
        if (t1 < kNever) offer({now + t1, i, wall_partner(k, 1)});
      }
      const int c = grid.cell_along(i, k);
      if (c > 0) {
        const double t0 = gap_closing_time(x - grid.face(k, c), v, 0.5 * a, 0.0, 0.0, 0.0);
        if (t0 < kNever) offer({now + t0, i, cell_face(k, 0)});
      }
      if (c < grid.cells_along(k) - 1) {
        const double t1 = gap_closing_time(grid.face(k, c + 1) - x, -v, -0.5 * a, 0.0, 0.0, 0.0);
        if (t1 < kNever) offer({now + t1, i, cell_face(k, 1)});
      }
    }
    if (model.rough_walls && balls.slip_sign[i] != 0) {
      const double t = roll_time(sim, i);
      if (t < kNever) offer({now + t, i, kRollEvent});
    }
  }
  grid.for_each_near(i, [&](int j) {
    if (balls.asleep[i] && balls.asleep[j]) return;
    const double t = pair_time(sim, i, j, best.t);
    if (t < kNever) offer({t, i, j, 0, balls.course[j]});
  });
  sim.queue.set(i, best);
}

void run_events_until(ExactSim& sim, double t_end) {
  std::fill(sim.balls.step_events.begin(), sim.balls.step_events.end(), 0);
  const int n = sim.model.ball_count;
  while (n > 0) {
    const int i = sim.queue.top();
    const PredictedEvent ev = sim.queue.event(i);
    if (!(ev.t <= t_end)) break;
    sim.now = ev.t;
    if (ev.j >= 0 && sim.balls.course[ev.j] != ev.cj) {
      predict(sim, i);  // the partner changed course since: look again
      continue;
    }
    if (ev.j >= 0) {
      on_pair(sim, i, ev.j);
    } else if (ev.j == kRollEvent) {
      on_roll(sim, i);
    } else if (!is_cell_face(ev.j)) {
      on_wall(sim, i, wall_axis(ev.j), wall_side(ev.j));
    } else {
      on_cell(sim, i, cell_face_axis(ev.j), cell_face_up(ev.j));
    }
  }
  sim.now = t_end;
  for (int i = 0; i < n; ++i) sim.balls.advance(i, t_end, sim.model.rotation);
  sim.time = t_end;
}

}  // namespace ballbench

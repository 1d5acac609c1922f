#include "solver/exact_cluster.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/exact_sim.h"

namespace ballbench {
namespace {

// Projected Gauss-Seidel sweeps when settling a cluster: this many plus 4 per ball in it.
constexpr int kClusterSweeps = 64;
// Clusters with at most this many contacts are settled exactly (Lemke), larger by Gauss-Seidel.
constexpr size_t kMaxExactContacts = 48;
// Largest cluster settled at once (balls); beyond it, contacts are left to binary events.
constexpr size_t kMaxCluster = 4096;

// Ball k and its contacts join the cluster being gathered.
void join(ExactSim& sim, int k) {
  ClusterScratch& c = sim.cluster;
  if (sim.balls.asleep[k] || c.joined_in[k] == c.settle || c.members.size() >= kMaxCluster) return;
  c.joined_in[k] = c.settle;
  c.position[k] = static_cast<int>(c.members.size());
  sim.balls.advance(k, sim.now, sim.model.rotation);
  c.members.push_back(k);
  for (int d = 0; d < 2; ++d) c.vel_before[d].push_back(sim.balls.vel[d][k]);
}

// The balls touching the impact of i and j through awake balls, and their slow contacts among
// themselves and with walls and sleeping balls.
void gather(ExactSim& sim, int i, int j, bool jammed) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  ClusterScratch& cl = sim.cluster;
  ++cl.settle;
  cl.members.clear();
  cl.contacts.clear();
  for (int d = 0; d < 2; ++d) cl.vel_before[d].clear();
  join(sim, i);
  if (j >= 0) join(sim, j);
  for (size_t q = 0; q < cl.members.size(); ++q) {
    const int k = cl.members[q];
    if (model.has_walls)
      for (int d = 0; d < 2; ++d)
        for (int side = 0; side < 2; ++side) {
          const double gap = side == 0 ? balls.pos[d][k] - balls.radius[k] - model.box_lo[d]
                                       : model.box_hi[d] - balls.radius[k] - balls.pos[d][k];
          if (gap > kTouch * balls.radius[k]) continue;
          ClusterContact c{{k, -1, 0, 0, 1 / balls.inv_mass[k], 0}, 0, gap < -0.5 * kOverlapCap * balls.radius[k]};
          (d == 0 ? c.nx : c.ny) = side == 0 ? 1 : -1;
          if (std::abs(balls.vel[d][k]) > model.rest_velocity && !jammed) continue;  // a real bounce (its own event), or parting
          cl.contacts.push_back(c);
        }
    sim.grid.for_each_near(k, [&](int m) {
      // Each pair once: from the first of the two to be scanned.
      if (!balls.asleep[m] && cl.joined_in[m] == cl.settle && cl.position[m] < static_cast<int>(q)) return;
      balls.advance(m, sim.now, model.rotation);
      double n[2] = {balls.pos[0][k] - balls.pos[0][m], balls.pos[1][k] - balls.pos[1][m]};
      const double dist = norm2(n[0], n[1]), rs = balls.radius[k] + balls.radius[m];
      if (dist == 0 || dist - rs > kTouch * rs) return;
      n[0] /= dist, n[1] /= dist;
      const double wn = (balls.vel[0][k] - balls.vel[0][m]) * n[0] + (balls.vel[1][k] - balls.vel[1][m]) * n[1];
      // Only slow contacts: a real impact (closing faster than rest_velocity) is a binary event
      // that follows at the same time, and a pair parting that fast is not in contact.
      if (std::abs(wn) > model.rest_velocity && !(jammed && wn < 0)) return;
      const double wm = balls.asleep[m] ? 0.0 : balls.inv_mass[m];
      const double Ax = balls.acc[0][k] - balls.acc[0][m], Ay = balls.acc[1][k] - balls.acc[1][m];
      const double press = -(Ax * n[0] + Ay * n[1]);
      const double target =
          pressed(model, press, Ax, Ay, kVelocityNoise * (balls.speed(k) + balls.speed(m))) ? 0.5 * press * model.contact_time : 0.0;
      // Crept to the overlap cap, or pressed together: even a slow closing must stop.
      const bool firm = dist < rs * (1 - 0.5 * kOverlapCap) || target > 0;
      cl.contacts.push_back({{k, balls.asleep[m] ? -1 : m, n[0], n[1], 1 / (balls.inv_mass[k] + wm), 0}, target, firm});
      if (!balls.asleep[m]) join(sim, m);
    });
  }
}

// One awake ball against fixed contacts: its new velocity is the exact projection of the old
// one onto {v : v.n_c >= target_c} (a ball wedged between two nearly opposite supports would
// take Gauss-Seidel millions of sweeps). In 2D at most two contacts are active: try the sets
// of none, one and two, keep the nearest feasible velocity.
void settle_one(ExactSim& sim, int k, double tolerance) {
  ExactBalls& balls = sim.balls;
  const std::vector<ClusterContact>& contacts = sim.cluster.contacts;
  const double v0[2] = {balls.vel[0][k], balls.vel[1][k]};
  const double fine = kVelocityNoise * (norm2(v0[0], v0[1]) + sim.model.rest_velocity);  // round-off of a projection
  auto feasible = [&](const double* v) {
    for (const ClusterContact& c : contacts)
      if (v[0] * c.nx + v[1] * c.ny < c.target - fine) return false;
    return true;
  };
  // Already within the slack of every contact (the Gauss-Seidel tolerance for slow ones)?
  bool slack = true;
  for (const ClusterContact& c : contacts)
    if (v0[0] * c.nx + v0[1] * c.ny < c.target - (c.firm || c.target > 0 ? fine : tolerance)) slack = false;
  if (slack || feasible(v0)) return;
  double best[2] = {v0[0], v0[1]}, best_d2 = kNever;
  auto offer = [&](double x, double y) {
    const double v[2] = {x, y};
    const double d2 = (x - v0[0]) * (x - v0[0]) + (y - v0[1]) * (y - v0[1]);
    if (d2 < best_d2 && feasible(v)) best[0] = x, best[1] = y, best_d2 = d2;
  };
  const int m = static_cast<int>(contacts.size());
  for (int a = 0; a < m; ++a) {
    const ClusterContact& c = contacts[a];
    const double push = c.target - (v0[0] * c.nx + v0[1] * c.ny);
    if (push > 0) offer(v0[0] + push * c.nx, v0[1] + push * c.ny);
  }
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b) {
      const ClusterContact &ca = contacts[a], &cb = contacts[b];
      const double det = ca.nx * cb.ny - ca.ny * cb.nx;
      if (std::abs(det) < 1e-12) continue;
      // v.n_a = t_a and v.n_b = t_b; then the impulses along n_a, n_b must both push.
      const double x = (ca.target * cb.ny - cb.target * ca.ny) / det;
      const double y = (ca.nx * cb.target - cb.nx * ca.target) / det;
      const double dx = x - v0[0], dy = y - v0[1];
      const double la = (dx * cb.ny - dy * cb.nx) / det, lb = (ca.nx * dy - ca.ny * dx) / det;
      if (la >= 0 && lb >= 0) offer(x, y);
    }
  if (best_d2 < kNever) balls.vel[0][k] = best[0], balls.vel[1][k] = best[1];
}

// Normal velocity change of contact c per unit impulse at contact d: J_c M^-1 J_d^T.
double coupling(const std::vector<double>& inv_mass, const ClusterContact& c, const ClusterContact& d) {
  const double dot = c.nx * d.nx + c.ny * d.ny;
  double k = 0;
  if (c.i == d.i) k += inv_mass[c.i];
  if (c.j >= 0 && c.j == d.j) k += inv_mass[c.j];
  if (d.j >= 0 && c.i == d.j) k -= inv_mass[c.i];
  if (c.j >= 0 && c.j == d.i) k -= inv_mass[c.j];
  return k * dot;
}

// A small cluster: the impulses lambda >= 0 solve the linear complementarity problem
//   w = A lambda + b >= 0, lambda >= 0, lambda.w = 0,
// A = J M^-1 J^T (the contacts' coupling through the balls' masses), b = J v - target (a
// contact's normal velocity beyond its target), by Lemke's method (lemke.h). False if it finds
// no solution.
bool settle_exact(ExactSim& sim) {
  ExactBalls& balls = sim.balls;
  ClusterScratch& cl = sim.cluster;
  const int m = static_cast<int>(cl.contacts.size());
  cl.coupling.resize(static_cast<size_t>(m) * m);
  cl.violation.resize(m);
  cl.impulse.resize(m);
  for (int c = 0; c < m; ++c) {
    const ClusterContact& cc = cl.contacts[c];
    double wn = balls.vel[0][cc.i] * cc.nx + balls.vel[1][cc.i] * cc.ny;
    if (cc.j >= 0) wn -= balls.vel[0][cc.j] * cc.nx + balls.vel[1][cc.j] * cc.ny;
    cl.violation[c] = wn - cc.target;
    for (int d = 0; d < m; ++d) cl.coupling[static_cast<size_t>(c) * m + d] = coupling(balls.inv_mass, cc, cl.contacts[d]);
  }
  const LcpOutcome outcome = solve_lcp_lemke(m, cl.coupling.data(), cl.violation.data(), cl.impulse.data(), cl.lemke);
  if (outcome == LcpOutcome::failed) return false;
  if (outcome == LcpOutcome::satisfied) return true;
  for (int c = 0; c < m; ++c) {
    const ClusterContact& cc = cl.contacts[c];
    for (int d = 0; d < 2; ++d) {
      balls.vel[d][cc.i] += cl.impulse[c] * balls.inv_mass[cc.i] * cc.n(d);
      if (cc.j >= 0) balls.vel[d][cc.j] -= cl.impulse[c] * balls.inv_mass[cc.j] * cc.n(d);
    }
  }
  return true;
}

// Projected Gauss-Seidel on the accumulated impulses (each >= 0: contacts only push).
void settle_many(ExactSim& sim, double tolerance) {
  ExactBalls& balls = sim.balls;
  const int sweeps = kClusterSweeps + 4 * static_cast<int>(sim.cluster.members.size());
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    double worst = 0;
    for (ClusterContact& c : sim.cluster.contacts) {
      double wn = balls.vel[0][c.i] * c.nx + balls.vel[1][c.i] * c.ny;
      if (c.j >= 0) wn -= balls.vel[0][c.j] * c.nx + balls.vel[1][c.j] * c.ny;
      if (c.impulse == 0 && !c.firm && c.target == 0 && wn >= -tolerance) continue;  // closing within noise
      const double next = std::max(0.0, c.impulse + (c.target - wn) * c.mass);
      const double dJ = next - c.impulse;
      if (dJ == 0) continue;
      c.impulse = next;
      for (int d = 0; d < 2; ++d) {
        balls.vel[d][c.i] += dJ * balls.inv_mass[c.i] * c.n(d);
        if (c.j >= 0) balls.vel[d][c.j] -= dJ * balls.inv_mass[c.j] * c.n(d);
      }
      worst = std::max(worst, std::abs(dJ) / c.mass);
    }
    if (worst <= tolerance) break;
  }
}

// The simultaneous impact of the cluster: exact for one ball or a few contacts, else projected
// Gauss-Seidel (Catto's sequential impulses) to the tolerance.
void solve_cluster(ExactSim& sim) {
  const double tolerance = kRestSlop * sim.model.rest_velocity;
  if (sim.cluster.members.size() == 1) {
    settle_one(sim, sim.cluster.members[0], tolerance);
  } else if (sim.cluster.contacts.size() > kMaxExactContacts || !settle_exact(sim)) {
    settle_many(sim, tolerance);
  }
}

}  // namespace

void settle_cluster(ExactSim& sim, int i, int j, bool jammed) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  ClusterScratch& cl = sim.cluster;
  if (model.friction > 0)
    throw std::runtime_error(fmt::format(
        "exact: ball {} at t = {} s needs a multi-contact settle ({}), where friction has no closed form", i, sim.now,
        jammed ? "the jam rule: many collisions within contact_time" : "an impact slower than rest_velocity"));
  gather(sim, i, j, jammed);
  // First perfectly inelastic (every target 0); balls left slow and carried fall asleep.
  cl.rebound.resize(cl.contacts.size());
  bool bounce = false;
  for (size_t c = 0; c < cl.contacts.size(); ++c) {
    cl.rebound[c] = cl.contacts[c].target;
    bounce |= cl.rebound[c] > 0;
    cl.contacts[c].target = 0;
  }
  solve_cluster(sim);
  for (const int k : cl.members) try_sleep(sim, k);
  sleep_group(sim, cl.members);
  // Then the pressed contacts of balls still awake get their micro-bounce. Between nearly
  // opposite normals (a wedge) that could take a launch many times rest_velocity: then the
  // micro-bounce is dropped, and the ball is left to the jam rule.
  if (bounce) {
    for (int d = 0; d < 2; ++d) {
      cl.vel_inelastic[d].resize(cl.members.size());
      for (size_t q = 0; q < cl.members.size(); ++q) cl.vel_inelastic[d][q] = balls.vel[d][cl.members[q]];
    }
    size_t kept = 0;
    for (size_t c = 0; c < cl.contacts.size(); ++c) {
      ClusterContact cc = cl.contacts[c];
      if (balls.asleep[cc.i] || (cc.j >= 0 && balls.asleep[cc.j])) continue;
      cc.target = cl.rebound[c], cc.impulse = 0;
      cl.contacts[kept++] = cc;
    }
    cl.contacts.resize(kept);
    solve_cluster(sim);
    double jump = 0;
    for (size_t q = 0; q < cl.members.size(); ++q)
      jump = std::max(jump, norm2(balls.vel[0][cl.members[q]] - cl.vel_inelastic[0][q],
                                  balls.vel[1][cl.members[q]] - cl.vel_inelastic[1][q]));
    if (jump > model.rest_velocity)
      for (size_t q = 0; q < cl.members.size(); ++q)
        for (int d = 0; d < 2; ++d) balls.vel[d][cl.members[q]] = cl.vel_inelastic[d][q];
  }
  for (size_t q = 0; q < cl.members.size(); ++q) {
    const int k = cl.members[q];
    if (!balls.asleep[k] && (balls.vel[0][k] != cl.vel_before[0][q] || balls.vel[1][k] != cl.vel_before[1][q]))
      sim.repredict.changed_course(balls, k), after_impulse(model, balls, k);
  }
}

}  // namespace ballbench

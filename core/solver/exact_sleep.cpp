#include "solver/exact_sleep.h"

#include <algorithm>
#include <cmath>

#include "solver/exact_sim.h"

namespace ballbench {
namespace {

// A single contact carries a ball's weight only if its normal is within this angle of -g (rad):
// a ball perched off-centre on one ball must roll off, not sleep there.
constexpr double kSupportAngle = 1e-9;

void fall_asleep(ExactSim& sim, int k) {
  sim.balls.asleep[k] = 1;
  for (int d = 0; d < 2; ++d) sim.balls.vel[d][k] = 0, sim.balls.acc[d][k] = 0;
  sim.repredict.changed_course(sim.balls, k);
}

}  // namespace

bool supported(const ExactSim& sim, int i, bool with_group) {
  const ExactModel& model = sim.model;
  const ExactBalls& balls = sim.balls;
  if (!model.has_gravity) return false;
  const double* g = model.gravity;
  const double gap = model.support_gap;
  const double gn = norm2(g[0], g[1]);
  const double up[2] = {-g[0] / gn, -g[1] / gn};
  double nrm[16][2];
  int m = 0;
  auto add = [&](double x, double y) {
    if (m < 16) nrm[m][0] = x, nrm[m][1] = y, ++m;
  };
  if (model.has_walls)
    for (int k = 0; k < 2; ++k) {
      if (balls.pos[k][i] - balls.radius[i] - model.box_lo[k] <= gap) add(k == 0 ? 1 : 0, k == 1 ? 1 : 0);
      if (model.box_hi[k] - balls.radius[i] - balls.pos[k][i] <= gap) add(k == 0 ? -1 : 0, k == 1 ? -1 : 0);
    }
  sim.grid.for_each_near(i, [&](int j) {
    if (!balls.asleep[j] && !(with_group && sim.sleep.in_group[j] == sim.sleep.group_round)) return;
    const double dx = balls.pos[0][i] - balls.pos[0][j], dy = balls.pos[1][i] - balls.pos[1][j];
    const double d = norm2(dx, dy);
    if (d > 0 && d - balls.radius[i] - balls.radius[j] <= gap) add(dx / d, dy / d);
  });
  auto cross = [](const double* a, const double* b) { return a[0] * b[1] - a[1] * b[0]; };
  for (int k = 0; k < m; ++k)
    if (nrm[k][0] * up[0] + nrm[k][1] * up[1] > 0 && std::abs(cross(nrm[k], up)) <= kSupportAngle) return true;
  for (int k = 0; k < m; ++k)
    for (int l = k + 1; l < m; ++l) {
      const double c = cross(nrm[k], nrm[l]);
      if (std::abs(c) < 1e-12) continue;
      const double alpha = cross(up, nrm[l]) / c, beta = cross(nrm[k], up) / c;  // up = alpha n_k + beta n_l
      if (alpha >= 0 && beta >= 0) return true;
    }
  return false;
}

// A rough ball on a wall rolls on (exactly), so it never sleeps.
void try_sleep(ExactSim& sim, int i) {
  const ExactModel& model = sim.model;
  const ExactBalls& balls = sim.balls;
  if (balls.asleep[i] || !model.settings.sleep || !model.has_gravity || model.friction > 0) return;
  if (!balls.is_jammed(i) && (balls.speed(i) >= model.rest_velocity || !supported(sim, i))) return;
  fall_asleep(sim, i);
}

// One at a time, none of a group resting on one another would sleep (each rests on another that is
// awake). The group starts as every slow awake candidate and loses, until none is left to lose,
// each ball whose weight walls, sleeping balls and the rest of the group do not carry.
void sleep_group(ExactSim& sim, const std::vector<int>& candidates) {
  const ExactModel& model = sim.model;
  if (!model.settings.sleep || !model.has_gravity) return;
  SleepScratch& s = sim.sleep;
  ++s.group_round;
  s.group.clear();
  for (const int k : candidates)
    if (!sim.balls.asleep[k] && sim.balls.speed(k) < model.rest_velocity) s.in_group[k] = s.group_round, s.group.push_back(k);
  for (bool changed = true; changed && !s.group.empty();) {
    changed = false;
    for (size_t q = 0; q < s.group.size();) {
      const int k = s.group[q];
      if (supported(sim, k, true)) {
        ++q;
        continue;
      }
      s.in_group[k] = 0;
      s.group[q] = s.group.back();
      s.group.pop_back();
      changed = true;
    }
  }
  std::sort(s.group.begin(), s.group.end());
  for (const int k : s.group) fall_asleep(sim, k);
}

void wake(ExactSim& sim, int i) {
  const ExactModel& model = sim.model;
  ExactBalls& balls = sim.balls;
  std::vector<int>& stack = sim.sleep.to_wake;
  stack.assign(1, i);
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    if (!balls.asleep[k]) continue;
    balls.advance(k, sim.now, model.rotation);
    balls.asleep[k] = 0;
    for (int d = 0; d < 2; ++d) balls.acc[d][k] = model.gravity[d];  // every axis free
    sim.repredict.changed_course(balls, k);
    sim.grid.for_each_near(k, [&](int m) {
      if (!balls.asleep[m]) return;
      const double dx = balls.pos[0][m] - balls.pos[0][k], dy = balls.pos[1][m] - balls.pos[1][k];
      const bool above = dx * model.gravity[0] + dy * model.gravity[1] < 0;
      if (above && norm2(dx, dy) - balls.radius[k] - balls.radius[m] <= model.support_gap) stack.push_back(m);
    });
  }
}

}  // namespace ballbench

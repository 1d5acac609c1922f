#include "solver/home_soft.h"

#include <algorithm>
#include <cmath>

#include "solver/contact.h"

namespace ballbench {
namespace {

// The soft step's contacts reach this fraction of the largest radius beyond what the balls' motion
// can close within the step (speculative margin).
constexpr double kSoftMargin = 0.1;

// The largest squared speed and the positions' bounds, now.
StartScan scan(const HomeWorld& w) {
  StartScan s;
  for (int i = 0; i < w.n; ++i) s.add(w.p(i, 0), w.p(i, 1), w.v(i, 0) * w.v(i, 0) + w.v(i, 1) * w.v(i, 1));
  return s;
}

}  // namespace

SoftResting::SoftResting(const HomeSettings& s, int n)
    : soft_(s.soft), max_stride_(s.max_stride), max_parts_(s.max_parts) {
  if (s.sleep_speed > 0) sleep_ = SleepIslands(n, s.sleep_speed, s.sleep_time);
}

void SoftResting::step(HomeWorld& w, double dt, double v_rest, bool no_pairs, HomeGrid& grid, ForkJoin& pool,
                       const std::function<void()>& renumber_if_due) {
  if (sleep_.all_asleep()) return;  // every ball asleep: nothing can move or wake one
  const StartScan first = scan(w);
  const double travel = (std::sqrt(first.speed2) + w.g.norm() * dt) * dt;
  const double parts = std::ceil(travel / (max_stride_ * w.rmin));
  const int k = parts > 1 ? static_cast<int>(std::min(parts, static_cast<double>(max_parts_))) : 1;
  for (int p = 0; p < k; ++p) part(w, dt / k, v_rest, no_pairs, p == 0 ? first : scan(w), grid, pool, renumber_if_due);
}

// One soft step (soft_step.h) of dt over every contact that can touch within it, found on a grid
// whose cells cover the fastest ball's motion; `start`: the state's scan at its start.
void SoftResting::part(HomeWorld& w, double dt, double v_rest, bool no_pairs, const StartScan& start, HomeGrid& grid,
                       ForkJoin& pool, const std::function<void()>& renumber_if_due) {
  if (sleep_.all_asleep()) return;
  const int n = w.n;
  const double g = w.g.norm();
  const double speed2 = start.speed2;
  // The warm start holds one substep's impulses; a substep of another length scales them.
  const double h = dt / std::max(soft_.substeps, 1);
  const double warm_scale = warm_h_ > 0 ? h / warm_h_ : 1.0;
  warm_h_ = h;
  // Gravity adds at most g dt within the step; contacts can speed a ball up (kSpeedMargin).
  const double reach = (std::sqrt(speed2) + g * dt) * dt * kSpeedMargin;
  const double margin = kSoftMargin * w.rmax;
  contacts_.clear();
  // The mass is set once it is known which balls sleep (below).
  const auto add = [&](int i, int j, double nx, double ny, double gap) {
    const double warm = warm_.find(i, j);
    contacts_.push_back({{i, j, nx, ny, 0.0, warm > 0 ? warm * warm_scale : 0.0}, gap, 0.0, 0.0});
  };
  // A pair that can touch within the step, the lower number first, so the warm start finds it
  // whichever cell order the grid gave it this step. Their closing speed is bounded by the sum
  // of their speeds, not their relative speed: two balls falling together close at once when the
  // lower one lands. (|va| + |vb| <= sqrt(2 (va^2 + vb^2)), one square root.)
  const double* __restrict px = w.p.col(0).data();
  const double* __restrict py = w.p.col(1).data();
  const double* __restrict vx = w.v.col(0).data();
  const double* __restrict vy = w.v.col(1).data();
  const double* __restrict radius = w.equal_radii ? nullptr : w.r.data();
  const double r0 = w.r0;
  const auto try_pair = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    const double dx = px[a] - px[b], dy = py[a] - py[b];
    const double speed2 = vx[a] * vx[a] + vy[a] * vy[a] + vx[b] * vx[b] + vy[b] * vy[b];
    const double rs = radius ? radius[a] + radius[b] : r0 + r0;
    const double lim = rs + (std::sqrt(2 * speed2) + 2 * g * dt) * dt * kSpeedMargin + margin;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= lim * lim || d2 == 0) return;
    const double d = std::sqrt(d2);
    add(a, b, dx / d, dy / d, d - rs);
  };
  const auto try_walls = [&](int i) {
    for (int axis = 0; axis < 2; ++axis) {
      const double v = w.v(i, axis), toward = std::abs(v) + g * dt;
      for (int side = 0; side < 2; ++side) {
        const double gap = w.wall_gap(i, axis, side);
        if (gap >= toward * dt * kSpeedMargin + margin) continue;
        const double sign = side == 0 ? 1.0 : -1.0;  // the normal points into the box
        add(i, wall_partner(axis, side), axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, gap);
      }
    }
  };
  // Two sleeping balls have no contact: neither moves (unless one wakes, below).
  const int sleeping = sleep_.sleeping();
  const auto asleep = [&](int i) { return sleep_.asleep(i); };
  if (!no_pairs) {
    grid.build(w.p, w.r, 2.0 * w.rmax + 2.0 * reach + margin, pool, false, &start.bounds);
    renumber_if_due();
    if (sleeping > 0 && 2 * sleeping > n) {
      // Mostly asleep: the pairs around the balls awake, not every pair of the grid.
      for (int i = 0; i < n; ++i)
        if (!asleep(i))
          grid.for_each_near(i, [&](int j) {
            if (j != i && (asleep(j) || j > i)) try_pair(i, j);
          });
    } else {
      const int* id = grid.id();
      grid.for_each_forward_pair(0, grid.balls(), [&](int sa, int sb) {
        const int a = id[sa], b = id[sb];
        if (sleeping == 0 || !(asleep(a) && asleep(b))) try_pair(a, b);
      });
    }
  }
  if (w.walls)
    for (int i = 0; i < n; ++i)
      if (sleeping == 0 || !asleep(i)) try_walls(i);
  if (sleeping > 0) {
    // A ball woken now gains the contacts it had none of while it slept.
    sleep_.wake_touched(contacts_, w.v.col(0).data(), w.v.col(1).data());
    for (int i : sleep_.woken()) {
      if (!no_pairs)
        grid.for_each_near(i, [&](int j) {
          const SleepIslands::State sj = sleep_.state(j);
          if (sj == SleepIslands::kAsleep || (sj == SleepIslands::kWoken && j > i)) try_pair(i, j);
        });
      if (w.walls) try_walls(i);
    }
    sleep_.finish_waking();
  }
  const double* inv_m = w.equal_masses ? nullptr : w.inv_m.data();
  const std::vector<int>& awake = sleep_.awake(n, inv_m, w.inv_m0);
  if (sleep_.sleeping() > 0) inv_m = sleep_.held_inv_mass().data();
  for (SoftContact& c : contacts_) {
    const double wi = inv_m ? inv_m[c.i] : w.inv_m0, wj = c.j < 0 ? 0.0 : inv_m ? inv_m[c.j] : w.inv_m0;
    c.mass = 1.0 / (wi + wj);
  }
  const SoftBodies bodies{w.p.col(0).data(),
                          w.p.col(1).data(),
                          w.v.col(0).data(),
                          w.v.col(1).data(),
                          inv_m,
                          w.inv_m0,
                          sleep_.sleeping() > 0 ? awake.data() : nullptr,
                          static_cast<int>(awake.size())};
  soft_step(bodies, n, contacts_, w.g.x(), w.g.y(), dt, soft_, {w.e, v_rest}, scratch_);
  if (sleep_.enabled()) sleep_.fall_asleep(contacts_, w.v.col(0).data(), w.v.col(1).data(), dt);
  warm_entries_.clear();
  for (const SoftContact& c : contacts_)
    if (c.impulse > 0) warm_entries_.push_back({c.i, c.j, c.impulse});
  warm_.assign(warm_entries_);
}

}  // namespace ballbench

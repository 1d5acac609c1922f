#include "solver/home_broad_grid.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace ballbench {
namespace {

// The screen's kernel over slots [s0, s1), reading the state through the slot -> ball map (nearly
// the identity between renumberings, so nearly front to back). The rare outcome (a contact, or
// an approach within the step) takes one branch, decided by both tests at once, and the kernel
// only records the pair: making the contact inside it would grow the rare branch and slow the
// sweep. The part then makes its pairs' contacts, from the state it has just read, in parallel
// (a serial pass over all pairs afterwards would read the state again), by add_pair_contact's
// expressions (make_pair_contact). Internal linkage (this file's own), so the compiler inlines the
// pair test into the walk at -O2 as at -O3.
template <bool kEqualRadii>
void screen_slots(const HomeWorld& w, EventStep& s, const HomeGrid& grid, const RestingContacts& contacts, int s0, int s1,
                  double reach, std::vector<std::pair<int, int>>& hits, std::vector<PassContact>& found) {
  const double slop = s.slop, two = 2.0, dt = s.dt, rs0 = w.r0 + w.r0;
  const double lim0 = rs0 + std::max(slop * rs0, reach), lim0_2 = lim0 * lim0, rs0_2 = rs0 * rs0;
  const double* __restrict x = w.p.col(0).data();
  const double* __restrict y = w.p.col(1).data();
  const double* __restrict vx = w.v.col(0).data();
  const double* __restrict vy = w.v.col(1).data();
  const double* __restrict r = w.r.data();
  const int* __restrict id = grid.id();
  uint8_t* active = s.active.data();
  grid.for_each_forward_pair(s0, s1, [&](int sa, int sb) {
    const int a = id[sa], b = id[sb];  // nearly sa and sb: the balls are renumbered in cell order
    const double dx = x[a] - x[b], dy = y[a] - y[b];
    const double wx = vx[a] - vx[b], wy = vy[a] - vy[b];
    const double d2 = dx * dx + dy * dy, bb = dx * wx + dy * wy;
    double lim2, rs2;
    if constexpr (kEqualRadii) {
      lim2 = lim0_2, rs2 = rs0_2;
    } else {
      const double rs = r[a] + r[b];
      const double lim = rs + std::max(slop * rs, reach);
      lim2 = lim * lim, rs2 = rs * rs;
    }
    const bool contact = d2 < lim2 && d2 != 0;
    // & rather than &&: the sign of b is a coin toss per pair, a branch on it mispredicts half the time.
    const bool approach = (bb < 0) & ((d2 - rs2) + two * bb * dt <= 0);
    if (contact | approach) [[unlikely]] {
      if (contact) hits.push_back({a, b});
      if (approach) {
        // Both parts may mark the same ball (the same value): atomic, relaxed, free on x86.
        std::atomic_ref<uint8_t>(active[a]).store(1, std::memory_order_relaxed);
        std::atomic_ref<uint8_t>(active[b]).store(1, std::memory_order_relaxed);
      }
    }
  });
  for (const auto& [a, b] : hits) {
    const double dx = x[a] - x[b], dy = y[a] - y[b];
    PassContact c;
    if (contacts.make_pair_contact(w, s, a, b, dx, dy, dx * dx + dy * dy, vx[a] - vx[b], vy[a] - vy[b],
                                   kEqualRadii ? rs0 : r[a] + r[b], dt, true, c)) {
      contacts.find_warm_impulse(c);
      found.push_back(c);
    }
  }
}

}  // namespace

GridBroadPhase::GridBroadPhase(const HomeShortcuts& sc, const HomeSettings&, int, int parts)
    : sc_(sc), start_parts_(parts), wall_hits_(parts), pair_hits_(parts), pair_contacts_(parts) {}

void GridBroadPhase::start_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, bool renumber_due,
                                const std::function<bool()>& renumber_if_due) {
  start_pass(w, s, pool, renumber_due);
  build(w, grid, pool, s.dt, false);
  // A renumbering moves the balls: the wall screen start_pass did is done again after it.
  if (!sc_.no_pairs && renumber_if_due()) walls_screened_ = false;
}

// One read of the state instead of five: the end of the last step (each ball from its own clock to
// the step's end), the kick (symplectic Euler's velocity update), the largest speed and the
// positions' bounds for the grid, and the wall screen (screen_walls) unless a renumbering is due.
void GridBroadPhase::start_pass(HomeWorld& w, EventStep& s, ForkJoin& pool, bool renumber_due) {
  const int parts = pool.parts();
  const bool screen = w.walls && !sc_.no_walls && !renumber_due;
  const double reach = s.v_rest * s.dt;
  pool.run([&](int p) {
    wall_hits_[p].clear();
    const int b = static_cast<int>(ForkJoin::range_begin(w.n, p, parts));
    const int e = static_cast<int>(ForkJoin::range_begin(w.n, p + 1, parts));
    std::vector<int>& near = wall_hits_[p];
    start_parts_[p] = screen ? scan<Scan{.start = true, .screen = true}>(w, s, b, e, reach, near)
                             : scan<Scan{.start = true}>(w, s, b, e, reach, near);
  });
  unfinished_ = 0;
  start_ = StartScan{};
  for (const StartScan& q : start_parts_) start_.merge(q);
  walls_screened_ = screen;
}

// The grid over the positions now, with cells wide enough that any two balls which can touch
// within `horizon` are in adjacent cells. At the start of a step start_pass has measured the speeds
// and bounds; in mid-step they are taken afresh.
void GridBroadPhase::build(const HomeWorld& w, HomeGrid& grid, ForkJoin& pool, double horizon, bool mid_step) {
  vbound_ = (mid_step ? w.max_speed() : std::sqrt(start_.speed2)) * kSpeedMargin;
  if (sc_.no_pairs) return;
  grid.build(w.p, w.r, 2.0 * w.rmax + 2.0 * vbound_ * horizon, pool, false, mid_step ? nullptr : &start_.bounds);
}

// Rare (large mass ratios, chains of impacts). Not renumbered: the event loop holds ball numbers.
void GridBroadPhase::rebuild_mid_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, double t) {
  for (int i = 0; i < w.n; ++i) s.advance(w, i, t);
  build(w, grid, pool, s.dt - t, true);
}

void GridBroadPhase::screen(HomeWorld& w, EventStep& s, const HomeGrid& grid, ForkJoin& pool,
                            RestingContacts& contacts) {
  const double reach = s.v_rest * s.dt;
  if (sc_.no_walls) {
    std::fill(s.active.begin(), s.active.end(), 0);
  } else {
    if (!walls_screened_) screen_walls(w, s, pool, reach);
    const size_t first = contacts.size();
    for (const auto& near : wall_hits_)
      for (int i : near) contacts.add_wall_contacts(w, s, i, reach, s.dt, true);
    contacts.find_warm_impulses(first);
  }
  if (sc_.no_pairs) return;
  sc_.equal_radii ? screen_pairs<true>(w, s, grid, pool, contacts, reach)
                  : screen_pairs<false>(w, s, grid, pool, contacts, reach);
  for (const auto& found : pair_contacts_) contacts.append(found);
}

// Per ball, in parallel: `active` if it can reach the wall it moves towards within the step
// (predict's test max(gap, 0) / |v| <= dt, as gap <= |v| dt with a relative margin far above
// round-off, so it never says no where predict would say yes), and listed in wall_hits_, in ball
// order, if a wall is within contact reach (add_wall_contacts' test, the same expressions).
void GridBroadPhase::screen_walls(HomeWorld& w, EventStep& s, ForkJoin& pool, double reach) {
  const int parts = pool.parts();
  pool.run([&](int p) {
    wall_hits_[p].clear();
    const int b = static_cast<int>(ForkJoin::range_begin(w.n, p, parts));
    const int e = static_cast<int>(ForkJoin::range_begin(w.n, p + 1, parts));
    if (sc_.elastic)
      scan<Scan{.contacts = false, .screen = true}>(w, s, b, e, reach, wall_hits_[p]);
    else
      scan<Scan{.screen = true}>(w, s, b, e, reach, wall_hits_[p]);
  });
}

template <GridBroadPhase::Scan kScan>
StartScan GridBroadPhase::scan(HomeWorld& w, EventStep& s, int b, int e, double reach, std::vector<int>& near) {
  constexpr Scan equal{.equal_radii = true, .contacts = kScan.contacts, .start = kScan.start, .screen = kScan.screen};
  return sc_.equal_radii ? scan_range<equal>(w, s, b, e, reach, near) : scan_range<kScan>(w, s, b, e, reach, near);
}

// Balls [b, e), as kScan says.
template <GridBroadPhase::Scan kScan>
StartScan GridBroadPhase::scan_range(HomeWorld& w, EventStep& s, int b, int e, double reach, std::vector<int>& near) {
  constexpr bool kEqualRadii = kScan.equal_radii, kContacts = kScan.contacts, kStart = kScan.start,
                 kScreen = kScan.screen;
  const double k = s.dt * (1.0 + 1e-9), slop = s.slop;
  double* __restrict x = w.p.col(0).data();
  double* __restrict y = w.p.col(1).data();
  double* __restrict tl = s.clock.data();
  const double end = unfinished_;
  double* __restrict vx = w.v.col(0).data();
  double* __restrict vy = w.v.col(1).data();
  const double* __restrict rad = w.r.data();
  uint8_t* __restrict active = s.active.data();
  const double x0 = w.box.min(0), x1 = w.box.max(0), y0 = w.box.min(1), y1 = w.box.max(1), r0 = w.r0;
  if (kScreen && !w.walls) {  // open space without the no-walls shortcut: nothing reaches a wall
    std::fill(active + b, active + e, 0);
    if (!kStart) return {};
  }
  const bool kick = kStart && !sc_.no_gravity;
  const double gx = w.g.x() * s.dt, gy = w.g.y() * s.dt;
  StartScan q;
  for (int i = b; i < e; ++i) {
    if constexpr (kStart) {
      if (end > 0) {  // as EventStep::advance to the step's end
        x[i] = on_line(x[i], vx[i], end, tl[i]), y[i] = on_line(y[i], vy[i], end, tl[i]);
        tl[i] = 0;
      }
      if (kick) vx[i] += gx, vy[i] += gy;  // as the Eigen kick: v + g dt, each component
      q.add(x[i], y[i], vx[i] * vx[i] + vy[i] * vy[i]);
    }
    if (!kScreen || !w.walls) continue;
    const double r = kEqualRadii ? r0 : rad[i];
    const double gx0 = x[i] - r - x0, gx1 = x1 - r - x[i], gy0 = y[i] - r - y0, gy1 = y1 - r - y[i];
    const bool hit = reaches_wall(gx0, gx1, gy0, gy1, vx[i], vy[i], k);
    if constexpr (kContacts) {
      const bool touch = std::min(std::min(gx0, gx1), std::min(gy0, gy1)) < std::max(slop * r, reach);
      active[i] = touch | hit;
      if (touch) [[unlikely]] near.push_back(i);
    } else {
      active[i] = hit;
    }
  }
  return q;
}

// One sweep over every pair of balls in adjacent cells, in cell order, in parallel over fixed runs
// of slots. It makes (a) the contacts of the pairs within contact reach (add_pair_contact's, with
// their warm-start impulses), in the order the contact pass has always added them, and (b) marks
// `active` both balls of every pair predict could find an event for: approaching (b < 0) and not
// provably apart at the end of the step by the very bound predict uses, |d|^2 + 2 b dt > (r_i +
// r_j)^2. A ball in no such pair, no contact and no wall reach has no event this step (its predict
// would find none), so it is not predicted: results are bit-identical to predicting every ball.
template <bool kEqualRadii>
void GridBroadPhase::screen_pairs(const HomeWorld& w, EventStep& s, const HomeGrid& grid, ForkJoin& pool,
                                  const RestingContacts& contacts, double reach) {
  const int parts = pool.parts();
  pool.run([&](int p) {
    pair_hits_[p].clear();
    pair_contacts_[p].clear();
    const int n = grid.balls();
    screen_slots<kEqualRadii>(w, s, grid, contacts, static_cast<int>(ForkJoin::range_begin(n, p, parts)),
                              static_cast<int>(ForkJoin::range_begin(n, p + 1, parts)), reach, pair_hits_[p],
                              pair_contacts_[p]);
  });
}

}  // namespace ballbench

#include "solver/home_broad_list.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace ballbench {
namespace {

// The screen's time for a pair that touches at the start of the step (see first_pair_events).
constexpr double kTouching = -1;

}  // namespace

ListBroadPhase::ListBroadPhase(const HomeShortcuts& sc, const HomeSettings& s, int n, int parts)
    : sc_(sc),
      list_steps_(s.list_steps),
      near_wall_mark_(n, 0),
      extent_(parts),
      approaches_(parts),
      first_t_(n, kNever),
      first_j_(n, -1) {}

void ListBroadPhase::start_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, bool,
                                const std::function<bool()>& renumber_if_due) {
  if (!sc_.no_gravity) {
    w.v.col(0).array() += w.g.x() * s.dt;
    w.v.col(1).array() += w.g.y() * s.dt;
  }
  if (!covers(s.dt)) rebuild(w, grid, pool, s.dt, s.dt, w.p, start_speed(w), &renumber_if_due);
}

// Every ball stays within half the skin of where it was at the list's build over the next
// `horizon` at its present velocity (its path is straight, its distance from there convex, so the
// ends decide). A collision that changes a velocity is checked again (too_fast). The largest
// displacement plus the largest speed bounds every ball's own sum; the last step's end_step
// measured both (extent_), and nothing has moved since.
bool ListBroadPhase::covers(double horizon) const {
  if (half_skin_ < 0) return false;  // no list yet
  double moved2 = 0, speed2 = 0;
  for (const auto& [m, v] : extent_) moved2 = std::max(moved2, m), speed2 = std::max(speed2, v);
  return std::sqrt(moved2) + std::sqrt(speed2) * horizon <= half_skin_;
}

// The largest speed at the start of a step, as the last step's end_step measured it (before the
// first step, when nothing has measured it, counted afresh).
double ListBroadPhase::start_speed(const HomeWorld& w) const {
  if (half_skin_ < 0) return w.max_speed();
  double speed2 = 0;
  for (const auto& e : extent_) speed2 = std::max(speed2, e.second);
  return std::sqrt(speed2);
}

// A fresh list from the positions `at` (w.p at the start of a step; in mid-step, where each
// ball's line has taken it): a grid with cells of 2 r_max + skin, its adjacent pairs closer than
// r_i + r_j + skin kept. The skin lets the fastest ball (`vmax` now) move for list_steps steps of
// dt, and at least over `horizon`. Renumbering in cell order, when due (at the start of a step
// only: `renumber_if_due` is null in mid-step), happens on this grid, so the list is built in the
// new numbers: it leaves the grid's slot -> ball map the identity and w.p (so `at`) in the new order.
void ListBroadPhase::rebuild(HomeWorld& w, HomeGrid& grid, ForkJoin& pool, double dt, double horizon,
                             const Eigen::MatrixX2d& at, double vmax, const std::function<bool()>* renumber_if_due) {
  // The relative margin keeps round-off in the positions from failing the check at once.
  half_skin_ = vmax * std::max(list_steps_ * dt, horizon) * (1.0 + 1e-9);
  for (int i : near_wall_) near_wall_mark_[i] = 0;  // in the numbers before a renumbering
  // The list is built from the grid's copy of the positions.
  grid.build(at, w.r, 2.0 * w.rmax + 2.0 * half_skin_, pool, true);
  if (renumber_if_due) (*renumber_if_due)();
  list_.build(grid, sc_.equal_radii, w.r0, 2.0 * half_skin_, pool);
  built_at_ = at;
  // A ball farther than 2 half_skin from every wall now starts each step the list covers within
  // half_skin - |v| dt of here (covers), so more than half_skin + |v| dt from every wall: it
  // cannot reach one before a collision changes its course (and then it is predicted anyway).
  // Only the grid's edge cells can hold such a ball: the rest are not looked at.
  near_wall_.clear();
  if (!w.walls) return;
  const double reach = w.rmax + 2.0 * half_skin_;
  const int* id = grid.id();
  grid.for_each_slot_beyond(w.box.min(0) + reach, w.box.max(0) - reach, w.box.min(1) + reach, w.box.max(1) - reach,
                            [&](int s) {
                              const int i = id[s];
                              const auto [gx0, gx1, gy0, gy1] = wall_gaps(w, built_at_(i, 0), built_at_(i, 1), w.radius(i));
                              if (std::min(std::min(gx0, gx1), std::min(gy0, gy1)) <= 2.0 * half_skin_)
                                near_wall_.push_back(i);
                            });
  for (int i : near_wall_) near_wall_mark_[i] = 1;
}

// Gaps (m) between a ball at (x, y) of radius r and the walls: min x, max x, min y, max y.
std::array<double, 4> ListBroadPhase::wall_gaps(const HomeWorld& w, double x, double y, double r) {
  return {x - r - w.box.min(0), w.box.max(0) - r - x, y - r - w.box.min(1), w.box.max(1) - r - y};
}

void ListBroadPhase::rebuild_mid_step(HomeWorld& w, EventStep& s, HomeGrid& grid, ForkJoin& pool, double t) {
  rebuild_at_ = w.p + (w.v.array().colwise() * (t - Eigen::Map<const Eigen::ArrayXd>(s.clock.data(), w.n))).matrix();
  rebuild(w, grid, pool, s.dt, s.dt - t, rebuild_at_, w.max_speed(), nullptr);
}

void ListBroadPhase::screen(HomeWorld& w, EventStep& s, const HomeGrid&, ForkJoin& pool, RestingContacts&) {
  std::fill(s.active.begin(), s.active.end(), 0);
  if (!sc_.no_walls) {
    // Only balls near a wall when the list was built can reach one before it expires.
    const double k = s.dt * (1.0 + 1e-9);
    for (int i : near_wall_) {
      const auto [gx0, gx1, gy0, gy1] = wall_gaps(w, w.p(i, 0), w.p(i, 1), w.radius(i));
      s.active[i] = reaches_wall(gx0, gx1, gy0, gy1, w.v(i, 0), w.v(i, 1), k);
    }
  }
  sc_.equal_radii ? screen_list<true>(w, s, pool) : screen_list<false>(w, s, pool);
  first_pair_events();
}

// The pair screen over the list, in parallel over fixed runs of pairs: the grid's screen's test
// (GridBroadPhase::screen_slots). A pair that passes it but is not listed cannot touch within the
// step (the list covers it), so it has no event and the balls marked active are those the grid's
// screen would mark. Every pair that passes also gets its collision time here, by next_event's own
// expressions (approach_root), into approaches_: the balls' first events come from them instead
// of from walking each active ball's 3 x 3 cells again (first_pair_events).
template <bool kEqualRadii>
void ListBroadPhase::screen_list(const HomeWorld& w, EventStep& s, ForkJoin& pool) {
  const int parts = pool.parts();
  const long m = list_.pairs();
  const double dt = s.dt, two = 2.0, rs0_2 = 4.0 * w.r0 * w.r0;
  pool.run([&](int p) {
    std::vector<Approach>& found = approaches_[p];
    found.clear();
    const long k0 = ForkJoin::range_begin(m, p, parts), k1 = ForkJoin::range_begin(m, p + 1, parts);
    const int* __restrict first = list_.first();
    const int* __restrict second = list_.second();
    const double* __restrict x = w.p.col(0).data();
    const double* __restrict y = w.p.col(1).data();
    const double* __restrict vx = w.v.col(0).data();
    const double* __restrict vy = w.v.col(1).data();
    uint8_t* active = s.active.data();
    for (long k = k0; k < k1; ++k) {
      const int a = first[k], b = second[k];
      const double dx = x[a] - x[b], dy = y[a] - y[b];
      const double wx = vx[a] - vx[b], wy = vy[a] - vy[b];
      const double d2 = dx * dx + dy * dy, bb = dx * wx + dy * wy;
      double rs2 = rs0_2;
      if constexpr (!kEqualRadii) {
        const double rs = w.r(a) + w.r(b);
        rs2 = rs * rs;
      }
      if ((bb < 0) & ((d2 - rs2) + two * bb * dt <= 0)) [[unlikely]] {
        std::atomic_ref<uint8_t>(active[a]).store(1, std::memory_order_relaxed);
        std::atomic_ref<uint8_t>(active[b]).store(1, std::memory_order_relaxed);
        const double rs = w.radius(a) + w.radius(b), touch = rs + s.touching_gap(rs);
        // next_event's expressions from t0 = 0 (0 + t is t): the pair touches now, or meets at t.
        const double t = d2 < touch * touch ? kTouching : approach_root(bb, d2 - rs * rs, wx, wy);
        if (t <= dt) found.push_back({a, b, t});
      }
    }
  });
}

// The first pair event of every ball the screen found approaching, as next_event would find it
// from the start of the step (its pair part: the earliest time, a tie to the first pair met).
// next_event meets pairs in cell order, which is not the screen's, so a ball whose earliest time
// is shared by two partners gets kAsk (next_event decides), as does one in a pair that touches now:
// such a pair's event (t0) depends on the pairs met before it (its prune). Both are rare.
void ListBroadPhase::first_pair_events() {
  for (const auto& found : approaches_)
    for (const Approach& f : found) {
      const auto note = [&](int i, int j) {
        if (first_j_[i] == kAsk) return;
        if (f.t == kTouching || f.t == first_t_[i]) first_j_[i] = kAsk;
        else if (f.t < first_t_[i]) first_t_[i] = f.t, first_j_[i] = j;
      };
      note(f.a, f.b), note(f.b, f.a);
    }
}

void ListBroadPhase::first_events_queued() {
  for (const auto& found : approaches_)
    for (const Approach& f : found) first_t_[f.a] = first_t_[f.b] = kNever, first_j_[f.a] = first_j_[f.b] = -1;
}

void ListBroadPhase::end_step(HomeWorld& w, EventStep& s, ForkJoin& pool) {
  const int parts = pool.parts();
  pool.run([&](int p) {
    const int b = static_cast<int>(ForkJoin::range_begin(w.n, p, parts));
    const int e = static_cast<int>(ForkJoin::range_begin(w.n, p + 1, parts));
    double* __restrict x = w.p.col(0).data();
    double* __restrict y = w.p.col(1).data();
    const double* __restrict vx = w.v.col(0).data();
    const double* __restrict vy = w.v.col(1).data();
    double* __restrict tl = s.clock.data();
    const double* __restrict bx = built_at_.col(0).data();
    const double* __restrict by = built_at_.col(1).data();
    const double dt = s.dt;
    double moved2 = 0, speed2 = 0;
    for (int i = b; i < e; ++i) {
      x[i] = on_line(x[i], vx[i], dt, tl[i]), y[i] = on_line(y[i], vy[i], dt, tl[i]);
      tl[i] = 0;
      const double dx = x[i] - bx[i], dy = y[i] - by[i];
      moved2 = std::max(moved2, dx * dx + dy * dy);
      speed2 = std::max(speed2, vx[i] * vx[i] + vy[i] * vy[i]);
    }
    extent_[p] = {moved2, speed2};
  });
}

}  // namespace ballbench

#include "solver/home_soft.h"

#include <algorithm>
#include <cmath>

#include "solver/contact.h"
#include "solver/rough_impact.h"

namespace ballbench {
namespace {

// The soft step's contacts reach this fraction of the largest radius beyond what the balls' motion
// can close within the step (speculative margin).
constexpr double kSoftMargin = 0.1;

// How far a ball may move within a part of dt that starts at `start`: gravity adds at most g dt,
// and contacts can speed a ball up (kSpeedMargin). A pair closes at most twice as far.
double part_reach(const HomeWorld& w, const StartScan& start, double dt) {
  return (std::sqrt(start.speed2) + w.g.norm() * dt) * dt * kSpeedMargin;
}

// The largest squared speed and the positions' bounds, now.
StartScan scan(const HomeWorld& w) {
  StartScan s;
  for (int i = 0; i < w.n; ++i) s.add(w.p(i, 0), w.p(i, 1), w.v(i, 0) * w.v(i, 0) + w.v(i, 1) * w.v(i, 1));
  return s;
}

// Which contacts can touch within a part of dt: a pair whose gap the sum of the two balls' reach
// speeds (not their relative speed: two balls falling together close at once when the lower one
// lands), with what gravity adds, can close within it, or a wall a ball can reach, plus `margin`.
// A ball's reach speed (reach_speeds) is its own or a faster neighbour's.
struct ContactTest {
  const double* __restrict px;
  const double* __restrict py;
  const double* __restrict speed;   // per ball: its reach speed (m/s)
  const double* __restrict radius;  // null: every ball has r0
  double r0, g, dt, margin;
  const HomeWorld& w;

  ContactTest(const HomeWorld& w, const std::vector<double>& speed, double dt, double margin)
      : px(w.p.col(0).data()),
        py(w.p.col(1).data()),
        speed(speed.data()),
        radius(w.equal_radii ? nullptr : w.r.data()),
        r0(w.r0),
        g(w.g.norm()),
        dt(dt),
        margin(margin),
        w(w) {}

  // Pair a < b: if it can touch, its contact to `add(a, b, nx, ny, gap)`; whether it did.
  template <class Add>
  bool pair(int a, int b, Add&& add) const {
    const double dx = px[a] - px[b], dy = py[a] - py[b];
    const double rs = radius ? radius[a] + radius[b] : r0 + r0;
    const double lim = rs + (speed[a] + speed[b] + 2 * g * dt) * dt * kSpeedMargin + margin;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= lim * lim || d2 == 0) return false;
    const double d = std::sqrt(d2);
    add(a, b, dx / d, dy / d, d - rs);
    return true;
  }

  // Wall `side` of `axis` for ball i, as pair().
  template <class Add>
  bool wall(int i, int axis, int side, Add&& add) const {
    const double gap = w.wall_gap(i, axis, side);
    if (gap >= (speed[i] + g * dt) * dt * kSpeedMargin + margin) return false;
    const double sign = side == 0 ? 1.0 : -1.0;  // the normal points into the box
    add(i, wall_partner(axis, side), axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, gap);
    return true;
  }
  template <class Add>
  void walls(int i, Add&& add) const {
    for (int axis = 0; axis < 2; ++axis)
      for (int side = 0; side < 2; ++side) wall(i, axis, side, add);
  }
};

// How far beyond what can touch within the step the candidates reach, in radii of the largest ball:
// in a settled hexagonal pile the next shell of neighbours is 1.46 radii beyond touching, so half a
// radius adds no candidate there, and a pile at rest keeps its candidates for good.
constexpr double kCandidateSkin = 0.5;

// Each ball's reach speed within a part: the largest of its own speed and its candidate
// neighbours' (pairs (i, j), j < 0 a wall). A ball struck within the part by a faster one carries
// that speed on: beside a wall, or a hair's breadth from a ball it was not closing on, it crosses
// a gap its own speed would not (a column landing on the balls at rest below it).
template <class Pairs>
void reach_speeds(const HomeWorld& w, const Pairs& pairs, std::vector<double>& own, std::vector<double>& reach) {
  own.resize(w.n);
  for (int i = 0; i < w.n; ++i) own[i] = std::sqrt(w.v(i, 0) * w.v(i, 0) + w.v(i, 1) * w.v(i, 1));
  reach = own;
  for (const auto& c : pairs)
    if (c.j >= 0) reach[c.i] = std::max(reach[c.i], own[c.j]), reach[c.j] = std::max(reach[c.j], own[c.i]);
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

// One soft step (soft_step.h) of dt over every contact that can touch within it; `start`: the
// state's scan at its start.
void SoftResting::part(HomeWorld& w, double dt, double v_rest, bool no_pairs, const StartScan& start, HomeGrid& grid,
                       ForkJoin& pool, const std::function<void()>& renumber_if_due) {
  if (sleep_.all_asleep()) return;
  const int n = w.n;
  // The warm start holds one substep's impulses; a substep of another length scales them.
  const double h = dt / std::max(soft_.substeps, 1);
  warm_scale_ = warm_h_ > 0 ? h / warm_h_ : 1.0;
  warm_h_ = h;
  contacts_.clear();
  if (sleep_.enabled())
    gather_awake(w, dt, no_pairs, start, grid, pool, renumber_if_due);
  else
    gather_from_candidates(w, dt, no_pairs, start, grid, pool, renumber_if_due);
  const double* inv_m = w.equal_masses ? nullptr : w.inv_m.data();
  const std::vector<int>& awake = sleep_.awake(inv_m, w.inv_m0);
  if (sleep_.sleeping() > 0) inv_m = sleep_.held_inv_mass().data();
  const bool rough = w.rough();
  for (SoftContact& c : contacts_) {
    const double wi = inv_m ? inv_m[c.i] : w.inv_m0, wj = c.j < 0 ? 0.0 : inv_m ? inv_m[c.j] : w.inv_m0;
    c.mass = 1.0 / (wi + wj);
    if (rough) c.tangent_mass = tangent_mass(wi, wj, w.k);
  }
  SoftBodies bodies{w.p.col(0).data(),
                    w.p.col(1).data(),
                    w.v.col(0).data(),
                    w.v.col(1).data(),
                    inv_m,
                    w.inv_m0,
                    sleep_.sleeping() > 0 ? awake.data() : nullptr,
                    static_cast<int>(awake.size())};
  if (w.rotation) {
    bodies.w = w.w.data(), bodies.angle = w.angle.data();
    bodies.radius = w.equal_radii ? nullptr : w.r.data(), bodies.r0 = w.r0, bodies.k = w.k, bodies.mu = w.mu;
  }
  soft_step(bodies, n, contacts_, w.g.x(), w.g.y(), dt, soft_, {w.e, v_rest}, scratch_);
  if (sleep_.enabled()) {
    sleep_.fall_asleep(contacts_, w.v.col(0).data(), w.v.col(1).data(), dt);
    if (w.rotation)  // a ball asleep is at rest: it does not turn either
      for (int i = 0; i < n; ++i)
        if (sleep_.asleep(i)) w.w(i) = 0;
    warm_entries_.clear();
    for (const SoftContact& c : contacts_)
      if (c.impulse > 0) warm_entries_.push_back({c.i, c.j, c.impulse, c.tangent_impulse});
    warm_.assign(warm_entries_);
  } else {
    // A candidate whose contact pushed nothing starts the next part from 0 (one without a contact
    // in this part was set to 0 as it was tested).
    for (size_t k = 0; k < contacts_.size(); ++k) {
      Candidate& c = candidates_[candidate_of_[k]];
      c.impulse = contacts_[k].impulse, c.tangent = contacts_[k].tangent_impulse;
    }
  }
}

void SoftResting::gather_from_candidates(const HomeWorld& w, double dt, bool no_pairs, const StartScan& start,
                                         HomeGrid& grid, ForkJoin& pool,
                                         const std::function<void()>& renumber_if_due) {
  const double reach = part_reach(w, start, dt);
  candidate_of_.clear();
  // The candidates hold while no pair can have come within reach of touching that was not within
  // reach of touching plus the skin at their build: each ball moved at most `moved` since.
  bool hold = built_reach_ >= 0;
  if (hold) {
    double moved2 = 0;
    for (int i = 0; i < w.n; ++i) {
      const double dx = w.p(i, 0) - built_at_(i, 0), dy = w.p(i, 1) - built_at_(i, 1);
      moved2 = std::max(moved2, dx * dx + dy * dy);
    }
    hold = 2 * std::sqrt(moved2) + 2 * reach <= 2 * built_reach_ + built_skin_;
  }
  if (!hold) build_candidates(w, reach, no_pairs, start, grid, pool, renumber_if_due);
  reach_speeds(w, candidates_, own_speed_, reach_speed_);
  const ContactTest test(w, reach_speed_, dt, kSoftMargin * w.rmax);
  int k = 0;
  const auto add = [&](int i, int j, double nx, double ny, double gap) {
    contacts_.push_back(warm_contact(i, j, nx, ny, gap, candidates_[k].impulse, candidates_[k].tangent));
    candidate_of_.push_back(k);
  };
  for (const int m = static_cast<int>(candidates_.size()); k < m; ++k) {
    Candidate& c = candidates_[k];
    const bool contact = c.j >= 0 ? test.pair(c.i, c.j, add) : test.wall(c.i, wall_axis(c.j), wall_side(c.j), add);
    if (!contact) c.impulse = 0, c.tangent = 0;
  }
}

// The candidates: every pair within 2 reach + margin + skin of touching (on a grid with cells that
// wide), the lower number first, and every wall within reach + margin + skin of a ball; each with
// the impulse its contact ended the last part with. The skin is left out while a ball moves so
// fast that the candidates would not hold for a few parts (the fluid's pour), where it would only
// add candidates.
void SoftResting::build_candidates(const HomeWorld& w, double reach, bool no_pairs, const StartScan& start,
                                   HomeGrid& grid, ForkJoin& pool, const std::function<void()>& renumber_if_due) {
  warm_entries_.clear();
  for (const Candidate& c : candidates_)
    if (c.impulse > 0) warm_entries_.push_back({c.i, c.j, c.impulse, c.tangent});
  warm_.assign(warm_entries_);  // a renumbering (below) re-keys it
  const double skin = reach <= 0.25 * kCandidateSkin * w.rmax ? kCandidateSkin * w.rmax : 0.0;
  const double extra = kSoftMargin * w.rmax + skin;
  candidates_.clear();
  const auto keep = [&](int i, int j) {
    const WarmStart::Entry* e = warm_.entry(i, j);
    candidates_.push_back(e ? Candidate{i, j, e->impulse, e->tangent} : Candidate{i, j, 0.0, 0.0});
  };
  if (!no_pairs) {
    grid.build(w.p, w.r, 2.0 * w.rmax + 2.0 * reach + extra, pool, false, &start.bounds);
    renumber_if_due();
    const double* px = w.p.col(0).data();
    const double* py = w.p.col(1).data();
    const int* id = grid.id();
    grid.for_each_forward_pair(0, grid.balls(), [&](int sa, int sb) {
      int a = id[sa], b = id[sb];
      if (a > b) std::swap(a, b);
      const double lim = w.radius(a) + w.radius(b) + 2.0 * reach + extra;
      const double dx = px[a] - px[b], dy = py[a] - py[b];
      if (dx * dx + dy * dy < lim * lim) keep(a, b);
    });
  }
  if (w.walls)
    for (int i = 0; i < w.n; ++i)
      for (int axis = 0; axis < 2; ++axis)
        for (int side = 0; side < 2; ++side)
          if (w.wall_gap(i, axis, side) < reach + extra) keep(i, wall_partner(axis, side));
  built_at_ = w.p;
  built_reach_ = reach;
  built_skin_ = skin;
}

void SoftResting::gather_awake(HomeWorld& w, double dt, bool no_pairs, const StartScan& start, HomeGrid& grid,
                               ForkJoin& pool, const std::function<void()>& renumber_if_due) {
  const int n = w.n;
  const double reach = part_reach(w, start, dt);
  const double margin = kSoftMargin * w.rmax;
  const auto add = [&](int i, int j, double nx, double ny, double gap) {
    const WarmStart::Entry* e = warm_.entry(i, j);
    contacts_.push_back(e ? warm_contact(i, j, nx, ny, gap, e->impulse, e->tangent) : warm_contact(i, j, nx, ny, gap, 0, 0));
  };
  // The pairs within reach of touching, the lower number first, so the warm start finds each
  // whichever cell order the grid gave it this step; tested once every ball's reach speed is known.
  near_.clear();
  const auto try_pair = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    const double lim = w.radius(a) + w.radius(b) + 2 * reach + margin;
    const double dx = w.p(a, 0) - w.p(b, 0), dy = w.p(a, 1) - w.p(b, 1);
    if (dx * dx + dy * dy < lim * lim) near_.push_back({a, b, 0.0, 0.0});
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
  reach_speeds(w, near_, own_speed_, reach_speed_);
  const ContactTest test(w, reach_speed_, dt, margin);
  for (const Candidate& c : near_) test.pair(c.i, c.j, add);
  if (w.walls)
    for (int i = 0; i < n; ++i)
      if (sleeping == 0 || !asleep(i)) test.walls(i, add);
  if (sleeping > 0) {
    // A ball woken now gains the contacts it had none of while it slept.
    sleep_.wake_touched(contacts_, w.v.col(0).data(), w.v.col(1).data());
    for (int i : sleep_.woken()) {
      if (!no_pairs)
        grid.for_each_near(i, [&](int j) {
          const SleepIslands::State sj = sleep_.state(j);
          if (sj == SleepIslands::kAsleep || (sj == SleepIslands::kWoken && j > i))
            test.pair(std::min(i, j), std::max(i, j), add);
        });
      if (w.walls) test.walls(i, add);
    }
    sleep_.finish_waking();
  }
}

}  // namespace ballbench

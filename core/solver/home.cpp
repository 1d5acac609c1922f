#include "solver/home.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"
#include "fork_join.h"
#include "solver/contact.h"
#include "solver/home_grid.h"
#include "solver/home_world.h"
#include "solver/neighbour_list.h"
#include "solver/home_soft.h"
#include "solver/rough_impact.h"
#include "solver/warm_start.h"

namespace ballbench {
namespace {

// The list screen's time for a pair that touches at the start of the step (see first_pair_events).
constexpr double kTouching = -1;
// tmp_.first_j: the ball's first pair event is left to next_event (see first_pair_events).
constexpr int kAsk = -2;
// Sweeps the cluster solve may take to bring every contact within the velocity tolerance; a
// cluster that needs more is left to the event loop, which finishes the job one event at a time.
constexpr int kClusterIterations = 200;
// Fraction of its gap a speculative contact may close in one step (see add_contact).
constexpr double kSpeculativeFraction = 0.5;
// From this many balls the per-ball loops run on every core. A hand-over costs ~7 us and a step
// has about a dozen: two threads lose below 10^5 balls, break even there and win at 10^6
// (ballbench_home_benchmark's home/threads/; PERFORMANCE.md, "Threads").
constexpr int kParallelBalls = 100'000;
// Every this many steps the balls are renumbered in the grid's cell order, so that neighbours in
// space are neighbours in memory (home/reorder/ in ballbench_home_benchmark; PERFORMANCE.md,
// "Renumbering"). Balls drift by under a cell per step, so the order stays good for a while; read()
// maps back to the scene's order. Only from kReorderBalls balls, where it pays: renumbering
// changes the order of the contact solve, and so the trajectory of every scene in tests/ and the
// regression suite, all far below 10^4 balls.
constexpr int kReorderSteps = 16;
constexpr int kReorderBalls = 10'000;

int reorder_steps(int n, int requested) {
  if (requested >= 0) return requested;
  return n >= kReorderBalls ? kReorderSteps : 0;
}

// The shortcuts this scene allows among those `allow` permits.
HomeShortcuts shortcuts(const Scene& scene, const HomeShortcuts& allow, double rest_velocity) {
  const SceneFeatures f = scene.features();
  HomeShortcuts s;
  s.no_gravity = allow.no_gravity && !f.gravity;
  s.no_walls = allow.no_walls && !f.walls;
  s.equal_radii = allow.equal_radii && f.equal_radii && scene.n() > 0;
  s.equal_masses = allow.equal_masses && f.equal_masses && scene.n() > 0;
  s.no_pairs = allow.no_pairs && scene.n() < 2;
  // Restitution 1 with a resting speed of 0 (no gravity, rest_velocity left to its default or 0):
  // no impact is resting contact and no contact is speculative, so the contact pass would only hold
  // touching pairs that do not approach, which it leaves as they are (every impact is the event
  // loop's: make_contact).
  const bool no_rest = rest_velocity == 0 || (rest_velocity < 0 && !f.gravity);
  s.elastic = allow.elastic && f.elastic && no_rest;
  return s;
}

// Where a ball that was at x with velocity v at its own clock t_own is at time t (one coordinate).
// Every advance along a line (the event loop's, the end of a step, read()'s end positions) is this
// one expression, so read() gives exactly what the next step's start_pass will compute.
inline double on_line(double x, double v, double t, double t_own) { return x + v * (t - t_own); }

// A pair the list screen found approaching, and when it meets (kTouching: it touches now).
struct Approach {
  int a, b;
  double t;
};

// A contact of the start-of-step contact pass (contact_pass) and of the cluster solves. With
// friction it also holds a tangential impulse, bounded by the friction coefficient times the normal
// impulse (Coulomb's law as sequential impulses: Catto, GDC 2005), in the tangent (-n_y, n_x).
struct PassContact : Contact {
  double target;  // least normal velocity wanted after the solve (m/s)
  bool moved;     // an impulse was applied (warm start or solve): both velocities may have changed
  double tangent_impulse = 0;  // accumulated friction impulse (N s); 0 without friction
  double tangent_mass = 0;     // effective mass along the tangent (rough_impact.h; kg)
};

// The step's scratch: per-step and per-part buffers, each with one job, sized once and reused
// every step (no allocation once warm). Nothing here outlives the step that fills it, except as
// the capacity it keeps.
struct StepScratch {
  // Per part of the thread team (ForkJoin), filled in parallel, read in part order.
  std::vector<std::vector<std::pair<int, int>>> pair_hits;  // ball pairs within contact reach
  std::vector<std::vector<PassContact>> pair_contacts;      // their contacts (screen_slots)
  std::vector<std::vector<int>> wall_hits;                  // balls within contact reach of a wall
  std::vector<std::vector<PredictedEvent>> first_events;    // the active balls' events at the start of drift
  std::vector<StartScan> start_parts;                       // each part's share of start_pass
  std::vector<std::vector<Approach>> approaches;            // listed: the list screen's approaching pairs
  // The contact pass and the cluster solves.
  std::vector<PassContact> contacts;
  std::vector<int> live;            // contacts a sweep after the first still visits (see solve_contacts)
  std::vector<uint8_t> degree;      // per ball: its contacts in the solve, saturating at 2; 0 between solves
  std::vector<int> cluster;         // the balls of the resting cluster being solved
  std::vector<uint8_t> in_cluster;  // per ball: 1 while in that cluster; 0 between clusters
  std::vector<WarmStart::Entry> warm_entries;  // for rebuilding the warm start
  // The event loop.
  std::vector<PredictedEvent> queue;  // a min-heap on t, see push_event
  std::vector<double> first_t;        // listed: each ball's first pair event at the start of drift (kNever: none)
  std::vector<int> first_j;           // listed: its partner (-1: none, kAsk: next_event decides)
  Eigen::MatrixX2d rebuild_at;        // listed: positions at a rebuild in mid-step
  // Renumbering (from kReorderBalls balls): one column of the state in the new order, and the
  // slots whose permutation cycle is done.
  std::vector<double> column;
  std::vector<uint8_t> placed;

  explicit StepScratch(int parts)
      : pair_hits(parts), pair_contacts(parts), wall_hits(parts), first_events(parts), approaches(parts) {}
};

class Home final : public Engine {
 public:
  Home(const Scene& scene, HomeSettings s)
      : s_(s),
        sc_(shortcuts(scene, s.allow, s.rest_velocity)),
        reorder_(reorder_steps(scene.n(), s.reorder_steps)),
        w_(scene, sc_.equal_radii, sc_.equal_masses),
        listed_(sc_.elastic && !sc_.no_pairs),
        t_local_(w_.n),
        count_(w_.n, 0),
        active_(w_.n, 0),
        pool_(ForkJoin::threads_for(w_.n, kParallelBalls, s.threads)),
        tmp_(pool_.parts()),
        extent_(pool_.parts()),
        soft_(s.resting == "soft" && scene.features().gravity) {
    if (listed_) tmp_.first_t.assign(w_.n, kNever), tmp_.first_j.assign(w_.n, -1), near_wall_mark_.assign(w_.n, 0);
    if (!soft_ && !sc_.elastic) tmp_.degree.assign(w_.n, 0), tmp_.in_cluster.assign(w_.n, 0);  // contact solves
    if (soft_) soft_path_ = SoftResting(s, w_.n);
  }

  void step(double dt) override {
    ++steps_;
    t_ += dt;
    dt_ = dt;
    v_rest_ = s_.rest_velocity >= 0 ? s_.rest_velocity : 2.0 * w_.g.norm() * dt;
    if (soft_) return soft_path_.step(w_, dt, v_rest_, sc_.no_pairs, grid_, pool_, [&] { renumber_if_due(); });
    // Symplectic Euler: velocity first (thesis eq. 3, in the bowl program's order), then the
    // positions move along straight lines for the whole step, which the event loop follows exactly.
    // Without a neighbour list one parallel pass kicks and measures what the grid and the wall
    // screen need (start_pass); the list needs neither (and has gravity only if rest_velocity is 0).
    walls_screened_ = false;
    if (!listed_) {
      start_pass();
    } else if (!sc_.no_gravity) {
      w_.v.col(0).array() += w_.g.x() * dt;
      w_.v.col(1).array() += w_.g.y() * dt;
    }
    build_broad_phase(dt);
    v_tol_ = velocity_tolerance();
    contact_pass();
    drift();
  }

  // In the scene's order: a plain copy until the balls are first renumbered, then a gather through
  // the scene -> ball map, which writes the output front to back (scattering the writes through a
  // ball -> scene map instead cost 10-15% of a harness step at 10^5 balls).
  // A step whose final advance is left to the next start_pass (unfinished_dt_) gets its end
  // positions here, by finish_step's expressions: the same numbers.
  void read(State& out) const override {
    out.t = t_;
    out.resize(w_.n, w_.rotation);
    const double end = unfinished_dt_;
    const double* __restrict tl = t_local_.data();
    // The angles are brought to the step's end by drift itself (end_angles).
    if (w_.rotation)
      for (int k = 0; k < w_.n; ++k) {
        const int i = renumbered_ ? w_.ball_of[k] : k;
        out.w(k) = w_.w(i), out.angle(k) = w_.angle(i);
      }
    if (!renumbered_ && end == 0) {
      out.pos = w_.p, out.vel = w_.v;
      return;
    }
    // A gather through the renumbering (random reads): on the step's threads, each part over its
    // own range of the scene's order.
    const int* at = renumbered_ ? w_.ball_of.data() : nullptr;
    const int parts = pool_.parts();
    pool_.run([&](int part) {
      const long b = ForkJoin::range_begin(w_.n, part, parts), e = ForkJoin::range_begin(w_.n, part + 1, parts);
      for (int c = 0; c < 2; ++c) {
        const double* __restrict p = w_.p.col(c).data();
        const double* __restrict v = w_.v.col(c).data();
        double* __restrict op = out.pos.col(c).data();
        double* __restrict ov = out.vel.col(c).data();
        if (end == 0)
          for (long k = b; k < e; ++k) op[k] = p[at[k]], ov[k] = v[at[k]];
        else
          for (long k = b; k < e; ++k) {
            const long i = at ? at[k] : k;
            op[k] = on_line(p[i], v[i], end, tl[i]), ov[k] = v[i];
          }
      }
    });
  }

  nlohmann::json settings() const override {
    return {{"contact_iterations", s_.contact_iterations},
            {"rest_velocity", s_.rest_velocity},
            {"contact_slop", s_.contact_slop},
            {"max_events_per_ball", s_.max_events_per_ball},
            {"resting", s_.resting},
            {"substeps", s_.soft.substeps},
            {"substep_iterations", s_.soft.substep_iterations},
            {"relax_iterations", s_.soft.relax_iterations},
            {"max_stride", s_.max_stride},
            {"max_parts", s_.max_parts},
            {"contact_hertz", s_.soft.contact_hertz},
            {"damping_ratio", s_.soft.damping_ratio},
            {"push_speed", s_.soft.push_speed},
            {"sleep_speed", s_.sleep_speed},
            {"sleep_time", s_.sleep_time}};
  }

 private:
  // Grid over the positions at the start of the step, with cells wide enough that any two balls
  // which can touch during the rest of the step are in adjacent cells.
  // `mid_step`: a
  // rebuild within the step (rebuild_mid_step), which must not renumber the balls.
  // With a neighbour list (elastic scenes) the list is kept while it covers the step, rebuilt when
  // it does not (in mid-step, rebuild_mid_step rebuilds it itself).
  void build_broad_phase(double horizon, bool mid_step = false) {
    if (listed_) {
      if (!mid_step && !list_covers(horizon)) rebuild_list(horizon, true, w_.p, start_speed());
      return;
    }
    // At the start of a step start_pass has measured the speeds and bounds; in mid-step they are taken afresh.
    vbound_ = (mid_step ? max_speed() : std::sqrt(start_.speed2)) * kSpeedMargin;
    if (sc_.no_pairs) return;
    grid_.build(w_.p, w_.r, 2.0 * w_.rmax + 2.0 * vbound_ * horizon, pool_, false, mid_step ? nullptr : &start_.bounds);
    // A renumbering moves the balls: the wall screen start_pass did is done again after it.
    if (!mid_step && renumber_if_due()) walls_screened_ = false;
  }

  // The first pass over the balls without a neighbour list, in parallel: the end of the last step
  // (each ball from its own clock to the step's end, as finish_step does with a list), the kick
  // (symplectic Euler's velocity update), then the largest speed and the positions' bounds for the
  // grid, and the wall screen (screen_walls) unless a renumbering is due: one read of the state
  // instead of five.
  void start_pass() {
    const int parts = pool_.parts();
    const bool screen = w_.walls && !sc_.no_walls && !renumber_due();
    const double reach = v_rest_ * dt_;
    tmp_.start_parts.resize(parts);
    pool_.run([&](int p) {
      tmp_.wall_hits[p].clear();
      const int b = static_cast<int>(ForkJoin::range_begin(w_.n, p, parts));
      const int e = static_cast<int>(ForkJoin::range_begin(w_.n, p + 1, parts));
      std::vector<int>& near = tmp_.wall_hits[p];
      tmp_.start_parts[p] = screen ? scan<Scan{.start = true, .screen = true}>(b, e, reach, near)
                               : scan<Scan{.start = true}>(b, e, reach, near);
    });
    unfinished_dt_ = 0;
    start_ = StartScan{};
    for (const StartScan& q : tmp_.start_parts) start_.merge(q);
    walls_screened_ = screen;
  }

  // Renumbering in cell order (reorder_by_cell) right after a grid's build at the start of a step:
  // at the first, then when reorder_ steps have passed since the last. Returns whether it did.
  bool renumber_due() const { return reorder_ > 0 && !(renumbered_ && steps_ - renumbered_at_ < reorder_); }
  bool renumber_if_due() {
    if (!renumber_due() || grid_.balls() != w_.n) return false;
    reorder_by_cell();
    renumbered_ = true, renumbered_at_ = steps_;
    return true;
  }

  double max_speed() const { return w_.n > 0 ? std::sqrt(w_.v.rowwise().squaredNorm().maxCoeff()) : 0.0; }

  // Every ball stays within half the skin of where it was at the list's build over the next
  // `horizon` at its present velocity (its path is straight, its distance from there convex, so the
  // ends decide). A collision that changes a velocity is checked again (beyond_skin). The largest
  // displacement plus the largest speed bounds every ball's own sum; the last step's final advance
  // measured both (extent_), and nothing has moved since.
  bool list_covers(double horizon) const {
    if (half_skin_ < 0) return false;  // no list yet
    double moved2 = 0;
    for (const auto& [m, v] : extent_) moved2 = std::max(moved2, m);
    return std::sqrt(moved2) + start_speed() * horizon <= half_skin_;
  }

  // The largest speed at the start of a step, as the last step's final advance measured it (before
  // the first step, when nothing has measured it, counted afresh).
  double start_speed() const {
    if (half_skin_ < 0) return max_speed();
    double speed2 = 0;
    for (const auto& e : extent_) speed2 = std::max(speed2, e.second);
    return std::sqrt(speed2);
  }

  bool beyond_skin(int i, double t) const {
    return (w_.p.row(i) - built_at_.row(i)).norm() + w_.v.row(i).norm() * (dt_ - t) > half_skin_;
  }

  // A fresh neighbour list from the positions now: a grid with cells of 2 r_max + skin, its
  // adjacent pairs closer than r_i + r_j + skin kept. The skin lets the fastest ball move for
  // list_steps steps (and at least over `horizon`). Renumbering in cell order, when due, happens
  // here, on this grid, so the list is built in the new numbers.
  // `at`: every ball's position now (w_.p at the start of a step; in mid-step, where each ball's line
  // has taken it, the balls themselves left where they are, so a rebuild changes no trajectory).
  // `vmax`: the largest speed now.
  void rebuild_list(double horizon, bool may_renumber, const Eigen::MatrixX2d& at, double vmax) {
    // The relative margin keeps round-off in the positions from failing the check at once.
    half_skin_ = vmax * std::max(s_.list_steps * dt_, horizon) * (1.0 + 1e-9);
    for (int i : near_wall_) near_wall_mark_[i] = 0;  // in the numbers before a renumbering
    // The list is built from the grid's copy of the positions.
    grid_.build(at, w_.r, 2.0 * w_.rmax + 2.0 * half_skin_, pool_, true);
    // Renumbering (at the start of a step only, where `at` is w_.p) leaves the grid's slot -> ball map
    // the identity and w_.p in the new order: the list and built_at_ then use the new numbers.
    if (may_renumber) renumber_if_due();
    list_.build(grid_, sc_.equal_radii, w_.r0, 2.0 * half_skin_, pool_);
    built_at_ = at;
    // A ball farther than 2 half_skin from every wall now starts each step the list covers within
    // half_skin - |v| dt of here (list_covers), so more than half_skin + |v| dt from every wall: it
    // cannot reach one before a collision changes its course (and then it is predicted anyway).
    // Only the grid's edge cells can hold such a ball: the rest are not looked at.
    near_wall_.clear();
    if (!w_.walls) return;
    const double reach = w_.rmax + 2.0 * half_skin_;
    const int* id = grid_.id();
    grid_.for_each_slot_beyond(w_.box.min(0) + reach, w_.box.max(0) - reach, w_.box.min(1) + reach, w_.box.max(1) - reach,
                               [&](int s) {
                                 const int i = id[s];
                                 const auto [gx0, gx1, gy0, gy1] = wall_gaps(built_at_(i, 0), built_at_(i, 1), w_.radius(i));
                                 if (std::min(std::min(gx0, gx1), std::min(gy0, gy1)) <= 2.0 * half_skin_)
                                   near_wall_.push_back(i);
                               });
    for (int i : near_wall_) near_wall_mark_[i] = 1;
  }


  // One branch on a flag fixed at construction; the hot pair screen is compiled per case instead.

  // A gap below this counts as touching: the contact slop times the radius sum (of a pair, or of a
  // ball alone at a wall). The hot kernels (scan_range, screen_slots) keep the slop in a local and
  // apply the same product.
  double touching_gap(double radius_sum) const { return s_.contact_slop * radius_sum; }
  double touch_pair(int i, int j) const { return touching_gap(w_.radius(i) + w_.radius(j)); }
  double touch_wall(int i) const { return touching_gap(w_.radius(i)); }


  double relative_normal_velocity(int i, int j, double nx, double ny) const {
    double wx = w_.v(i, 0), wy = w_.v(i, 1);
    if (j >= 0) wx -= w_.v(j, 0), wy -= w_.v(j, 1);
    return wx * nx + wy * ny;
  }

  void apply_impulse(int i, int j, double nx, double ny, double J) {
    const double mi = w_.inv_mass(i);
    w_.v(i, 0) += J * mi * nx, w_.v(i, 1) += J * mi * ny;
    if (j >= 0) {
      const double mj = w_.inv_mass(j);
      w_.v(j, 0) -= J * mj * nx, w_.v(j, 1) -= J * mj * ny;
    }
  }

  // The slip of contact (i, j) of normal n: the velocity of i's contact point relative to j's
  // along the tangent (-n_y, n_x) (rough_impact.h). Rotating scenes only.
  double slip(int i, int j, double nx, double ny) const {
    double wx = w_.v(i, 0), wy = w_.v(i, 1), spin = w_.w(i) * w_.radius(i);
    if (j >= 0) wx -= w_.v(j, 0), wy -= w_.v(j, 1), spin += w_.w(j) * w_.radius(j);
    return wy * nx - wx * ny - spin;
  }

  // A tangential impulse Jt along (-n_y, n_x) at the contact on i, its opposite on j: it moves and
  // turns both (rough_impact.h: w -= r Jt / I, I = k m r^2).
  void apply_tangent_impulse(int i, int j, double nx, double ny, double Jt) {
    const double mi = w_.inv_mass(i) * Jt;
    w_.v(i, 0) -= mi * ny, w_.v(i, 1) += mi * nx;
    w_.w(i) -= mi / (w_.k * w_.radius(i));
    if (j >= 0) {
      const double mj = w_.inv_mass(j) * Jt;
      w_.v(j, 0) += mj * ny, w_.v(j, 1) -= mj * nx;
      w_.w(j) -= mj / (w_.k * w_.radius(j));
    }
  }

  // The friction update of contact c after its normal one (Catto 2005): the tangential impulse that
  // stops the slip, clamped to the friction cone |Jt| <= mu Jn of this sweep's normal impulse.
  // Returns how much it changed the slip (m/s).
  double solve_friction(PassContact& c) {
    const double bound = w_.mu * c.impulse, old = c.tangent_impulse;
    c.tangent_impulse = std::clamp(old - slip(c.i, c.j, c.nx, c.ny) * c.tangent_mass, -bound, bound);
    if (c.tangent_impulse == old) return 0.0;
    apply_tangent_impulse(c.i, c.j, c.nx, c.ny, c.tangent_impulse - old);
    c.moved = true;
    return std::abs(c.tangent_impulse - old) / c.tangent_mass;
  }

  // The velocity constraint of one contact, for the sequential-impulse solve:
  // - approaching faster than v_rest, touching or not: an impact, left to the exact event loop (a
  //   touching pair that approaches is collided at once there, pair by pair, each impact losing
  //   energy to restitution). Bounce targets (-e vn) inside the solve cannot all be met in a jammed
  //   cluster, and then the cluster solves of one step feed on each other (seed-bowl's pile, in
  //   some ball orders, escalates to ~10^5 m/s within one step: HomeOnTheBowl.HoldsInAnyBallOrder);
  // - touching and slower: resting contact, target 0 (do not approach). Not a small separation:
  //   a jammed chain (seed-bowl's row of 20 balls spans its 10 m box exactly, wall to wall) cannot
  //   separate everywhere at once, and an infeasible target keeps the solve from converging. What
  //   the solve leaves over is below the velocity tolerance, which predict ignores. A small
  //   overlap is closed within the step when `close_overlap`, but never faster than v_rest: the
  //   push is kinetic energy put in, and an overlap the scene starts with (allow_overlap, seed-box)
  //   pushed apart at overlap / dt gained energy as 1/dt (measured: 18% at dt 0.0025 on
  //   seed-box). Without gravity v_rest = 0 and overlapping balls part by their own motion, as in
  //   `exact` (an approaching overlapping pair is an impact at once, in predict);
  // - not touching: a speculative contact (Catto, "Speculative Contacts", 2013): the pair may close
  //   part of its gap within `horizon` but not overlap, target -f gap / horizon (f < 1, so that
  //   it lands as touching over a few steps instead of as an impact event at the end of this one);
  // make_contact writes the contact into `c` from the relative normal velocity vn, or returns false
  // (fast); it reads the state only, so the pair screen's parts call it too.
  void add_contact(int i, int j, double nx, double ny, double gap, double touch, double horizon, bool close_overlap) {
    PassContact c;
    if (make_contact(i, j, nx, ny, relative_normal_velocity(i, j, nx, ny), gap, touch, horizon, close_overlap, c))
      tmp_.contacts.push_back(c);
  }
  bool make_contact(int i, int j, double nx, double ny, double vn, double gap, double touch, double horizon,
                    bool close_overlap, PassContact& c) const {
    const bool touching = gap < touch, fast = -vn > v_rest_;
    if (fast) return false;
    double target;
    if (touching) target = close_overlap ? std::min(std::max(-gap, 0.0) / horizon, v_rest_) : 0.0;
    else target = -kSpeculativeFraction * gap / horizon;
    // Kept even when satisfied now: an impulse on a neighbour can push the pair together.
    const double inv_j = j >= 0 ? w_.inv_mass(j) : 0.0, eff = 1.0 / (w_.inv_mass(i) + inv_j);
    c = {{i, j, nx, ny, eff, 0.0}, target, false};
    if (w_.rough()) c.tangent_mass = tangent_mass(w_.inv_mass(i), inv_j, w_.k);
    return true;
  }

  // Warm start (Catto 2005): the impulse contact c ended the last step with, if it had one. Only
  // looked up: the impulses are applied afterwards, in the contacts' order.
  void find_warm_impulse(PassContact& c) const {
    if (const WarmStart::Entry* e = warm_.entry(c.i, c.j)) c.impulse = e->impulse, c.tangent_impulse = e->tangent, c.moved = true;
  }

  // Adds a contact for every wall within max(touch, reach) of ball i.
  void add_wall_contacts(int i, double reach, double horizon, bool close_overlap) {
    if (!w_.walls) return;
    for (int axis = 0; axis < 2; ++axis)
      for (int side = 0; side < 2; ++side) {
        const double gap = w_.wall_gap(i, axis, side), touch = touch_wall(i);
        if (gap >= std::max(touch, reach)) continue;
        const double sign = side == 0 ? 1.0 : -1.0;  // the normal points into the box
        add_contact(i, wall_partner(axis, side), axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, gap, touch, horizon,
                    close_overlap);
      }
  }

  // Adds the contact of pair (i, j) if their gap is below max(touch, reach); returns whether it was.
  bool add_pair_contact(int i, int j, double reach, double horizon, bool close_overlap) {
    const double dx = w_.p(i, 0) - w_.p(j, 0), dy = w_.p(i, 1) - w_.p(j, 1);
    const double rs = w_.radius(i) + w_.radius(j), limit = rs + std::max(touch_pair(i, j), reach);
    const double d2 = dx * dx + dy * dy;
    if (d2 >= limit * limit || d2 == 0) return false;  // squared first: most candidates are far
    PassContact c;
    if (make_pair_contact(i, j, dx, dy, d2, w_.v(i, 0) - w_.v(j, 0), w_.v(i, 1) - w_.v(j, 1), rs, horizon, close_overlap, c))
      tmp_.contacts.push_back(c);
    return true;
  }

  // make_contact for pair (i, j) at separation (dx, dy), |d|^2 = d2 > 0, relative velocity (wx, wy)
  // and radius sum rs: add_pair_contact's and the pair screen's.
  bool make_pair_contact(int i, int j, double dx, double dy, double d2, double wx, double wy, double rs,
                         double horizon, bool close_overlap, PassContact& c) const {
    const double d = std::sqrt(d2), nx = dx / d, ny = dy / d;
    return make_contact(i, j, nx, ny, wx * nx + wy * ny, d - rs, touching_gap(rs), horizon, close_overlap, c);
  }

  // Sequential impulses (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005): sweeps
  // over tmp_.contacts until every contact is within `tolerance` of its target or `sweeps` ran.
  // Returns the largest approach beyond a target left after the last sweep (m/s).
  //
  // A contact that shares no ball with another (isolated) sees velocities only it changes, so its
  // first update solves it: it ends at its target with a positive impulse (the update's algebra
  // gives the relative normal velocity exactly the target, up to round-off), or with none and
  // separating faster. Later sweeps skip it. Visited again, it would only move by round-off (an
  // ulp-level walk of its impulse), far below any tolerance, so it cannot decide whether another
  // sweep is needed. In a falling gas most contacts are isolated pairs, close but parting (10^6
  // bowl balls: ~25 000 contacts, half of them such).
  double solve_contacts(int sweeps, double tolerance) {
    double worst = kNever;  // largest violation seen in the last sweep (m/s)
    const bool rough = w_.rough();
    // Normal first, then friction against the normal impulse just found: for disks the two do
    // not couple (the contact point lies on the normal), so an isolated contact is still solved
    // by its first update.
    const auto update = [&](PassContact& c) {
      const double vn = relative_normal_velocity(c.i, c.j, c.nx, c.ny);
      const double old = c.impulse;
      c.impulse = std::max(0.0, old + (c.target - vn) * c.mass);
      apply_impulse(c.i, c.j, c.nx, c.ny, c.impulse - old);
      c.moved |= c.impulse != old;
      if (c.impulse > 0 || vn < c.target) worst = std::max(worst, std::abs(c.target - vn));
      if (rough) worst = std::max(worst, solve_friction(c));
    };
    // tmp_.live: the contacts a sweep after the first visits (all but the isolated ones).
    tmp_.live.clear();
    if (sweeps <= 0) {
      for (size_t k = 0; k < tmp_.contacts.size(); ++k) tmp_.live.push_back(static_cast<int>(k));
    } else {
      // Balls' contact counts (saturating at 2), all zero between solves and left so.
      uint8_t* degree = tmp_.degree.data();
      const auto bump = [&](int b) { degree[b] = static_cast<uint8_t>(std::min(degree[b] + 1, 2)); };
      for (const PassContact& c : tmp_.contacts) {
        bump(c.i);
        if (c.j >= 0) bump(c.j);
      }
      worst = 0;
      for (size_t k = 0; k < tmp_.contacts.size(); ++k) {
        PassContact& c = tmp_.contacts[k];
        const bool isolated = degree[c.i] == 1 && (c.j < 0 || degree[c.j] == 1);
        update(c);
        if (!isolated) tmp_.live.push_back(static_cast<int>(k));
      }
      for (const PassContact& c : tmp_.contacts) {
        degree[c.i] = 0;
        if (c.j >= 0) degree[c.j] = 0;
      }
    }
    for (int it = 1; it < sweeps && worst > tolerance; ++it) {
      worst = 0;
      for (int k : tmp_.live) update(tmp_.contacts[k]);
    }
    if (worst <= tolerance) return 0.0;
    // The isolated contacts were solved by their one update.
    double left = 0;
    for (int k : tmp_.live) {
      const PassContact& c = tmp_.contacts[k];
      left = std::max(left, c.target - relative_normal_velocity(c.i, c.j, c.nx, c.ny));
    }
    return left;
  }

  // Resting contact at the start of the step: every contact within reach of resting speeds
  // (v_rest dt) is solved together, so a pile settles in one pass instead of through a cascade of
  // zero-time events.
  //
  // Warm started (Catto 2005): each contact begins with the impulse it ended the last step with, so
  // a pile at rest needs a sweep or two instead of as many as it is high.
  //
  // The same sweep screens the drift (see screen_pairs): a ball is `active` when it may have an
  // event this step; only active balls are predicted, the rest just move dt along their lines.
  void contact_pass() {
    tmp_.contacts.clear();
    const double reach = v_rest_ * dt_;
    if (sc_.no_walls) {
      std::fill(active_.begin(), active_.end(), 0);
    } else if (listed_) {
      // Only balls near a wall when the list was built can reach one before it expires.
      std::fill(active_.begin(), active_.end(), 0);
      const double k = dt_ * (1.0 + 1e-9);
      for (int i : near_wall_) active_[i] = reaches_wall(w_.p(i, 0), w_.p(i, 1), w_.v(i, 0), w_.v(i, 1), w_.radius(i), k);
    } else {
      if (!walls_screened_) screen_walls(reach);
      for (const auto& near : tmp_.wall_hits)
        for (int i : near) add_wall_contacts(i, reach, dt_, true);
    }
    const size_t wall_contacts = tmp_.contacts.size();
    if (!sc_.no_pairs) {
      // With pairs, the elastic shortcut always has its neighbour list (listed_), and no contacts.
      if (listed_) {
        sc_.equal_radii ? screen_list<true>() : screen_list<false>();
      } else {
        sc_.equal_radii ? screen_pairs<true>(reach) : screen_pairs<false>(reach);
        for (const auto& found : tmp_.pair_contacts) tmp_.contacts.insert(tmp_.contacts.end(), found.begin(), found.end());
      }
    }
    if (sc_.elastic) return;  // no contacts were listed: nothing to solve or remember
    // The pair contacts found their warm-start impulses in the screen.
    for (size_t k = 0; k < wall_contacts; ++k) find_warm_impulse(tmp_.contacts[k]);
    for (const PassContact& c : tmp_.contacts)
      if (c.moved) {
        apply_impulse(c.i, c.j, c.nx, c.ny, c.impulse);
        if (c.tangent_impulse != 0) apply_tangent_impulse(c.i, c.j, c.nx, c.ny, c.tangent_impulse);
      }
    solve_contacts(s_.contact_iterations, 0.5 * v_tol_);
    // A contact that moved its balls changed velocities the screen could not know: predict both.
    // One that applied nothing (most, in a gas: close but parting) leaves them to the screen, which
    // saw their velocities as they still are (a partner that changed is predicted, and finds them).
    for (const PassContact& c : tmp_.contacts)
      if (c.moved) {
        active_[c.i] = 1;
        if (c.j >= 0) active_[c.j] = 1;
      }
    tmp_.warm_entries.clear();
    for (const PassContact& c : tmp_.contacts)
      if (c.impulse > 0) tmp_.warm_entries.push_back({c.i, c.j, c.impulse, c.tangent_impulse});
    warm_.assign(tmp_.warm_entries);
  }

  // Per ball, in parallel: `active` if it can reach the wall it moves towards within the step
  // (predict's test max(gap, 0) / |v| <= dt, as gap <= |v| dt with a relative margin far above
  // round-off, so it never says no where predict would say yes), and listed in tmp_.wall_hits, in
  // ball order, if a wall is within contact reach (add_wall_contacts' test, the same expressions).
  void screen_walls(double reach) {
    const int parts = pool_.parts();
    pool_.run([&](int p) {
      tmp_.wall_hits[p].clear();
      const int b = static_cast<int>(ForkJoin::range_begin(w_.n, p, parts));
      const int e = static_cast<int>(ForkJoin::range_begin(w_.n, p + 1, parts));
      if (sc_.elastic)
        scan<Scan{.contacts = false, .screen = true}>(b, e, reach, tmp_.wall_hits[p]);
      else
        scan<Scan{.screen = true}>(b, e, reach, tmp_.wall_hits[p]);
    });
  }

  // Can a ball with these gaps to the four walls (min x, max x, min y, max y) reach the one it moves
  // towards within k = dt (1 + 1e-9)? Bitwise, no ternaries: the direction of motion is a coin toss
  // per ball, and the compiler turned the selects into branches once nothing else needed both gaps.
  static bool reaches_wall(double gx0, double gx1, double gy0, double gy1, double vx, double vy, double k) {
    const double kx = std::abs(vx) * k, ky = std::abs(vy) * k;
    const bool left = vx < 0, down = vy < 0;
    return (left & (gx0 <= kx)) | (!left & (gx1 <= kx)) | (down & (gy0 <= ky)) | (!down & (gy1 <= ky));
  }
  bool reaches_wall(double x, double y, double vx, double vy, double r, double k) const {
    const auto [gx0, gx1, gy0, gy1] = wall_gaps(x, y, r);
    return reaches_wall(gx0, gx1, gy0, gy1, vx, vy, k);
  }
  // Gaps (m) between a ball at (x, y) of radius r and the walls: min x, max x, min y, max y.
  std::array<double, 4> wall_gaps(double x, double y, double r) const {
    return {x - r - w_.box.min(0), w_.box.max(0) - r - x, y - r - w_.box.min(1), w_.box.max(1) - r - y};
  }

  // What a pass of scan_range over balls does; each set is its own compiled loop.
  struct Scan {
    bool equal_radii = false;  // every ball has radius w_.r0 (scan sets it from the shortcut)
    // A contact pass follows: a ball touching a wall is active and listed. False for the elastic
    // shortcut: no contact pass, so touching a wall is no reason to be predicted and no ball is
    // listed; an approach within the step still is.
    bool contacts = true;
    // start_pass: each ball is first brought to the end of the last step (if unfinished) and
    // kicked, and the speeds and positions are returned (else an empty StartScan).
    bool start = false;
    bool screen = false;  // the wall screen (screen_walls)
  };
  template <Scan kScan>
  StartScan scan(int b, int e, double reach, std::vector<int>& near) {
    constexpr Scan equal{.equal_radii = true, .contacts = kScan.contacts, .start = kScan.start, .screen = kScan.screen};
    return sc_.equal_radii ? scan_range<equal>(b, e, reach, near) : scan_range<kScan>(b, e, reach, near);
  }
  // Balls [b, e), as kScan says.
  template <Scan kScan>
  StartScan scan_range(int b, int e, double reach, std::vector<int>& near) {
    constexpr bool kEqualRadii = kScan.equal_radii, kContacts = kScan.contacts, kStart = kScan.start,
                   kScreen = kScan.screen;
    const double k = dt_ * (1.0 + 1e-9), slop = s_.contact_slop;
    double* __restrict x = w_.p.col(0).data();
    double* __restrict y = w_.p.col(1).data();
    double* __restrict tl = t_local_.data();
    const double end = unfinished_dt_;
    double* __restrict vx = w_.v.col(0).data();
    double* __restrict vy = w_.v.col(1).data();
    const double* __restrict rad = w_.r.data();
    uint8_t* __restrict active = active_.data();
    const double x0 = w_.box.min(0), x1 = w_.box.max(0), y0 = w_.box.min(1), y1 = w_.box.max(1), r0 = w_.r0;
    if (kScreen && !w_.walls) {  // open space without the no-walls shortcut: nothing reaches a wall
      std::fill(active + b, active + e, 0);
      if (!kStart) return {};
    }
    const bool kick = kStart && !sc_.no_gravity;
    const double gx = w_.g.x() * dt_, gy = w_.g.y() * dt_;
    StartScan q;
    for (int i = b; i < e; ++i) {
      if constexpr (kStart) {
        if (end > 0) {  // as finish_step
          x[i] = on_line(x[i], vx[i], end, tl[i]), y[i] = on_line(y[i], vy[i], end, tl[i]);
          tl[i] = 0;
        }
        if (kick) vx[i] += gx, vy[i] += gy;  // as the Eigen kick: v + g dt, each component
        q.add(x[i], y[i], vx[i] * vx[i] + vy[i] * vy[i]);
      }
      if (!kScreen || !w_.walls) continue;
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

  // One sweep over every pair of balls in adjacent cells, in cell order, in parallel
  // over fixed runs of slots. It makes (a) the contacts of the pairs within contact reach
  // (add_pair_contact's, with their warm-start impulses), in the order the contact
  // pass has always added them, and (b) marks `active` both balls of every pair predict could find
  // an event for: approaching (b < 0) and not provably apart at the end of the step by the very
  // bound predict uses, |d|^2 + 2 b dt > (r_i + r_j)^2. A ball in no such pair, no contact and no
  // wall reach has no event this step (its predict would find none), so it is not predicted:
  // results are bit-identical to predicting every ball. In the 10^4 gas 3.5% of balls are active.
  template <bool kEqualRadii>
  void screen_pairs(double reach) {
    const int parts = pool_.parts();
    pool_.run([&](int p) {
      tmp_.pair_hits[p].clear();
      tmp_.pair_contacts[p].clear();
      const int n = grid_.balls();
      screen_slots<kEqualRadii>(static_cast<int>(ForkJoin::range_begin(n, p, parts)),
                                static_cast<int>(ForkJoin::range_begin(n, p + 1, parts)), reach, tmp_.pair_hits[p],
                                tmp_.pair_contacts[p]);
    });
  }

  // The screen's kernel over slots [s0, s1), reading the state through the slot -> ball map (nearly
  // the identity between renumberings, so nearly front to back). The rare outcome (a contact, or
  // an approach within the step) takes one branch, decided by both tests at once, and the kernel
  // only records the pair: making the contact inside it would grow the rare branch and slow the
  // sweep. The part then makes its pairs' contacts, from the state it has just read, in parallel
  // (a serial pass over all pairs afterwards would read the state again), by add_pair_contact's
  // expressions (make_pair_contact).
  template <bool kEqualRadii>
  void screen_slots(int s0, int s1, double reach, std::vector<std::pair<int, int>>& hits, std::vector<PassContact>& found) {
    const double slop = s_.contact_slop, two = 2.0, dt = dt_, rs0 = w_.r0 + w_.r0;
    const double lim0 = rs0 + std::max(slop * rs0, reach), lim0_2 = lim0 * lim0, rs0_2 = rs0 * rs0;
    const double* __restrict x = w_.p.col(0).data();
    const double* __restrict y = w_.p.col(1).data();
    const double* __restrict vx = w_.v.col(0).data();
    const double* __restrict vy = w_.v.col(1).data();
    const double* __restrict r = w_.r.data();
    const int* __restrict id = grid_.id();
    uint8_t* active = active_.data();
    grid_.for_each_forward_pair(s0, s1, [&](int sa, int sb) {
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
      if (make_pair_contact(a, b, dx, dy, dx * dx + dy * dy, vx[a] - vx[b], vy[a] - vy[b],
                            kEqualRadii ? rs0 : r[a] + r[b], dt, true, c)) {
        find_warm_impulse(c);
        found.push_back(c);
      }
    }
  }

  // The pair screen over the neighbour list (elastic scenes: no contacts to find, only the
  // approaches), in parallel over fixed runs of pairs: the same test as screen_slots. A pair that
  // passes it but is not listed cannot touch within the step (the list covers it), so it has no
  // event and the balls predicted are those the grid's screen would give events to.
  // Every pair that passes also gets its collision time here, by next_event's own expressions
  // (approach_root), into tmp_.approaches: drift takes the balls' first events from them instead of
  // walking each active ball's 3 x 3 cells again (first_pair_events).
  template <bool kEqualRadii>
  void screen_list() {
    const int parts = pool_.parts();
    const long m = list_.pairs();
    const double dt = dt_, two = 2.0, rs0_2 = 4.0 * w_.r0 * w_.r0;
    pool_.run([&](int p) {
      std::vector<Approach>& found = tmp_.approaches[p];
      found.clear();
      const long k0 = ForkJoin::range_begin(m, p, parts), k1 = ForkJoin::range_begin(m, p + 1, parts);
      const int* __restrict first = list_.first();
      const int* __restrict second = list_.second();
      const double* __restrict x = w_.p.col(0).data();
      const double* __restrict y = w_.p.col(1).data();
      const double* __restrict vx = w_.v.col(0).data();
      const double* __restrict vy = w_.v.col(1).data();
      uint8_t* active = active_.data();
      for (long k = k0; k < k1; ++k) {
        const int a = first[k], b = second[k];
        const double dx = x[a] - x[b], dy = y[a] - y[b];
        const double wx = vx[a] - vx[b], wy = vy[a] - vy[b];
        const double d2 = dx * dx + dy * dy, bb = dx * wx + dy * wy;
        double rs2 = rs0_2;
        if constexpr (!kEqualRadii) {
          const double rs = w_.r(a) + w_.r(b);
          rs2 = rs * rs;
        }
        if ((bb < 0) & ((d2 - rs2) + two * bb * dt <= 0)) [[unlikely]] {
          std::atomic_ref<uint8_t>(active[a]).store(1, std::memory_order_relaxed);
          std::atomic_ref<uint8_t>(active[b]).store(1, std::memory_order_relaxed);
          const double rs = w_.radius(a) + w_.radius(b), touch = rs + touch_pair(a, b);
          // next_event's expressions from t0 = 0 (0 + t is t): the pair touches now, or meets at t.
          const double t = d2 < touch * touch ? kTouching : approach_root(bb, d2 - rs * rs, wx, wy);
          if (t <= dt) found.push_back({a, b, t});
        }
      }
    });
  }

  // The first pair event of every ball the list screen found approaching, as next_event would find
  // it from the start of the step (its pair part: the earliest time, a tie to the first pair met).
  // next_event meets pairs in cell order, which is not the screen's, so a ball whose earliest time
  // is shared by two partners gets kAsk (next_event decides), as does one in a pair that touches now:
  // such a pair's event (t0) depends on the pairs met before it (its prune). Both are rare.
  void first_pair_events() {
    for (const auto& found : tmp_.approaches)
      for (const Approach& f : found) {
        const auto note = [&](int i, int j) {
          if (tmp_.first_j[i] == kAsk) return;
          if (f.t == kTouching || f.t == tmp_.first_t[i]) tmp_.first_j[i] = kAsk;
          else if (f.t < tmp_.first_t[i]) tmp_.first_t[i] = f.t, tmp_.first_j[i] = j;
        };
        note(f.a, f.b), note(f.b, f.a);
      }
  }

  // Ball i's earliest event from the start of the step: its walls (next_event's own loop), then its
  // pair event from first_pair_events, or next_event itself where that said kAsk.
  bool first_event(int i, PredictedEvent& best) const {
    if (!listed_ || tmp_.first_j[i] == kAsk) return next_event<true>(i, best);
    best = {kNever, i, 0, count_[i], 0};
    wall_event<true>(i, best);
    const int j = tmp_.first_j[i];
    // A pair event earlier than the wall's is never pruned in next_event (its bound holds until then).
    if (j >= 0 && tmp_.first_t[i] < best.t) best = {tmp_.first_t[i], i, j, count_[i], count_[j]};
    return best.t <= dt_;
  }

  // Renumbers the balls in the cell order of the grid just built (slot s becomes ball s). Everything
  // indexed by ball moves with them; the warm-start impulses are re-keyed. Positions and velocities
  // are gathered in slot order one column at a time (in parallel, through tmp_.column); the other
  // per-ball arrays are permuted in place along the permutation's cycles.
  void reorder_by_cell() {
    const int* id = grid_.id();
    const int parts = pool_.parts();
    tmp_.column.resize(w_.n);
    double* column_in_order = tmp_.column.data();
    for (double* column : {w_.p.col(0).data(), w_.p.col(1).data(), w_.v.col(0).data(), w_.v.col(1).data()}) {
      pool_.run([&](int p) {
        const long b = ForkJoin::range_begin(w_.n, p, parts), e = ForkJoin::range_begin(w_.n, p + 1, parts);
        for (long s = b; s < e; ++s) column_in_order[s] = column[id[s]];
      });
      pool_.run([&](int p) {
        const long b = ForkJoin::range_begin(w_.n, p, parts), e = ForkJoin::range_begin(w_.n, p + 1, parts);
        std::copy(column_in_order + b, column_in_order + e, column + b);
      });
    }
    tmp_.placed.resize(w_.n);
    uint8_t* placed = tmp_.placed.data();
    auto permute = [&](auto* a) {
      std::fill(placed, placed + w_.n, 0);
      for (int s = 0; s < w_.n; ++s) {
        if (placed[s]) continue;
        const auto first = a[s];  // the cycle s <- id[s] <- id[id[s]] ... back to s
        int k = s;
        for (; id[k] != s; k = id[k]) a[k] = a[id[k]], placed[k] = 1;
        a[k] = first, placed[k] = 1;
      }
    };
    if (w_.r.size()) permute(w_.r.data());
    if (w_.inv_m.size()) permute(w_.inv_m.data());
    if (w_.rotation) permute(w_.w.data()), permute(w_.angle.data());
    permute(count_.data());
    soft_path_.permute_per_ball(permute);
    grid_.renumbered([&](const int* new_number) {
      for (int& b : w_.ball_of) b = new_number[b];
      warm_.renumber(new_number, false, tmp_.warm_entries);
      soft_path_.renumbered(new_number);
    });
  }

  // A resting impact (slower than v_rest) at time t inside a pile: solve every contact of the
  // touching cluster around it at once (the same sequential impulses, to the velocity tolerance),
  // rather than one zero-time event at a time (an inelastic collapse of round-off otherwise).
  void resolve_resting_cluster(int i, int j, double t) {
    tmp_.cluster.clear();
    tmp_.contacts.clear();
    auto enter = [&](int b) {
      if (tmp_.in_cluster[b]) return;
      tmp_.in_cluster[b] = 1;
      advance(b, t);
      tmp_.cluster.push_back(b);
    };
    enter(i);
    if (j >= 0) enter(j);
    const double horizon = dt_ - t;
    for (size_t k = 0; k < tmp_.cluster.size(); ++k) {
      const int a = tmp_.cluster[k];
      add_wall_contacts(a, 0.0, horizon, false);
      if (sc_.no_pairs) continue;
      grid_.for_each_near(a, [&](int b) {
        if (b == a) return;
        if (tmp_.in_cluster[b]) {
          if (b > a) return;  // both in the cluster: the pair is added once, from the larger index
        } else {
          advance(b, t);  // along its own line: its queued prediction stays valid
        }
        if (add_pair_contact(a, b, 0.0, horizon, false)) enter(b);
      });
    }
    // Sequential impulses need not converge within the cluster's sweeps (a jammed pile converges
    // slowly); then the step's round-off tolerance rises to twice what the solve left,
    // so the same residual cannot fire the same cluster again. Overlap stays below residual x dt,
    // and the next contact pass closes it.
    for (int b : tmp_.cluster) tmp_.in_cluster[b] = 0;
    const double left = solve_contacts(kClusterIterations, 0.5 * v_tol_);
    v_tol_ = std::max(v_tol_, 2.0 * left);
    for (int b : tmp_.cluster) ++count_[b];
    // A neighbour list only covers balls within their skin. (The grid's speed bound is not
    // checked here: resting impulses are far below it.)
    if (listed_)
      for (int b : tmp_.cluster)
        if (beyond_skin(b, t)) return rebuild_mid_step(t);
    for (int b : tmp_.cluster) predict(b);
  }

  // Approach speeds that close less than the contact slop over a step are round-off, not motion.
  double velocity_tolerance() const { return s_.contact_slop * w_.rmax / dt_; }

  // Event-driven motion over [0, dt]: every ball moves on its straight line until its next
  // collision, found as the root of a quadratic, in time order (Alder & Wainwright 1959; event
  // invalidation by per-ball collision counters as in Rapaport, "The Art of Molecular Dynamics").
  void drift() {
    // t_local_ is 0 for every ball here: the last step's final advance (or this one's start_pass)
    // left it so.
    tmp_.queue.clear();
    // The active balls' predictions read only the state at the start of the step: on several
    // parts each predicts its fixed range of balls, and the events are queued in ball order, as
    // predicting one ball after the other would queue them.
    const int parts = pool_.parts();
    if (listed_) first_pair_events();
    if (parts == 1) {
      PredictedEvent ev;
      for (int i = 0; i < w_.n; ++i)
        if (active_[i] && first_event(i, ev)) push_event(ev);
    } else {
      pool_.run([&](int p) {
        tmp_.first_events[p].clear();
        const int b = static_cast<int>(ForkJoin::range_begin(w_.n, p, parts));
        const int e = static_cast<int>(ForkJoin::range_begin(w_.n, p + 1, parts));
        PredictedEvent ev;
        for (int i = b; i < e; ++i)
          if (active_[i] && first_event(i, ev)) tmp_.first_events[p].push_back(ev);
      });
      for (const auto& events : tmp_.first_events)
        for (const PredictedEvent& ev : events) push_event(ev);
    }
    if (listed_)
      for (const auto& found : tmp_.approaches)
        for (const Approach& f : found) tmp_.first_t[f.a] = tmp_.first_t[f.b] = kNever, tmp_.first_j[f.a] = tmp_.first_j[f.b] = -1;
    const int64_t budget = static_cast<int64_t>(s_.max_events_per_ball) * w_.n + 1000;
    int64_t events = 0;
    while (!tmp_.queue.empty()) {
      const PredictedEvent ev = pop_event();
      if (count_[ev.i] != ev.ci) continue;  // i collided since: its new event is queued
      if (ev.j >= 0 && count_[ev.j] != ev.cj) {
        predict(ev.i);  // the partner changed course: look again
        continue;
      }
      if (++events > budget)
        throw std::runtime_error(fmt::format("home: more than {} collision events in one step at t = {} s "
                                             "(an inelastic collapse the contact solves did not resolve)",
                                             budget, t_));
      advance(ev.i, ev.t);
      if (ev.j >= 0) advance(ev.j, ev.t);
      if (impact_speed(ev) <= v_rest_) {
        resolve_resting_cluster(ev.i, ev.j, ev.t);
        continue;
      }
      ev.j >= 0 ? collide_pair(ev.i, ev.j) : collide_wall(ev.i, ev.j);
      ++count_[ev.i];
      if (ev.j >= 0) ++count_[ev.j];
      if (too_fast(ev.i, ev.t) || (ev.j >= 0 && too_fast(ev.j, ev.t))) {
        rebuild_mid_step(ev.t);
        continue;
      }
      predict(ev.i);
      if (ev.j >= 0) predict(ev.j);
    }
    if (w_.rotation) end_angles();
    // Without a neighbour list the next step's start_pass brings the balls to the end of this one,
    // in the same pass as the kick (read() computes the end positions for its copy meanwhile).
    if (!listed_) {
      unfinished_dt_ = dt_;
      return;
    }
    pool_.run([&](int p) {
      const int b = static_cast<int>(ForkJoin::range_begin(w_.n, p, parts));
      const int e = static_cast<int>(ForkJoin::range_begin(w_.n, p + 1, parts));
      finish_step(b, e, extent_[p]);
    });
  }

  // Every ball's angle from its own clock to the end of the step, before the clocks are set back
  // for the next step (with the positions, in finish_step or the next start_pass): the angle is
  // kept at the ball's clock, and from here on at the step's end.
  void end_angles() {
    for (int i = 0; i < w_.n; ++i) w_.angle(i) += w_.w(i) * (dt_ - t_local_[i]);
  }

  // Balls [b, e) to the end of the step (advance(i, dt)), each clock set back to 0 for the next
  // step; the same pass measures the largest squared displacement from the list's build and the
  // largest squared speed, which the next step's list_covers needs.
  void finish_step(int b, int e, std::pair<double, double>& extent) {
    double* __restrict x = w_.p.col(0).data();
    double* __restrict y = w_.p.col(1).data();
    const double* __restrict vx = w_.v.col(0).data();
    const double* __restrict vy = w_.v.col(1).data();
    double* __restrict tl = t_local_.data();
    const double* __restrict bx = built_at_.col(0).data();
    const double* __restrict by = built_at_.col(1).data();
    const double dt = dt_;
    double moved2 = 0, speed2 = 0;
    for (int i = b; i < e; ++i) {
      x[i] = on_line(x[i], vx[i], dt, tl[i]), y[i] = on_line(y[i], vy[i], dt, tl[i]);
      tl[i] = 0;
      const double dx = x[i] - bx[i], dy = y[i] - by[i];
      moved2 = std::max(moved2, dx * dx + dy * dy);
      speed2 = std::max(speed2, vx[i] * vx[i] + vy[i] * vy[i]);
    }
    extent = {moved2, speed2};
  }

  // The event queue is a binary heap kept in a vector that keeps its capacity between steps,
  // operated exactly as std::priority_queue does (so the order of simultaneous events is too).
  void push_event(const PredictedEvent& ev) {
    tmp_.queue.push_back(ev);
    std::push_heap(tmp_.queue.begin(), tmp_.queue.end(), std::greater<>());
  }
  PredictedEvent pop_event() {
    std::pop_heap(tmp_.queue.begin(), tmp_.queue.end(), std::greater<>());
    const PredictedEvent ev = tmp_.queue.back();
    tmp_.queue.pop_back();
    return ev;
  }

  // Normal approach speed of an event's pair (or ball and wall) at the event time.
  double impact_speed(const PredictedEvent& ev) const {
    if (ev.j < 0) return std::abs(w_.v(ev.i, wall_axis(ev.j)));
    const double dx = w_.p(ev.i, 0) - w_.p(ev.j, 0), dy = w_.p(ev.i, 1) - w_.p(ev.j, 1);
    const double d = std::sqrt(dx * dx + dy * dy);
    return d > 0 ? -relative_normal_velocity(ev.i, ev.j, dx / d, dy / d) : 0.0;
  }

  // Ball i, just brought to time t with a new velocity, may now reach balls the broad phase did not
  // allow for: faster than the grid's speed bound, or beyond the neighbour list's skin.
  bool too_fast(int i, double t) const {
    return listed_ ? beyond_skin(i, t) : w_.v.row(i).squaredNorm() > vbound_ * vbound_;
  }

  // A collision made a ball faster than the broad phase allows for: bring every ball to time t and
  // rebuild the grid for the rest of the step. Rare (large mass ratios, chains of impacts).
  void rebuild_mid_step(double t) {
    if (listed_) {
      tmp_.rebuild_at = w_.p + (w_.v.array().colwise() * (t - Eigen::Map<const Eigen::ArrayXd>(t_local_.data(), w_.n))).matrix();
      rebuild_list(dt_ - t, false, tmp_.rebuild_at, max_speed());
    } else {
      for (int i = 0; i < w_.n; ++i) advance(i, t);
      build_broad_phase(dt_ - t, true);
    }
    tmp_.queue.clear();
    for (int i = 0; i < w_.n; ++i) {
      ++count_[i];
      predict(i);
    }
  }

  void advance(int i, double t) {
    w_.p(i, 0) = on_line(w_.p(i, 0), w_.v(i, 0), t, t_local_[i]), w_.p(i, 1) = on_line(w_.p(i, 1), w_.v(i, 1), t, t_local_[i]);
    if (w_.rotation) w_.angle(i) += w_.w(i) * (t - t_local_[i]);
    t_local_[i] = t;
  }

  // Queues ball i's earliest collision before the end of the step, if any. A touching pair (or
  // ball and wall) approaching so slowly that it would close less than the slop over the step is
  // not an event: that is round-off, and the next contact pass takes care of it.
  void predict(int i) {
    PredictedEvent best;
    if (next_event(i, best)) push_event(best);
  }

  // Ball i's earliest collision before the end of the step, in `best`; false if there is none.
  // Reads the state only, so the first predictions of a step may run in parallel (see drift).
  // kAtStart: every ball's clock is 0 (the start of drift), so no clock is read and no ball is
  // brought to a common time (x + v 0 is x): the same events, one array fewer to read per partner
  // and less arithmetic.
  template <bool kAtStart = false>
  bool next_event(int i, PredictedEvent& best) const {
    best = {kNever, i, 0, count_[i], 0};
    const double ti = kAtStart ? 0.0 : t_local_[i];
    const double v_tol = v_tol_;
    wall_event<kAtStart>(i, best);
    if (!sc_.no_pairs) grid_.for_each_near(i, [&](int j) {
      if (j == i) return;
      const double tj = kAtStart ? 0.0 : t_local_[j];
      const double t0 = std::max(ti, tj);
      double dx, dy;  // i - j at t0
      if constexpr (kAtStart) {
        dx = w_.p(i, 0) - w_.p(j, 0), dy = w_.p(i, 1) - w_.p(j, 1);
      } else {
        dx = on_line(w_.p(i, 0), w_.v(i, 0), t0, ti) - on_line(w_.p(j, 0), w_.v(j, 0), t0, tj);
        dy = on_line(w_.p(i, 1), w_.v(i, 1), t0, ti) - on_line(w_.p(j, 1), w_.v(j, 1), t0, tj);
      }
      const double wx = w_.v(i, 0) - w_.v(j, 0), wy = w_.v(i, 1) - w_.v(j, 1);
      const double b = dx * wx + dy * wy;  // < 0: approaching
      const double d2 = dx * dx + dy * dy;
      const double rs = w_.radius(i) + w_.radius(j);
      const double c = d2 - rs * rs;
      // Not approaching, or: |d(t)|^2 = d2 + 2 b t + a t^2 >= d2 + 2 b t (a >= 0), and even that
      // stays above rs^2 until the earliest event found so far (or the step's end): no root is
      // needed. One branch for both (| not ||): the sign of b is a coin toss per pair.
      if ((b >= 0) | (c + 2.0 * b * (std::min(best.t, dt_) - t0) > 0)) return;
      const double touch = rs + touch_pair(i, j);
      double t;
      if (d2 < touch * touch) {
        if (b * b < v_tol * v_tol * d2) return;  // -b / |d| < v_tol: round-off, not an approach
        t = t0;  // touching (or overlapping by round-off) and approaching: collide now
      } else {
        t = t0 + approach_root(b, c, wx, wy);
      }
      if (t < best.t) best = {t, i, j, count_[i], count_[j]};
    });
    return best.t <= dt_;
  }

  // Ball i's earliest wall event (from its own time), into `best` if earlier.
  // With a neighbour list, a ball not near a wall at its build cannot reach one while the list
  // holds, even after collisions (beyond_skin): its walls are not looked at.
  template <bool kAtStart = false>
  void wall_event(int i, PredictedEvent& best) const {
    if (!w_.walls || (listed_ && !near_wall_mark_[i])) return;
    const double ti = kAtStart ? 0.0 : t_local_[i];
    for (int axis = 0; axis < 2; ++axis) {
      const double v = w_.v(i, axis);
      if (v == 0) continue;
      const int side = v < 0 ? 0 : 1;
      const double gap = w_.wall_gap(i, axis, side);
      if (gap < touch_wall(i) && std::abs(v) < v_tol_) continue;
      // Touching or overlapping by round-off and approaching: collide now (Bannerman et al.,
      // "Stable algorithms for event-driven molecular dynamics", J. Comput. Phys. 2014).
      const double t = ti + std::max(gap, 0.0) / std::abs(v);
      if (t < best.t) best = {t, i, wall_partner(axis, side), count_[i], 0};
    }
  }

  // How long until an approaching pair (separation d, relative velocity w, b = d.w < 0,
  // c = |d|^2 - (r_i + r_j)^2 > 0) touches: the smaller root of |d + w t| = r_i + r_j, in the
  // cancellation-free form; kNever if it passes by.
  static double approach_root(double b, double c, double wx, double wy) {
    const double a = wx * wx + wy * wy;
    const double disc = b * b - a * c;
    return disc < 0 ? kNever : c / (-b + std::sqrt(disc));
  }

  // Restitution on the normal component; without friction the tangential velocity is untouched,
  // with it the rough-disk impulse law (rough_impact.h) stops or slows the slip.
  void collide_pair(int i, int j) {
    double nx = w_.p(i, 0) - w_.p(j, 0), ny = w_.p(i, 1) - w_.p(j, 1);
    const double d = std::sqrt(nx * nx + ny * ny);
    if (d == 0) return;  // coincident centres: no normal exists
    nx /= d, ny /= d;
    const double vn = relative_normal_velocity(i, j, nx, ny);
    if (vn >= 0) return;
    const double inv_sum = w_.inv_mass(i) + w_.inv_mass(j);
    if (!w_.rough()) return apply_impulse(i, j, nx, ny, -(1.0 + w_.e) * vn / inv_sum);
    const RoughImpulse P = rough_impact(vn, slip(i, j, nx, ny), w_.e, w_.mu, 1.0 / inv_sum,
                                        tangent_mass(w_.inv_mass(i), w_.inv_mass(j), w_.k));
    apply_impulse(i, j, nx, ny, P.normal);
    apply_tangent_impulse(i, j, nx, ny, P.tangent);
  }

  void collide_wall(int i, int code) {
    const int axis = wall_axis(code);
    if (!w_.rough()) {
      w_.v(i, axis) = -w_.e * w_.v(i, axis);
      return;
    }
    const double sign = wall_side(code) == 0 ? 1.0 : -1.0;  // the normal points into the box
    const double nx = axis == 0 ? sign : 0.0, ny = axis == 1 ? sign : 0.0;
    const double vn = relative_normal_velocity(i, code, nx, ny);
    if (vn >= 0) return;
    const double inv_m = w_.inv_mass(i);
    const RoughImpulse P = rough_impact(vn, slip(i, code, nx, ny), w_.e, w_.mu, 1.0 / inv_m, tangent_mass(inv_m, 0.0, w_.k));
    apply_impulse(i, code, nx, ny, P.normal);
    apply_tangent_impulse(i, code, nx, ny, P.tangent);
  }

  HomeSettings s_;
  HomeShortcuts sc_;  // the shortcuts taken, fixed at construction
  int reorder_;       // renumber the balls in cell order every this many steps (0: never)
  HomeWorld w_;                   // the balls and the scene's constants
  bool listed_;                   // elastic: a neighbour list with a skin instead of a grid per step
  std::vector<double> t_local_;   // each ball's own time within the step (s)
  std::vector<uint32_t> count_;   // collisions so far, to recognise stale events
  std::vector<uint8_t> active_;   // may have an event this step (see screen_pairs)
  mutable ForkJoin pool_;  // mutable: read() gathers on it too
  StepScratch tmp_;
  StartScan start_;                // this step's start_pass, merged
  bool walls_screened_ = false;   // start_pass did this step's wall screen
  double t_ = 0;                  // simulated time (s)
  double dt_ = 0;                 // the step in progress (s)
  double unfinished_dt_ = 0;      // > 0: the last step (this long) awaits its final advance (see drift)
  double v_rest_ = 0;             // this step's resting-impact speed (m/s)
  double vbound_ = 0;             // speed the broad phase allows for this step (m/s)
  double v_tol_ = 0;              // this step's round-off approach speed (m/s), see predict
  HomeGrid grid_;                 // built on the positions at the start of the step (listed_: at the list's build)
  NeighbourList list_;            // listed_ only
  Eigen::MatrixX2d built_at_;     // listed_: positions when the list was built
  std::vector<int> near_wall_;    // listed_: balls that can reach a wall before the list expires
  std::vector<uint8_t> near_wall_mark_;  // listed_: 1 for the balls in near_wall_
  // listed_, per part: the largest squared displacement since the list's build and the largest
  // squared speed, measured by a step's final advance for the next step's list check.
  std::vector<std::pair<double, double>> extent_;
  double half_skin_ = -1;         // listed_: how far a ball may move from there (negative: no list yet)
  bool renumbered_ = false;       // ever renumbered
  long renumbered_at_ = 0;        // the step of the last renumbering
  long steps_ = 0;                // steps taken
  WarmStart warm_;                // impulses at the end of the last contact pass (events path)
  bool soft_;                     // resting contact by the soft step (scenes with gravity)
  SoftResting soft_path_;         // soft_ only
};

}  // namespace

EngineEntry home_engine() {
  EngineInfo info;
  info.name = "home";
  info.role = EngineRole::ours;
  info.version = "0.1";
  info.limits =
      "double; impacts slower than rest_velocity (2 |g| dt) are resting contact (restitution 0); contacts within "
      "contact_slop (1e-6 of the radius sum) count as touching";
  info.summary = "our solver: symplectic Euler, resting-contact solve, exact event-driven motion within each step";
  info.caps.continuous_collision = true;
  // Coulomb friction at impacts (the rough-disk impulse law) and in resting contacts (sequential
  // impulses in the friction cone); the soft path solves it in its soft step.
  // Sweeps of the resting-contact solve; motion between contacts is exact at any setting.
  info.sweep_knobs = {{"contact_iterations", {4, 16, 200}}};
  return {info, [](const Scene& scene, const std::string&, const nlohmann::json& overrides) {
            HomeSettings s;
            SettingsReader r("home", overrides);
            r.get("contact_iterations", s.contact_iterations);
            r.get("rest_velocity", s.rest_velocity);
            r.get("contact_slop", s.contact_slop);
            r.get("max_events_per_ball", s.max_events_per_ball);
            r.get("resting", s.resting, {"soft", "events"});
            r.get("substeps", s.soft.substeps);
            r.get("substep_iterations", s.soft.substep_iterations);
            r.get("relax_iterations", s.soft.relax_iterations);
            r.get("max_stride", s.max_stride);
            r.get("max_parts", s.max_parts);
            r.get("contact_hertz", s.soft.contact_hertz);
            r.get("damping_ratio", s.soft.damping_ratio);
            r.get("push_speed", s.soft.push_speed);
            r.get("sleep_speed", s.sleep_speed);
            r.get("sleep_time", s.sleep_time);
            r.finish();
            if (s.soft.substeps < 1) throw InputError("settings.home.substeps: must be >= 1");
            if (s.soft.substep_iterations < 1) throw InputError("settings.home.substep_iterations: must be >= 1");
            if (s.soft.relax_iterations < 0) throw InputError("settings.home.relax_iterations: must be >= 0");
            if (!(s.max_stride > 0)) throw InputError("settings.home.max_stride: must be > 0");
            if (s.max_parts < 1) throw InputError("settings.home.max_parts: must be >= 1");
            if (!(s.soft.contact_hertz > 0)) throw InputError("settings.home.contact_hertz: must be > 0");
            if (!(s.soft.damping_ratio >= 0)) throw InputError("settings.home.damping_ratio: must be >= 0");
            if (!(s.soft.push_speed > 0)) throw InputError("settings.home.push_speed: must be > 0");
            if (!(s.sleep_speed >= 0)) throw InputError("settings.home.sleep_speed: must be >= 0");
            if (!(s.sleep_time > 0)) throw InputError("settings.home.sleep_time: must be > 0");
            if (s.contact_iterations < 0) throw InputError("settings.home.contact_iterations: must be >= 0");
            if (!(s.contact_slop > 0)) throw InputError("settings.home.contact_slop: must be > 0");
            if (s.max_events_per_ball < 1) throw InputError("settings.home.max_events_per_ball: must be >= 1");
            return make_home(scene, s);
          }};
}

std::unique_ptr<Engine> make_home(const Scene& scene, const HomeSettings& settings) {
  return std::make_unique<Home>(scene, settings);
}

}  // namespace ballbench

#include "solver/home.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"
#include "uniform_grid.h"

namespace ballbench {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// How much faster than the fastest ball at the start of the step a ball may become through
// collisions before the broad phase must be rebuilt (equal-mass elastic impacts can reach sqrt(2)).
constexpr double kSpeedMargin = 1.5;
// Sweeps the cluster solve may take to bring every contact within the velocity tolerance; a
// cluster that needs more is left to the event loop, which finishes the job one event at a time.
constexpr int kClusterIterations = 200;
// Fraction of its gap a speculative contact may close in one step (see add_contact).
constexpr double kSpeculativeFraction = 0.5;

struct Event {
  double t;         // time within the step (s)
  int i, j;         // j >= 0: ball pair; j < 0: wall -1 - (2 * axis + side)
  uint32_t ci, cj;  // collision counters of i and j when predicted; stale if they moved on
  bool operator>(const Event& o) const { return t > o.t; }
};

struct Contact {
  int i, j;         // j < 0: wall, as in Event
  double nx, ny;    // unit normal, from j (or the wall) towards i
  double target;    // least normal velocity wanted after the solve (m/s)
  double inv_mass;  // 1 / (1/m_i + 1/m_j)
  double impulse;   // accumulated, >= 0
};

class Home final : public Engine {
 public:
  Home(const Scene& scene, HomeSettings s)
      : s_(s),
        n_(scene.n()),
        e_(scene.restitution),
        g_(scene.gravity),
        box_(scene.container),
        walls_(scene.container.kind == ContainerKind::Box),
        r_(scene.radius),
        inv_m_(scene.mass.cwiseInverse()),
        rmax_(scene.radius.maxCoeff()),
        p_(scene.initial.pos),
        v_(scene.initial.vel),
        t_local_(n_),
        count_(n_, 0),
        stamp_(n_, 0) {}

  void step(double dt) override {
    t_ += dt;
    dt_ = dt;
    v_rest_ = s_.rest_velocity >= 0 ? s_.rest_velocity : 2.0 * g_.norm() * dt;
    // Symplectic Euler: velocity first (thesis eq. 3, in the bowl program's order), then the
    // positions move along straight lines for the whole step, which the event loop follows exactly.
    v_.col(0).array() += g_.x() * dt;
    v_.col(1).array() += g_.y() * dt;
    start_ = p_;
    build_broad_phase(dt);
    v_tol_ = velocity_tolerance();
    contact_pass();
    drift();
  }

  void read(State& out) const override {
    out.t = t_;
    out.pos = p_;
    out.vel = v_;
  }

  nlohmann::json settings() const override {
    return {{"contact_iterations", s_.contact_iterations},
            {"rest_velocity", s_.rest_velocity},
            {"contact_slop", s_.contact_slop},
            {"max_events_per_ball", s_.max_events_per_ball}};
  }

 private:
  // Grid over the positions at the start of the step, with cells wide enough that any two balls
  // which can touch during the rest of the step are in adjacent cells.
  void build_broad_phase(double horizon) {
    vbound_ = kSpeedMargin * std::sqrt(v_.rowwise().squaredNorm().maxCoeff());
    grid_.build(start_, 2.0 * rmax_ + 2.0 * vbound_ * horizon);
  }

  double touch_pair(int i, int j) const { return s_.contact_slop * (r_(i) + r_(j)); }
  double touch_wall(int i) const { return s_.contact_slop * r_(i); }

  // Gap between ball i and a wall (m): side 0 is the min wall, side 1 the max wall.
  double wall_gap(int i, int axis, int side) const {
    return side == 0 ? p_(i, axis) - r_(i) - box_.min(axis) : box_.max(axis) - r_(i) - p_(i, axis);
  }

  double relative_normal_velocity(int i, int j, double nx, double ny) const {
    double wx = v_(i, 0), wy = v_(i, 1);
    if (j >= 0) wx -= v_(j, 0), wy -= v_(j, 1);
    return wx * nx + wy * ny;
  }

  void apply_impulse(int i, int j, double nx, double ny, double J) {
    v_(i, 0) += J * inv_m_(i) * nx, v_(i, 1) += J * inv_m_(i) * ny;
    if (j >= 0) v_(j, 0) -= J * inv_m_(j) * nx, v_(j, 1) -= J * inv_m_(j) * ny;
  }

  // The velocity constraint of one contact, for the sequential-impulse solve:
  // - touching and approaching faster than v_rest: an impact, target -e vn (the bounce);
  // - touching and slower: resting contact, target 0 (do not approach). Not a small separation:
  //   a jammed chain (seed-bowl's row of 20 balls spans its 10 m box exactly, wall to wall) cannot
  //   separate everywhere at once, and an infeasible target keeps the solve from converging. What
  //   the solve leaves over is below the velocity tolerance, which predict ignores. A round-off
  //   overlap is closed within the step when `close_overlap`;
  // - not touching: a speculative contact (Catto, "Speculative Contacts", 2013): the pair may close
  //   part of its gap within `horizon` but not overlap, target -f gap / horizon (f < 1, so that
  //   it lands as touching over a few steps instead of as an impact event at the end of this one);
  // - approaching faster than v_rest and not touching: left to the exact event loop.
  void add_contact(int i, int j, double nx, double ny, double gap, double touch, double horizon, bool close_overlap) {
    const double vn = relative_normal_velocity(i, j, nx, ny);
    const bool touching = gap < touch, fast = -vn > v_rest_;
    if (fast && !touching) return;
    double target;
    if (touching && fast) target = -e_ * vn;
    else if (touching) target = close_overlap ? std::max(-gap, 0.0) / horizon : 0.0;
    else target = -kSpeculativeFraction * gap / horizon;
    // Kept even when satisfied now: an impulse on a neighbour can push the pair together.
    const double inv_mass = 1.0 / (inv_m_(i) + (j >= 0 ? inv_m_(j) : 0.0));
    contacts_.push_back({i, j, nx, ny, target, inv_mass, 0.0});
  }

  void add_wall_contacts(int i, double reach, double horizon, bool close_overlap) {
    if (!walls_) return;
    for (int axis = 0; axis < 2; ++axis)
      for (int side = 0; side < 2; ++side) {
        const double gap = wall_gap(i, axis, side), touch = touch_wall(i);
        if (gap >= std::max(touch, reach)) continue;
        const double sign = side == 0 ? 1.0 : -1.0;  // the normal points into the box
        add_contact(i, -1 - (2 * axis + side), axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, gap, touch, horizon,
                    close_overlap);
      }
  }

  // Adds the contact of pair (i, j) if their gap is below max(touch, reach); returns whether it was.
  bool add_pair_contact(int i, int j, double reach, double horizon, bool close_overlap) {
    const double dx = p_(i, 0) - p_(j, 0), dy = p_(i, 1) - p_(j, 1);
    const double rs = r_(i) + r_(j), limit = rs + std::max(touch_pair(i, j), reach);
    const double d2 = dx * dx + dy * dy;
    if (d2 >= limit * limit || d2 == 0) return false;  // squared first: most candidates are far
    const double d = std::sqrt(d2);
    add_contact(i, j, dx / d, dy / d, d - rs, touch_pair(i, j), horizon, close_overlap);
    return true;
  }

  // Sequential impulses (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005): sweeps
  // over contacts_ until every contact is within `tolerance` of its target or `sweeps` ran.
  // Returns the largest approach beyond a target left after the last sweep (m/s).
  double solve_contacts(int sweeps, double tolerance) {
    for (int it = 0; it < sweeps; ++it) {
      double worst = 0;  // largest violation seen in this sweep (m/s)
      for (Contact& c : contacts_) {
        const double vn = relative_normal_velocity(c.i, c.j, c.nx, c.ny);
        const double old = c.impulse;
        c.impulse = std::max(0.0, old + (c.target - vn) * c.inv_mass);
        apply_impulse(c.i, c.j, c.nx, c.ny, c.impulse - old);
        if (c.impulse > 0 || vn < c.target) worst = std::max(worst, std::abs(c.target - vn));
      }
      if (worst <= tolerance) return 0.0;
    }
    double left = 0;
    for (const Contact& c : contacts_) left = std::max(left, c.target - relative_normal_velocity(c.i, c.j, c.nx, c.ny));
    return left;
  }

  // Resting contact at the start of the step: every contact within reach of resting speeds
  // (v_rest dt) is solved together, so a pile settles in one pass instead of through a cascade of
  // zero-time events.
  //
  // Warm started (Catto 2005): each contact begins with the impulse it ended the last step with, so
  // a pile at rest needs a sweep or two instead of as many as it is high.
  void contact_pass() {
    contacts_.clear();
    const double reach = v_rest_ * dt_;
    for (int i = 0; i < n_; ++i) add_wall_contacts(i, reach, dt_, true);
    grid_.for_each_candidate_pair([&](int i, int j) { add_pair_contact(i, j, reach, dt_, true); });
    for (Contact& c : contacts_) {
      const auto it = warm_.find(contact_key(c));
      if (it == warm_.end()) continue;
      c.impulse = it->second;
      apply_impulse(c.i, c.j, c.nx, c.ny, c.impulse);
    }
    solve_contacts(s_.contact_iterations, 0.5 * v_tol_);
    warm_.clear();
    for (const Contact& c : contacts_)
      if (c.impulse > 0) warm_.emplace(contact_key(c), c.impulse);
  }

  // Pair (i, j) or ball i and wall -1 - k, as one number.
  uint64_t contact_key(const Contact& c) const {
    return static_cast<uint64_t>(c.i) * (static_cast<uint64_t>(n_) + 4) + static_cast<uint64_t>(c.j + 4);
  }

  // A resting impact (slower than v_rest) at time t inside a pile: solve every contact of the
  // touching cluster around it at once (the same sequential impulses, to the velocity tolerance),
  // rather than one zero-time event at a time (an inelastic collapse of round-off otherwise).
  void resolve_resting_cluster(int i, int j, double t) {
    ++stamp_now_;
    cluster_.clear();
    contacts_.clear();
    auto enter = [&](int b) {
      if (stamp_[b] == stamp_now_) return;
      stamp_[b] = stamp_now_;
      advance(b, t);
      cluster_.push_back(b);
    };
    enter(i);
    if (j >= 0) enter(j);
    const double horizon = dt_ - t;
    for (size_t k = 0; k < cluster_.size(); ++k) {
      const int a = cluster_[k];
      add_wall_contacts(a, 0.0, horizon, false);
      grid_.for_each_near(start_(a, 0), start_(a, 1), [&](int b) {
        if (b == a) return;
        if (stamp_[b] == stamp_now_) {
          if (b > a) return;  // both in the cluster: the pair is added once, from the larger index
        } else {
          advance(b, t);  // along its own line: its queued prediction stays valid
        }
        if (add_pair_contact(a, b, 0.0, horizon, false)) enter(b);
      });
    }
    // Sequential impulses need not converge inside a cluster (bounce targets of fast contacts can
    // fight each other); then the step's round-off tolerance rises to twice what the solve left,
    // so the same residual cannot fire the same cluster again. Overlap stays below residual x dt,
    // and the next contact pass closes it.
    const double left = solve_contacts(kClusterIterations, 0.5 * v_tol_);
    v_tol_ = std::max(v_tol_, 2.0 * left);
    for (int b : cluster_) ++count_[b];
    for (int b : cluster_) predict(b);
  }

  // Approach speeds that close less than the contact slop over a step are round-off, not motion.
  double velocity_tolerance() const { return s_.contact_slop * rmax_ / dt_; }

  // Event-driven motion over [0, dt]: every ball moves on its straight line until its next
  // collision, found as the root of a quadratic, in time order (Alder & Wainwright 1959; event
  // invalidation by per-ball collision counters as in Rapaport, "The Art of Molecular Dynamics").
  void drift() {
    std::fill(t_local_.begin(), t_local_.end(), 0.0);
    queue_ = {};
    for (int i = 0; i < n_; ++i) predict(i);
    const int64_t budget = static_cast<int64_t>(s_.max_events_per_ball) * n_ + 1000;
    int64_t events = 0;
    while (!queue_.empty()) {
      const Event ev = queue_.top();
      queue_.pop();
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
      if (too_fast(ev.i) || (ev.j >= 0 && too_fast(ev.j))) {
        rebuild_mid_step(ev.t);
        continue;
      }
      predict(ev.i);
      if (ev.j >= 0) predict(ev.j);
    }
    for (int i = 0; i < n_; ++i) advance(i, dt_);
  }

  // Normal approach speed of an event's pair (or ball and wall) at the event time.
  double impact_speed(const Event& ev) const {
    if (ev.j < 0) return std::abs(v_(ev.i, (-1 - ev.j) / 2));
    const double dx = p_(ev.i, 0) - p_(ev.j, 0), dy = p_(ev.i, 1) - p_(ev.j, 1);
    const double d = std::sqrt(dx * dx + dy * dy);
    return d > 0 ? -relative_normal_velocity(ev.i, ev.j, dx / d, dy / d) : 0.0;
  }

  bool too_fast(int i) const { return v_.row(i).squaredNorm() > vbound_ * vbound_; }

  // A collision made a ball faster than the broad phase allows for: bring every ball to time t and
  // rebuild the grid for the rest of the step. Rare (large mass ratios, chains of impacts).
  void rebuild_mid_step(double t) {
    for (int i = 0; i < n_; ++i) advance(i, t);
    start_ = p_;
    build_broad_phase(dt_ - t);
    queue_ = {};
    for (int i = 0; i < n_; ++i) {
      ++count_[i];
      predict(i);
    }
  }

  void advance(int i, double t) {
    const double h = t - t_local_[i];
    p_(i, 0) += v_(i, 0) * h, p_(i, 1) += v_(i, 1) * h;
    t_local_[i] = t;
  }

  // Queues ball i's earliest collision before the end of the step, if any. A touching pair (or
  // ball and wall) approaching so slowly that it would close less than the slop over the step is
  // not an event: that is round-off, and the next contact pass takes care of it.
  void predict(int i) {
    Event best{kNever, i, 0, count_[i], 0};
    const double ti = t_local_[i];
    const double v_tol = v_tol_;
    if (walls_)
      for (int axis = 0; axis < 2; ++axis) {
        const double v = v_(i, axis);
        if (v == 0) continue;
        const int side = v < 0 ? 0 : 1;
        const double gap = wall_gap(i, axis, side);
        if (gap < touch_wall(i) && std::abs(v) < v_tol) continue;
        // Touching or overlapping by round-off and approaching: collide now (Bannerman et al.,
        // "Stable algorithms for event-driven molecular dynamics", J. Comput. Phys. 2014).
        const double t = ti + std::max(gap, 0.0) / std::abs(v);
        if (t < best.t) best = {t, i, -1 - (2 * axis + side), count_[i], 0};
      }
    grid_.for_each_near(start_(i, 0), start_(i, 1), [&](int j) {
      if (j == i) return;
      const double t0 = std::max(ti, t_local_[j]);
      const double dx = (p_(i, 0) + v_(i, 0) * (t0 - ti)) - (p_(j, 0) + v_(j, 0) * (t0 - t_local_[j]));
      const double dy = (p_(i, 1) + v_(i, 1) * (t0 - ti)) - (p_(j, 1) + v_(j, 1) * (t0 - t_local_[j]));
      const double wx = v_(i, 0) - v_(j, 0), wy = v_(i, 1) - v_(j, 1);
      const double b = dx * wx + dy * wy;  // < 0: approaching
      if (b >= 0) return;
      const double d2 = dx * dx + dy * dy;
      const double rs = r_(i) + r_(j);
      const double c = d2 - rs * rs;
      // |d(t)|^2 = d2 + 2 b t + a t^2 >= d2 + 2 b t (a >= 0): if even that stays above rs^2 until
      // the earliest event found so far (or the step's end), no root is needed.
      if (c + 2.0 * b * (std::min(best.t, dt_) - t0) > 0) return;
      const double touch = rs + touch_pair(i, j);
      double t;
      if (d2 < touch * touch) {
        if (b * b < v_tol * v_tol * d2) return;  // -b / |d| < v_tol: round-off, not an approach
        t = t0;  // touching (or overlapping by round-off) and approaching: collide now
      } else {
        const double a = wx * wx + wy * wy;
        const double disc = b * b - a * c;
        if (disc < 0) return;
        t = t0 + c / (-b + std::sqrt(disc));  // the smaller root, in the cancellation-free form
      }
      if (t < best.t) best = {t, i, j, count_[i], count_[j]};
    });
    if (best.t <= dt_) queue_.push(best);
  }

  // Restitution on the normal component only; tangential velocity is untouched (frictionless).
  void collide_pair(int i, int j) {
    double nx = p_(i, 0) - p_(j, 0), ny = p_(i, 1) - p_(j, 1);
    const double d = std::sqrt(nx * nx + ny * ny);
    if (d == 0) return;  // coincident centres: no normal exists
    nx /= d, ny /= d;
    const double vn = relative_normal_velocity(i, j, nx, ny);
    if (vn >= 0) return;
    apply_impulse(i, j, nx, ny, -(1.0 + e_) * vn / (inv_m_(i) + inv_m_(j)));
  }

  void collide_wall(int i, int code) {
    const int axis = (-1 - code) / 2;
    v_(i, axis) = -e_ * v_(i, axis);
  }

  HomeSettings s_;
  int n_;
  double e_;
  Eigen::Vector2d g_;
  Container box_;
  bool walls_;
  Eigen::VectorXd r_, inv_m_;
  double rmax_;
  Eigen::MatrixX2d p_, v_;
  Eigen::MatrixX2d start_;        // positions at the start of the step: the grid is built on them
  std::vector<double> t_local_;   // each ball's own time within the step (s)
  std::vector<uint32_t> count_;   // collisions so far, to recognise stale events
  std::vector<uint32_t> stamp_;   // cluster membership: stamp_[b] == stamp_now_
  uint32_t stamp_now_ = 0;
  std::vector<int> cluster_;
  double t_ = 0;                  // simulated time (s)
  double dt_ = 0;                 // the step in progress (s)
  double v_rest_ = 0;             // this step's resting-impact speed (m/s)
  double vbound_ = 0;             // speed the broad phase allows for this step (m/s)
  double v_tol_ = 0;              // this step's round-off approach speed (m/s), see predict
  UniformGrid grid_;
  std::vector<Contact> contacts_;
  std::unordered_map<uint64_t, double> warm_;  // contact key -> impulse at the end of the last pass
  std::priority_queue<Event, std::vector<Event>, std::greater<>> queue_;
};

}  // namespace

EngineEntry home_engine() {
  EngineInfo info;
  info.name = "home";
  info.version = "0.1";
  info.limits =
      "double; impacts slower than rest_velocity (2 |g| dt) are resting contact (restitution 0); contacts within "
      "contact_slop (1e-6 of the radius sum) count as touching";
  info.summary = "our solver: symplectic Euler, resting-contact solve, exact event-driven motion within each step";
  info.caps.continuous_collision = true;
  return {info, [](const Scene& scene, const std::string&, const nlohmann::json& overrides) {
            HomeSettings s;
            SettingsReader r("home", overrides);
            r.get("contact_iterations", s.contact_iterations);
            r.get("rest_velocity", s.rest_velocity);
            r.get("contact_slop", s.contact_slop);
            r.get("max_events_per_ball", s.max_events_per_ball);
            r.finish();
            if (s.contact_iterations < 0) throw InputError("settings.home.contact_iterations: must be >= 0");
            if (!(s.contact_slop > 0)) throw InputError("settings.home.contact_slop: must be > 0");
            if (s.max_events_per_ball < 1) throw InputError("settings.home.max_events_per_ball: must be >= 1");
            return std::unique_ptr<Engine>(std::make_unique<Home>(scene, s));
          }};
}

}  // namespace ballbench

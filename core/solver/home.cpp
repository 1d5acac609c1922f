#include "solver/home.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
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

struct Event {
  double t;        // time within the step (s)
  int i, j;        // j >= 0: ball pair; j < 0: wall -1 - (2 * axis + side)
  uint32_t ci, cj; // collision counters of i and j when predicted; stale if they moved on
  bool operator>(const Event& o) const { return t > o.t; }
};

struct Contact {
  int i, j;          // j < 0: wall, as in Event
  double nx, ny;     // unit normal, from j (or the wall) towards i
  double target;     // normal velocity wanted after the pass (m/s)
  double inv_mass;   // 1 / (1/m_i + 1/m_j)
  double impulse;    // accumulated, >= 0
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
        p_(scene.initial.pos),
        v_(scene.initial.vel),
        t_local_(n_),
        count_(n_, 0) {
    rmax_ = r_.maxCoeff();
  }

  void step(double dt) override {
    t_ += dt;
    dt_ = dt;
    const double v_rest = s_.rest_velocity >= 0 ? s_.rest_velocity : 2.0 * g_.norm() * dt;
    // Symplectic Euler: velocity first (thesis eq. 3, in the bowl program's order), then the
    // positions move along straight lines for the whole step, which the event loop follows exactly.
    v_.col(0).array() += g_.x() * dt;
    v_.col(1).array() += g_.y() * dt;
    start_ = p_;
    build_broad_phase(dt);
    solve_touching_contacts(v_rest, dt);
    drift(dt, v_rest);
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

  // Resting contact, by sequential impulses (Catto, "Iterative Dynamics with Temporal Coherence",
  // GDC 2005) over every contact within reach of resting speeds (v_rest dt), solved together so a
  // pile settles in one pass instead of through a cascade of zero-time events:
  // - touching and approaching faster than v_rest: an impact, target -e vn (the bounce);
  // - otherwise a speculative contact (Catto, "Speculative Contacts", 2013): the pair may close
  //   its gap during the step but not overlap, target vn >= -gap / dt;
  // - approaching faster than v_rest but not yet touching: left to the exact event loop.
  void solve_touching_contacts(double v_rest, double dt) {
    contacts_.clear();
    auto add = [&](int i, int j, double nx, double ny, double gap, double touch, double inv_mass) {
      const double vn = relative_normal_velocity(i, j, nx, ny);
      const bool touching = gap < touch;
      if (-vn > v_rest && !touching) return;
      // A round-off overlap (gap < 0) gets a target that just closes it within the step.
      const double target = touching && -vn > v_rest ? -e_ * vn : -gap / dt;
      if (vn >= target) return;  // already satisfied, and impulses only push apart
      contacts_.push_back({i, j, nx, ny, target, inv_mass, 0.0});
    };
    const double reach = v_rest * dt;
    if (walls_)
      for (int i = 0; i < n_; ++i)
        for (int axis = 0; axis < 2; ++axis)
          for (int side = 0; side < 2; ++side) {
            const double gap = wall_gap(i, axis, side), touch = s_.contact_slop * r_(i);
            if (gap >= std::max(touch, reach)) continue;
            const double sign = side == 0 ? 1.0 : -1.0;  // normal points into the box
            add(i, -1 - (2 * axis + side), axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, gap, touch, 1.0 / inv_m_(i));
          }
    grid_.for_each_candidate_pair([&](int i, int j) {
      const double dx = p_(i, 0) - p_(j, 0), dy = p_(i, 1) - p_(j, 1);
      const double rs = r_(i) + r_(j), d = std::hypot(dx, dy), touch = s_.contact_slop * rs;
      if (d - rs < std::max(touch, reach) && d > 0)
        add(i, j, dx / d, dy / d, d - rs, touch, 1.0 / (inv_m_(i) + inv_m_(j)));
    });
    for (int it = 0; it < s_.contact_iterations; ++it)
      for (Contact& c : contacts_) {
        const double vn = relative_normal_velocity(c.i, c.j, c.nx, c.ny);
        const double old = c.impulse;
        c.impulse = std::max(0.0, old + (c.target - vn) * c.inv_mass);
        apply_impulse(c.i, c.j, c.nx, c.ny, c.impulse - old);
      }
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

  // Gap between ball i and a wall (m): side 0 is the min wall, side 1 the max wall.
  double wall_gap(int i, int axis, int side) const {
    return side == 0 ? p_(i, axis) - r_(i) - box_.min(axis) : box_.max(axis) - r_(i) - p_(i, axis);
  }

  // Event-driven motion over [0, dt]: every ball moves on its straight line until its next
  // collision, found as the root of a quadratic, in time order (Alder & Wainwright 1959; event
  // invalidation by per-ball collision counters as in Rapaport, "The Art of Molecular Dynamics").
  void drift(double dt, double v_rest) {
    std::fill(t_local_.begin(), t_local_.end(), 0.0);
    queue_ = {};
    for (int i = 0; i < n_; ++i) predict(i, dt);
    const int64_t budget = static_cast<int64_t>(s_.max_events_per_ball) * n_ + 1000;
    int64_t events = 0;
    while (!queue_.empty()) {
      const Event ev = queue_.top();
      queue_.pop();
      if (count_[ev.i] != ev.ci) continue;  // i collided since: its new event is queued
      if (ev.j >= 0 && count_[ev.j] != ev.cj) {
        predict(ev.i, dt);  // the partner changed course: look again
        continue;
      }
      if (++events > budget)
        throw std::runtime_error(fmt::format("home: more than {} collision events in one step at t = {} s "
                                             "(inelastic collapse not resolved by the contact pass)",
                                             budget, t_));
      advance(ev.i, ev.t);
      if (ev.j >= 0) {
        advance(ev.j, ev.t);
        collide_pair(ev.i, ev.j, v_rest);
        ++count_[ev.j];
      } else {
        collide_wall(ev.i, ev.j, v_rest);
      }
      ++count_[ev.i];
      if (too_fast(ev.i) || (ev.j >= 0 && too_fast(ev.j))) {
        rebuild_mid_step(ev.t, dt);
        continue;
      }
      predict(ev.i, dt);
      if (ev.j >= 0) predict(ev.j, dt);
    }
    for (int i = 0; i < n_; ++i) advance(i, dt);
  }

  bool too_fast(int i) const { return v_.row(i).squaredNorm() > vbound_ * vbound_; }

  // A collision made a ball faster than the broad phase allows for: bring every ball to time t and
  // rebuild the grid for the rest of the step. Rare (large mass ratios, chains of impacts).
  void rebuild_mid_step(double t, double dt) {
    for (int i = 0; i < n_; ++i) advance(i, t);
    start_ = p_;
    build_broad_phase(dt - t);
    queue_ = {};
    for (int i = 0; i < n_; ++i) {
      ++count_[i];
      predict(i, dt);
    }
  }

  void advance(int i, double t) {
    const double h = t - t_local_[i];
    p_(i, 0) += v_(i, 0) * h, p_(i, 1) += v_(i, 1) * h;
    t_local_[i] = t;
  }

  // Queues ball i's earliest collision before dt, if any.
  void predict(int i, double dt) {
    Event best{kNever, i, 0, count_[i], 0};
    const double ti = t_local_[i];
    if (walls_)
      for (int axis = 0; axis < 2; ++axis) {
        const double v = v_(i, axis);
        if (v == 0) continue;
        const int side = v < 0 ? 0 : 1;
        const double gap = wall_gap(i, axis, side);
        const double touch = s_.contact_slop * r_(i);
        if (gap < touch && std::abs(v) * dt_ < touch) continue;  // resting: closes less than the slop
        // Touching or overlapping by round-off and approaching: collide now (Bannerman et al.,
        // "Stable algorithms for event-driven molecular dynamics", J. Comput. Phys. 2014).
        const double t = ti + std::max(gap, 0.0) / std::abs(v);
        if (t < best.t) best = {t, i, -1 - (2 * axis + side), count_[i], 0};
      }
    const double approach_eps = 1e-12 * vbound_;  // slower approach is numerical noise, not motion
    grid_.for_each_near(start_(i, 0), start_(i, 1), [&](int j) {
      if (j == i) return;
      const double t0 = std::max(ti, t_local_[j]);
      const double dx = (p_(i, 0) + v_(i, 0) * (t0 - ti)) - (p_(j, 0) + v_(j, 0) * (t0 - t_local_[j]));
      const double dy = (p_(i, 1) + v_(i, 1) * (t0 - ti)) - (p_(j, 1) + v_(j, 1) * (t0 - t_local_[j]));
      const double wx = v_(i, 0) - v_(j, 0), wy = v_(i, 1) - v_(j, 1);
      const double b = dx * wx + dy * wy;  // < 0: approaching
      const double d2 = dx * dx + dy * dy;
      if (b >= -approach_eps * std::sqrt(d2)) return;
      const double rs = r_(i) + r_(j);
      const double c = d2 - rs * rs;
      const double a = wx * wx + wy * wy;
      double t;
      if (c <= 2 * rs * s_.contact_slop * rs) {
        // Touching (within the slop) and approaching. So slow an approach that it closes less than
        // the slop over the step is round-off, not motion: counting it would start a cascade of
        // zero-time events whose speeds shrink geometrically (an inelastic collapse of noise).
        if (-b * dt_ < s_.contact_slop * rs * std::sqrt(d2)) return;
        t = t0;  // collide now
      } else {
        const double disc = b * b - a * c;
        if (disc < 0) return;
        t = t0 + c / (-b + std::sqrt(disc));  // the smaller root, in the cancellation-free form
      }
      if (t < best.t) best = {t, i, j, count_[i], count_[j]};
    });
    if (best.t <= dt) queue_.push(best);
  }

  // Restitution on the normal component only; tangential velocity is untouched (frictionless).
  void collide_pair(int i, int j, double v_rest) {
    double nx = p_(i, 0) - p_(j, 0), ny = p_(i, 1) - p_(j, 1);
    const double d = std::hypot(nx, ny);
    if (d == 0) return;  // coincident centres: no normal exists
    nx /= d, ny /= d;
    const double vn = relative_normal_velocity(i, j, nx, ny);
    if (vn >= 0) return;
    const double e = -vn > v_rest ? e_ : 0.0;
    const double J = -(1.0 + e) * vn / (inv_m_(i) + inv_m_(j));
    apply_impulse(i, j, nx, ny, J);
  }

  void collide_wall(int i, int code, double v_rest) {
    const int axis = (-1 - code) / 2;
    const double vn = std::abs(v_(i, axis));
    v_(i, axis) = -(vn > v_rest ? e_ : 0.0) * v_(i, axis);
  }

  HomeSettings s_;
  int n_;
  double e_;
  Eigen::Vector2d g_;
  Container box_;
  bool walls_;
  Eigen::VectorXd r_, inv_m_;
  double rmax_ = 0;
  Eigen::MatrixX2d p_, v_, start_;
  std::vector<double> t_local_;   // each ball's own time within the step (s)
  std::vector<uint32_t> count_;   // collisions so far, to recognise stale events
  double dt_ = 0;                 // the step in progress (s)
  double vbound_ = 0;             // speed the broad phase allows for this step (m/s)
  UniformGrid grid_;
  std::vector<Contact> contacts_;
  std::priority_queue<Event, std::vector<Event>, std::greater<>> queue_;
  double t_ = 0;
};

}  // namespace

EngineEntry home_engine() {
  EngineInfo info;
  info.name = "home";
  info.version = "0.1";
  info.summary = "our solver: symplectic Euler + resting-contact pass + exact event-driven drift in each step";
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
            if (s.contact_slop < 0) throw InputError("settings.home.contact_slop: must be >= 0");
            if (s.max_events_per_ball < 1) throw InputError("settings.home.max_events_per_ball: must be >= 1");
            return std::unique_ptr<Engine>(std::make_unique<Home>(scene, s));
          }};
}

}  // namespace ballbench

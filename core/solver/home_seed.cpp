#include "solver/home_seed.h"

#include <cmath>
#include <unordered_set>
#include <vector>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"

namespace ballbench {
namespace {

// home-seed's settings, each declared once: reading, settings() and `ballbench list --settings
// home-seed` come from these rows.
const SettingsTable<HomeSeedSettings>& home_seed_settings_table() {
  using S = HomeSeedSettings;
  static const SettingsTable<S> table(
      "home-seed",
      {choice("flags", &S::flags, {{SeedFlags::per_ball, "per-ball"}, {SeedFlags::per_pair, "per-pair"}},
              "in-ball flags per ball (appendix 1) or per pair (appendix 2)"),
       setting("clamp", &S::clamp, any_value, "", "put a ball that ends outside the box back inside (appendix 2)")});
  return table;
}

class HomeSeed final : public Engine {
 public:
  HomeSeed(const Scene& scene, HomeSeedSettings settings)
      : s_(std::move(settings)),
        n_(scene.n()),
        e_(scene.restitution),
        g_(scene.gravity),
        box_(scene.container),
        r_(scene.radius),
        m_(scene.mass),
        p_(scene.initial.pos),
        v_(scene.initial.vel),
        in_wall_(n_, 0),
        in_ball_(n_, 0) {
    if (s_.flags == SeedFlags::per_ball) {
      // Appendix 1, lines 65-74: balls spawned overlapping are flagged and cannot collide.
      for (int i = 0; i < n_; ++i)
        for (int j = i + 1; j < n_; ++j)
          if ((p_.row(i) - p_.row(j)).norm() <= r_(i) + r_(j)) in_ball_[i] = in_ball_[j] = 1;
    }
  }

  void step(double dt) override {
    t_ += dt;
    // Appendix 2, lines 74-78: velocity first, then position (semi-implicit Euler). With g = 0 this
    // is exactly appendix 1's `p = p + v*dt`.
    v_.rowwise() += (g_ * dt).transpose();
    p_ += v_ * dt;
    if (box_.kind == ContainerKind::Box) walls();
    s_.flags == SeedFlags::per_ball ? pairs_per_ball_flags() : pairs_per_pair_flags();
  }

  void read(State& out) const override {
    out.t = t_;
    out.pos = p_;
    out.vel = v_;
  }

  nlohmann::json settings() const override { return home_seed_settings_table().json(s_); }

 private:
  // Distance from the centre to the nearer of the two walls on `axis`: the thesis's `5 - abs(p)`
  // for its symmetric box [-5, 5].
  double wall_gap(int i, int axis) const {
    return std::min(p_(i, axis) - box_.min(axis), box_.max(axis) - p_(i, axis));
  }

  // Appendix 1, lines 88-104 (appendix 2, lines 86-117): the if/elseif chain in its order. A ball
  // still in the x wall has its flag cleared by the fourth branch when it is clear of the y walls,
  // and bounces again next step: the thesis's ball stuck in the wall.
  void walls() {
    for (int i = 0; i < n_; ++i) {
      const double r = r_(i);
      if (wall_gap(i, 0) <= r && !in_wall_[i]) {
        v_(i, 0) = -v_(i, 0);
        v_.row(i) *= e_;  // the factor scales the whole velocity, tangent included
        in_wall_[i] = 1;
      } else if (wall_gap(i, 1) <= r && !in_wall_[i]) {
        v_(i, 1) = -v_(i, 1);
        v_.row(i) *= e_;
        in_wall_[i] = 1;
      } else if (wall_gap(i, 0) > r && in_wall_[i]) {
        in_wall_[i] = 0;
      } else if (wall_gap(i, 1) > r && in_wall_[i]) {
        in_wall_[i] = 0;
      }
      if (s_.clamp) {
        for (int a = 0; a < 2; ++a) {
          if (p_(i, a) < box_.min(a) + r) p_(i, a) = box_.min(a) + r;
          if (p_(i, a) > box_.max(a) - r) p_(i, a) = box_.max(a) - r;
        }
      }
    }
  }

  // Thesis eq. 11-12 as the code writes them (appendix 1, lines 118-119): the factor multiplies v1
  // only, not the exchange term. The code assumes equal masses (2 m2 / (m1 + m2) = 1); the mass
  // factor is kept so that unequal masses follow eq. 11-12.
  void collide(int i, int j) {
    const Eigen::RowVector2d x1 = p_.row(i), x2 = p_.row(j), v1 = v_.row(i), v2 = v_.row(j);
    const Eigen::RowVector2d d = x1 - x2;
    const double d2 = d.squaredNorm();
    if (d2 == 0.0) return;  // coincident centres: MATLAB would produce NaN; the normal is undefined
    const double mi = m_(i), mj = m_(j);
    const double k = (v1 - v2).dot(d) / d2;
    v_.row(i) = e_ * v1 - (2 * mj / (mi + mj)) * k * d;
    v_.row(j) = e_ * v2 - (2 * mi / (mi + mj)) * k * (-d);
  }

  bool touching(int i, int j) const {
    const double rs = r_(i) + r_(j);
    return (p_.row(i) - p_.row(j)).squaredNorm() <= rs * rs;
  }

  // Appendix 1, lines 109-127: one flag per ball; a flagged ball cannot collide with anyone, and a
  // non-touching pair of flagged balls clears both flags.
  void pairs_per_ball_flags() {
    for (int i = 0; i < n_; ++i)
      for (int j = i + 1; j < n_; ++j) {
        const bool hit = touching(i, j);
        if (hit && !in_ball_[i] && !in_ball_[j]) {
          collide(i, j);
          in_ball_[i] = in_ball_[j] = 1;
        } else if (!hit && in_ball_[i] && in_ball_[j]) {
          in_ball_[i] = in_ball_[j] = 0;
        }
      }
  }

  // Appendix 2, lines 122-140: one flag per pair (a set of flagged pairs, not an n x n matrix).
  void pairs_per_pair_flags() {
    for (int i = 0; i < n_; ++i)
      for (int j = i + 1; j < n_; ++j) {
        const bool hit = touching(i, j);
        const long long key = static_cast<long long>(i) * n_ + j;
        if (hit && !pair_flag_.contains(key)) {
          collide(i, j);
          pair_flag_.insert(key);
        } else if (!hit) {
          pair_flag_.erase(key);
        }
      }
  }

  HomeSeedSettings s_;
  int n_;
  double e_;
  Eigen::Vector2d g_;
  Container box_;
  Eigen::VectorXd r_, m_;
  Eigen::MatrixX2d p_, v_;
  std::vector<char> in_wall_, in_ball_;
  std::unordered_set<long long> pair_flag_;
  double t_ = 0;
};

}  // namespace

EngineEntry home_seed_engine() {
  EngineInfo info;
  info.name = "home-seed";
  info.role = EngineRole::thesis;
  info.version = "thesis-2017";
  info.limits =
      "double; discrete collision checks once per step with per-ball (or per-pair) flags, as in the thesis: "
      "tunnels and sticks by design; O(n^2) pair loop";
  info.summary = "faithful port of the 2017 thesis's MATLAB programs (sticks and tunnels on purpose)";
  info.caps.any_restitution = true;
  info.caps.friction = false;  // frictionless disks: no rotation
  info.caps.continuous_collision = false;
  info.settings = home_seed_settings_table().describe();
  info.bench.sizes = {.free_balls = 1000, .fluid_balls = 1000, .settled_balls = 1000};  // O(n^2) by design
  return {info, [](const Scene& scene, const std::string&, const nlohmann::json& overrides) {
            HomeSeedSettings s;
            home_seed_settings_table().read(overrides, s);
            return std::unique_ptr<Engine>(std::make_unique<HomeSeed>(scene, s));
          }, {}};
}

}  // namespace ballbench

#include "metrics/metrics.h"

#include <algorithm>
#include <cmath>

#include "metrics/energy.h"
#include "metrics/momentum.h"
#include "metrics/tunnelling.h"

namespace ballbench {

MetricsAccumulator::MetricsAccumulator(const Scene& scene, MetricsConfig config)
    : scene_(scene),
      cfg_(config),
      sticking_(scene.n(), config.stuck_samples),
      slip_(scene, config.contact_tolerance, config.roll_tolerance),
      tunnelling_(scene.radius, scene.container, config.contact_tolerance),
      deep_in_wall_(scene.n(), 0),
      wall_leaving_(scene.n(), 0) {
  m_.energy.reference = energy_reference(scene);
  m_.angular_momentum.centre = angular_momentum_centre(scene);
}

void MetricsAccumulator::observe(const State& s) {
  const double e = total_energy(s, scene_, m_.energy.reference);
  const Eigen::Vector2d p = total_momentum(s, scene_.mass);
  const double l = angular_momentum(s, scene_, m_.angular_momentum.centre);
  if (m_.samples == 0) {
    m_.energy.initial = e;
    m_.momentum.initial = p;
    m_.angular_momentum.initial = l;
    ke0_ = kinetic_energy(s, scene_);
  }
  m_.energy.final = e;
  m_.energy.max_abs_drift = std::max(m_.energy.max_abs_drift, std::abs(e - m_.energy.initial));
  if (m_.energy.initial > 0) m_.energy.max_rel_drift = m_.energy.max_abs_drift / m_.energy.initial;
  m_.momentum.final = p;
  m_.momentum.max_abs_drift = std::max(m_.momentum.max_abs_drift, (p - m_.momentum.initial).norm());
  m_.angular_momentum.final = l;
  m_.angular_momentum.max_abs_drift =
      std::max(m_.angular_momentum.max_abs_drift, std::abs(l - m_.angular_momentum.initial));
  slip_.observe(s);
  m_.slip = slip_.summary();

  // Overlaps: penetration (every depth) and sticking (deeper than the tolerance).
  double sample_max = 0;  // this sample's deepest overlap / radius
  overlapping_pairs(s.pos, scene_.radius, overlap_scratch_, overlaps_);
  deep_.clear();
  deep_leaving_.clear();
  for (const Overlap& o : overlaps_) {
    const double rel = o.depth / std::min(scene_.radius(o.i), scene_.radius(o.j));
    penetration_sum_ += rel, ++penetration_count_;
    sample_max = std::max(sample_max, rel);
    if (o.depth > cfg_.contact_tolerance * (scene_.radius(o.i) + scene_.radius(o.j))) {
      deep_.push_back(o);
      const Eigen::Vector2d d = (s.pos.row(o.i) - s.pos.row(o.j)).transpose();
      const Eigen::Vector2d w = (s.vel.row(o.i) - s.vel.row(o.j)).transpose();
      deep_leaving_.push_back(d.dot(w) > 0);
    }
  }
  if (scene_.container.kind == ContainerKind::Box) {
    const Container& box = scene_.container;
    for (int i = 0; i < s.n(); ++i) {
      const double r = scene_.radius(i);
      // The nearest wall: its gap, and the ball's speed along that wall's inward normal.
      const double gaps[4] = {s.pos(i, 0) - box.min.x(), box.max.x() - s.pos(i, 0), s.pos(i, 1) - box.min.y(),
                              box.max.y() - s.pos(i, 1)};
      const double inward[4] = {s.vel(i, 0), -s.vel(i, 0), s.vel(i, 1), -s.vel(i, 1)};
      int k = 0;
      for (int w = 1; w < 4; ++w)
        if (gaps[w] < gaps[k]) k = w;
      const double gap = gaps[k];
      const double depth = r - gap;  // > 0: the ball is in a wall
      wall_leaving_[i] = inward[k] > 0;
      if (depth > 0) {
        penetration_sum_ += depth / r, ++penetration_count_;
        sample_max = std::max(sample_max, depth / r);
      }
      deep_in_wall_[i] = depth > cfg_.contact_tolerance * r;
    }
  }
  m_.penetration_max = std::max(m_.penetration_max, sample_max);
  sticking_.observe(deep_, deep_leaving_, deep_in_wall_, wall_leaving_);
  for (int i : sticking_.counted_walls()) keep({EventKind::StickWall, motion_steps_, s.t, i, -1, s.pos(i, 0), s.pos(i, 1)});
  for (const auto& [i, j] : sticking_.counted_pairs()) {
    const Eigen::Vector2d mid = 0.5 * (s.pos.row(i) + s.pos.row(j)).transpose();
    keep({EventKind::StickPair, motion_steps_, s.t, i, j, mid.x(), mid.y()});
  }
  m_.sticking_pair = sticking_.pair_events();
  m_.sticking_wall = sticking_.wall_events();
  m_.penetration_mean = penetration_count_ ? penetration_sum_ / penetration_count_ : 0.0;
  if (m_.samples == 0) m_.penetration_initial = m_.penetration_max;
  else m_.penetration_after_start = std::max(m_.penetration_after_start, sample_max);
  ++m_.samples;
}

bool MetricsAccumulator::observe_motion(const State& prev, const State& cur) {
  ++motion_steps_;
  const StepTunnelling t = tunnelling_.step(prev, cur);
  left_container_ = !t.contained;
  m_.tunnelling_wall += t.wall;
  m_.tunnelling_pair += t.pair;
  for (int i : tunnelling_.wall_hits()) {
    const Eigen::Vector2d at = wall_crossing(prev.pos.row(i).transpose(), cur.pos.row(i).transpose(), scene_.container);
    keep({EventKind::TunnelWall, motion_steps_, cur.t, i, -1, at.x(), at.y()});
  }
  for (const auto& [i, j] : tunnelling_.pair_hits()) {
    const Eigen::Vector2d d0 = (prev.pos.row(i) - prev.pos.row(j)).transpose();
    const Eigen::Vector2d d1 = (cur.pos.row(i) - cur.pos.row(j)).transpose();
    const double s = closest_approach_fraction(d0, d1);
    const Eigen::Vector2d mid =
        0.5 * ((1 - s) * (prev.pos.row(i) + prev.pos.row(j)) + s * (cur.pos.row(i) + cur.pos.row(j))).transpose();
    keep({EventKind::TunnelPair, motion_steps_, cur.t, i, j, mid.x(), mid.y()});
  }
  return t.finite && (!cur.rotates() || (cur.w.allFinite() && cur.angle.allFinite()));
}

void MetricsAccumulator::keep(const Event& e) {
  if (events_.size() < kEventsKept) events_.push_back(e);
}

bool MetricsAccumulator::energy_blew_up() const {
  const double base = m_.energy.initial + ke0_;  // zero only for a scene with nothing moving or falling
  return base > 0 && m_.energy.final > cfg_.divergence_energy_factor * base;
}

}  // namespace ballbench

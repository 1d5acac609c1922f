// Tunnelling (metrics/tunnelling.h) over every step's motion: balls through a wall and pairs
// through each other, with where and when. The same sweep over the states finds a position,
// velocity or spin that is not finite and a ball that left the container: the run stops there.
#include <fmt/format.h>

#include "metrics/meter.h"
#include "metrics/tunnelling.h"

namespace ballbench {
namespace {

class TunnellingMeter final : public Meter {
 public:
  TunnellingMeter(const Scene& scene, const MetricsConfig& config)
      : scene_(scene), check_(scene.radius, scene.container, config.contact_tolerance) {}

  void motion(const State& prev, const State& cur, long step, EventLog& log) override {
    const StepTunnelling t = check_.step(prev, cur);
    finite_ = t.finite && (!cur.rotates() || (cur.w.allFinite() && cur.angle.allFinite()));
    left_container_ = !t.contained;
    wall_ += t.wall, pair_ += t.pair;
    for (int i : check_.wall_hits()) {
      const Eigen::Vector2d at =
          wall_crossing(prev.pos.row(i).transpose(), cur.pos.row(i).transpose(), scene_.container);
      log.keep({EventKind::TunnelWall, step, cur.t, i, -1, at.x(), at.y()});
    }
    for (const auto& [i, j] : check_.pair_hits()) {
      const Eigen::Vector2d d0 = (prev.pos.row(i) - prev.pos.row(j)).transpose();
      const Eigen::Vector2d d1 = (cur.pos.row(i) - cur.pos.row(j)).transpose();
      const double s = closest_approach_fraction(d0, d1);
      const Eigen::Vector2d mid =
          0.5 * ((1 - s) * (prev.pos.row(i) + prev.pos.row(j)) + s * (cur.pos.row(i) + cur.pos.row(j))).transpose();
      log.keep({EventKind::TunnelPair, step, cur.t, i, j, mid.x(), mid.y()});
    }
  }

  // A ball out of the box: no figure of the run means anything from there, as after a state that
  // is not finite.
  std::optional<std::string> stop() const override {
    if (!finite_) return "non-finite position or velocity";
    if (left_container_) return "a ball left the container (beyond a wall by more than its diameter)";
    return std::nullopt;
  }

  void write(MetricValues& out) const override {
    out.set(Metric::tunnelling_wall, wall_);
    out.set(Metric::tunnelling_pair, pair_);
  }

 private:
  const Scene& scene_;
  TunnellingCheck check_;
  bool finite_ = true, left_container_ = false;
  int wall_ = 0, pair_ = 0;
};

}  // namespace

MetricFamily tunnelling_metric() {
  MetricFamily f;
  f.name = "tunnelling";
  f.order = 40;
  f.stage = MetricStage::motion;
  f.rows = {
      shown(metric_row(Metric::tunnelling_wall, "",
                       fixed("balls whose centre went from inside the box to beyond a wall between two samples"), kExact),
            "tunnelling wall", "tun.wall", true),
      shown(metric_row(Metric::tunnelling_pair, "",
                       [](const MetricsConfig& cfg) {
                         return fmt::format(
                             "pairs apart in two consecutive samples whose relative motion, taken as a straight line "
                             "between them, came closer than {:.0f}% of their radius sum less (|dv_i| + |dv_j|) h / 4 "
                             "(dv: each ball's change of velocity between the samples, h: the time between them; a "
                             "path bent once by a collision strays at most that far from the straight line): they "
                             "passed through each other. A resolved bounce never counts; a ball that collides several "
                             "times within one sample interval can still fool the test, so `exact`'s count on a scene "
                             "is the floor",
                             100 * (1 - cfg.contact_tolerance));
                       },
                       kExact),
            "tunnelling pair", "tun.pair", true),
      total_row("tunnelling", "tunnelling events, walls and pairs together", &MetricValues::tunnelled),
  };
  f.make = [](const Scene& scene, const MetricsConfig& config) {
    return std::make_unique<TunnellingMeter>(scene, config);
  };
  return f;
}

}  // namespace ballbench

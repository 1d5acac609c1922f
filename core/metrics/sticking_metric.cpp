// Sticking (metrics/sticking.h) over the sampled states: episodes of a pair, or a ball in a wall,
// staying deeper than the contact tolerance, each counted once, with where and when.
#include <fmt/format.h>

#include "metrics/meter.h"
#include "metrics/sticking.h"

namespace ballbench {
namespace {

class StickingMeter final : public Meter {
 public:
  StickingMeter(const Scene& scene, const MetricsConfig& config)
      : scene_(scene),
        tolerance_(config.contact_tolerance),
        tracker_(scene.n(), config.stuck_samples),
        deep_in_wall_(scene.n(), 0),
        wall_leaving_(scene.n(), 0) {}

  void sample(SampleView& v, EventLog& log) override {
    const State& s = v.state;
    deep_.clear(), deep_leaving_.clear();
    for (const Overlap& o : v.overlaps())
      if (o.depth > tolerance_ * (scene_.radius(o.i) + scene_.radius(o.j))) {
        deep_.push_back(o);
        const Eigen::Vector2d d = (s.pos.row(o.i) - s.pos.row(o.j)).transpose();
        const Eigen::Vector2d w = (s.vel.row(o.i) - s.vel.row(o.j)).transpose();
        deep_leaving_.push_back(d.dot(w) > 0);
      }
    const std::vector<NearestWall>& walls = v.walls();
    for (size_t i = 0; i < walls.size(); ++i) {
      const double r = scene_.radius(static_cast<Eigen::Index>(i));
      wall_leaving_[i] = walls[i].inward_speed > 0;
      deep_in_wall_[i] = r - walls[i].gap > tolerance_ * r;
    }
    tracker_.observe(deep_, deep_leaving_, deep_in_wall_, wall_leaving_);
    for (int i : tracker_.counted_walls()) log.keep({EventKind::StickWall, v.step, s.t, i, -1, s.pos(i, 0), s.pos(i, 1)});
    for (const auto& [i, j] : tracker_.counted_pairs()) {
      const Eigen::Vector2d mid = 0.5 * (s.pos.row(i) + s.pos.row(j)).transpose();
      log.keep({EventKind::StickPair, v.step, s.t, i, j, mid.x(), mid.y()});
    }
  }

  void write(MetricValues& out) const override {
    out.set(Metric::sticking_wall, tracker_.wall_events());
    out.set(Metric::sticking_pair, tracker_.pair_events());
  }

 private:
  const Scene& scene_;
  double tolerance_;
  StickingTracker tracker_;
  std::vector<Overlap> deep_;
  std::vector<char> deep_leaving_, deep_in_wall_, wall_leaving_;
};

std::function<std::string(const MetricsConfig&)> definition(std::string what, std::string depth_of) {
  return [what, depth_of](const MetricsConfig& cfg) {
    return fmt::format("{} overlapping deeper than {:.0f}% of its {} for more than {} consecutive samples, and not "
                       "moving out at a sample past that; one event per episode (a pair placed overlapping that is "
                       "moving apart is leaving, not stuck)",
                       what, 100 * cfg.contact_tolerance, depth_of, cfg.stuck_samples);
  };
}

}  // namespace

MetricFamily sticking_metric() {
  MetricFamily f;
  f.name = "sticking";
  f.order = 50;
  f.stage = MetricStage::sample;
  f.rows = {
      shown(metric_row(Metric::sticking_wall, "", definition("a ball", "radius (in a wall)"), kExact), "sticking wall",
            "stk.wall", true),
      shown(metric_row(Metric::sticking_pair, "", definition("a pair", "radius sum"), kExact), "sticking pair", "stk.pair",
            true),
      total_row("sticking", "sticking episodes, walls and pairs together", &MetricValues::stuck),
  };
  f.make = [](const Scene& scene, const MetricsConfig& config) { return std::make_unique<StickingMeter>(scene, config); };
  return f;
}

}  // namespace ballbench

// Penetration over the sampled states: how deep balls sink into each other and into the walls,
// as a fraction of the radius (a pair's smaller one), deepest and mean; the first sample's apart
// (a placement that starts overlapping is the same for every engine).
#include <algorithm>

#include "metrics/meter.h"

namespace ballbench {
namespace {

class PenetrationMeter final : public Meter {
 public:
  explicit PenetrationMeter(const Scene& scene) : scene_(scene) {}

  void sample(SampleView& v, EventLog&) override {
    double sample_max = 0;  // this sample's deepest overlap / radius
    for (const Overlap& o : v.overlaps()) {
      const double rel = o.depth / std::min(scene_.radius(o.i), scene_.radius(o.j));
      sum_ += rel, ++count_;
      sample_max = std::max(sample_max, rel);
    }
    const std::vector<NearestWall>& walls = v.walls();
    for (size_t i = 0; i < walls.size(); ++i) {
      const double r = scene_.radius(static_cast<Eigen::Index>(i));
      const double depth = r - walls[i].gap;  // > 0: the ball is in a wall
      if (depth > 0) sum_ += depth / r, ++count_, sample_max = std::max(sample_max, depth / r);
    }
    max_ = std::max(max_, sample_max);
    if (v.first) initial_ = max_;
    else after_start_ = std::max(after_start_, sample_max);
  }

  void write(MetricValues& out) const override {
    out.set(Metric::penetration_max, max_);
    out.set(Metric::penetration_mean, count_ ? sum_ / static_cast<double>(count_) : 0.0);
    out.set(Metric::penetration_initial, initial_);
    out.set(Metric::penetration_after_start, after_start_);
  }

 private:
  const Scene& scene_;
  double sum_ = 0, max_ = 0, initial_ = 0, after_start_ = 0;
  long count_ = 0;
};

}  // namespace

MetricFamily penetration_metric() {
  MetricFamily f;
  f.name = "penetration";
  f.order = 60;
  f.stage = MetricStage::sample;
  MetricDef max = shown(metric_row(Metric::penetration_max, "",
                                   fixed("the deepest overlap over every contact in every sample, divided by the "
                                         "radius (the smaller one for a pair)"),
                                   kReal),
                        "penetration max", "pen.max", true, MeaningfulOn::no_scene);
  // What the engine lets balls sink, not the placement's overlap: the ensembles' column.
  MetricDef after_start = shown(metric_row(Metric::penetration_after_start, "",
                                           fixed("penetration max over every sample after the first: how deep the "
                                                 "engine lets balls sink (the accuracy spec's `overlap`)")),
                                "penetration after start", "", true);
  after_start.ensemble = "overlap";
  f.rows = {
      max,
      shown(metric_row(Metric::penetration_mean, "", fixed("the mean of the same over every overlapping contact in every sample"),
                       kReal),
            "penetration mean", "", true, MeaningfulOn::no_scene),
      shown(metric_row(Metric::penetration_initial, "",
                       fixed("penetration max of the first sample alone: how deep the placement starts overlapping, "
                             "the same for every engine")),
            "initial overlap", "", false, MeaningfulOn::no_scene),
      after_start,
  };
  f.make = [](const Scene& scene, const MetricsConfig&) { return std::make_unique<PenetrationMeter>(scene); };
  return f;
}

}  // namespace ballbench

// Linear and angular momentum (metrics/momentum.h) over the sampled states: start, end, drift.
// Reported everywhere; judged only in open space without gravity, where they are conserved.
#include <cmath>

#include "metrics/meter.h"
#include "metrics/momentum.h"

namespace ballbench {
namespace {

nlohmann::json vec_json(const Eigen::Vector2d& v) { return nlohmann::json::array({v.x(), v.y()}); }

class MomentumMeter final : public Meter {
 public:
  explicit MomentumMeter(const Scene& scene) : scene_(scene), centre_(angular_momentum_centre(scene)) {}

  void sample(SampleView& v, EventLog&) override {
    const Eigen::Vector2d p = total_momentum(v.state, scene_.mass);
    const double l = angular_momentum(v.state, scene_, centre_);
    if (v.first) p0_ = p, l0_ = l;
    p_ = p, l_ = l;
    p_drift_ = std::max(p_drift_, (p - p0_).norm());
    l_drift_ = std::max(l_drift_, std::abs(l - l0_));
  }

  void write(MetricValues& out) const override {
    out.set(Metric::momentum_initial, vec_json(p0_));
    out.set(Metric::momentum_final, vec_json(p_));
    out.set(Metric::momentum_max_abs_drift, p_drift_);
    out.set(Metric::angular_momentum_centre, vec_json(centre_));
    out.set(Metric::angular_momentum_initial, l0_);
    out.set(Metric::angular_momentum_final, l_);
    out.set(Metric::angular_momentum_max_abs_drift, l_drift_);
  }

 private:
  const Scene& scene_;
  Eigen::Vector2d centre_, p0_{0, 0}, p_{0, 0};
  double l0_ = 0, l_ = 0, p_drift_ = 0, l_drift_ = 0;
};

}  // namespace

MetricFamily momentum_metric() {
  MetricFamily f;
  f.name = "momentum";
  f.order = 20;
  f.stage = MetricStage::sample;
  f.rows = {
      metric_row(Metric::momentum_initial, "kg m/s", fixed("P0: P = sum m v at the start")),
      metric_row(Metric::momentum_final, "kg m/s", fixed("P at the last sample")),
      shown(metric_row(Metric::momentum_max_abs_drift, "kg m/s",
                       fixed("max over samples of |P - P0|. Conserved only in open space without gravity; walls and "
                             "gravity change it"),
                       kReal),
            "momentum drift (max abs)", "P drift", false, MeaningfulOn::open_space_without_gravity),
      metric_row(Metric::angular_momentum_centre, "m",
                 fixed("c, the fixed point angular momentum is taken about: the container's centre, or the initial "
                       "centre of mass in open space")),
      metric_row(Metric::angular_momentum_initial, "kg m^2/s",
                 fixed("L0: L = sum m (x - c) x v + I w at the start, orbital plus spin, counter-clockwise"), kReal),
      metric_row(Metric::angular_momentum_final, "kg m^2/s", fixed("L at the last sample"), kReal),
      shown(metric_row(Metric::angular_momentum_max_abs_drift, "kg m^2/s",
                       fixed("max over samples of |L - L0|. Friction trades orbit for spin and keeps the sum: "
                             "conserved in open space without gravity at any friction; walls and gravity change it"),
                       kReal),
            "angular momentum drift (max abs)", "L drift", false, MeaningfulOn::open_space_without_gravity),
  };
  f.applies = [](const Scene& scene) {
    const SceneFeatures ft = scene.features();
    return Applies{true, ft.gravity || ft.walls
                             ? "momentum drift is reported but not judged: walls and gravity change momentum"
                             : ""};
  };
  f.make = [](const Scene& scene, const MetricsConfig&) { return std::make_unique<MomentumMeter>(scene); };
  return f;
}

}  // namespace ballbench

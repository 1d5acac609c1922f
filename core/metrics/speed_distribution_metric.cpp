// The final speeds against the 2D Maxwell-Boltzmann (Rayleigh) law (metrics/speed_distribution.h):
// elastic, gravity-free scenes of 100+ equal balls.
#include "metrics/meter.h"
#include "metrics/speed_distribution.h"

namespace ballbench {
namespace {

class SpeedDistributionMeter final : public Meter {
 public:
  explicit SpeedDistributionMeter(int n) : critical_(rayleigh_ks_critical(n)) {}
  void final_state(const State& s) override { ks_ = rayleigh_ks_statistic(s); }
  void write(MetricValues& out) const override {
    out.set(Metric::speed_ks, ks_);
    out.set(Metric::speed_ks_critical, critical_);
  }

 private:
  double critical_, ks_ = 0;
};

}  // namespace

MetricFamily speed_distribution_metric() {
  MetricFamily f;
  f.name = "speed_distribution";
  f.order = 100;
  f.stage = MetricStage::final_state;
  f.rows = {
      metric_row(Metric::speed_ks, "",
                 fixed("the Kolmogorov-Smirnov statistic of the final speeds against the 2D Maxwell-Boltzmann "
                       "(Rayleigh) law, for elastic, gravity-free scenes of 100+ equal balls")),
      metric_row(Metric::speed_ks_critical, "", fixed("the statistic's 1% critical value, 1.63 / sqrt(n)")),
  };
  f.applies = [](const Scene& scene) {
    if (speed_distribution_applies(scene)) return Applies{};
    return Applies{false,
                   "speed distribution (Rayleigh KS): only for elastic, gravity-free, equal-mass scenes of >= 100 balls"};
  };
  f.make = [](const Scene& scene, const MetricsConfig&) { return std::make_unique<SpeedDistributionMeter>(scene.n()); };
  return f;
}

}  // namespace ballbench

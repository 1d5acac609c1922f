// Jitter: the RMS speed of the final state, for scenes with gravity and walls, where balls should
// come to rest (a pile).
#include <cmath>

#include "metrics/meter.h"

namespace ballbench {
namespace {

class JitterMeter final : public Meter {
 public:
  void final_state(const State& s) override { jitter_ = std::sqrt(s.vel.rowwise().squaredNorm().mean()); }
  void write(MetricValues& out) const override { out.set(Metric::jitter, jitter_); }

 private:
  double jitter_ = 0;
};

}  // namespace

MetricFamily jitter_metric() {
  MetricFamily f;
  f.name = "jitter";
  f.order = 70;
  f.stage = MetricStage::final_state;
  f.rows = {metric_row(Metric::jitter, "m/s",
                       fixed("the RMS speed of the final state, for scenes with gravity and walls, where balls should "
                             "come to rest (a pile)"))};
  f.applies = [](const Scene& scene) {
    if (scene.features().gravity && scene.features().walls) return Applies{};
    return Applies{false, "jitter (final RMS speed): only for scenes with gravity and walls, where balls come to rest"};
  };
  f.make = [](const Scene&, const MetricsConfig&) { return std::make_unique<JitterMeter>(); };
  return f;
}

}  // namespace ballbench

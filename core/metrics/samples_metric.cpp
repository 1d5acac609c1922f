// The states the sampled metrics saw.
#include "metrics/meter.h"

namespace ballbench {
namespace {

class SamplesMeter final : public Meter {
 public:
  void sample(SampleView&, EventLog&) override { ++samples_; }
  void write(MetricValues& out) const override { out.set(Metric::samples, samples_); }

 private:
  long samples_ = 0;
};

}  // namespace

MetricFamily samples_metric() {
  MetricFamily f;
  f.name = "samples";
  f.order = 0;
  f.stage = MetricStage::sample;
  f.rows = {metric_row(Metric::samples, "", fixed("the states the sampled metrics saw (every k-th step and the last)"))};
  f.make = [](const Scene&, const MetricsConfig&) { return std::make_unique<SamplesMeter>(); };
  return f;
}

}  // namespace ballbench

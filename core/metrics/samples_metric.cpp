// The states the sampled metrics saw, and the run's figures that come from outside its states
// (the error against the reference, the step time) as the seed ensembles summarise them.
#include "metrics/meter.h"
#include "result.h"

namespace ballbench {
namespace {

class SamplesMeter final : public Meter {
 public:
  void sample(SampleView&, EventLog&) override { ++samples_; }
  void write(MetricValues& out) const override { out.set("samples", samples_); }

 private:
  long samples_ = 0;
};

}  // namespace

MetricFamily samples_metric() {
  MetricFamily f;
  f.name = "samples";
  f.order = 0;
  f.stage = MetricStage::sample;
  MetricDef pos_err = metric_row("", "m", fixed("position RMS error against the reference at the last step"));
  pos_err.ensemble = "pos.err";
  pos_err.meaningful = MeaningfulOn::predictable_scenes;
  pos_err.get = [](const Result& r) {
    return r.reference.reference.empty() ? nlohmann::json() : nlohmann::json(r.reference.pos_rms_final);
  };
  MetricDef cost = metric_row("", "ns", fixed("the engine's own step time per ball per step"));
  cost.ensemble = "ns/ball-step";
  cost.get = [](const Result& r) { return nlohmann::json(r.ns_per_ball_step); };
  f.rows = {metric_row("samples", "", fixed("the states the sampled metrics saw (every k-th step and the last)")),
            pos_err, cost};
  f.make = [](const Scene&, const MetricsConfig&) { return std::make_unique<SamplesMeter>(); };
  return f;
}

}  // namespace ballbench

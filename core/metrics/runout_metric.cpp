// The final heap's runout (scenes that ask for `runout`; metrics/runout.h).
#include <fmt/format.h>

#include "metrics/meter.h"
#include "metrics/runout.h"

namespace ballbench {
namespace {

class RunoutMeter final : public Meter {
 public:
  explicit RunoutMeter(const Scene& scene) : scene_(scene) {}
  void final_state(const State& s) override { runout_ = runout(s, scene_.radius); }
  void write(MetricValues& out) const override {
    out.set(Metric::runout, runout_ ? nlohmann::json(*runout_) : nlohmann::json());
  }

 private:
  const Scene& scene_;
  std::optional<double> runout_;
};

}  // namespace

MetricFamily runout_metric() {
  MetricFamily f;
  f.name = "runout";
  f.order = 91;
  f.stage = MetricStage::final_state;
  f.rows = {shown(metric_row(Metric::runout, "m",
                             fixed(fmt::format(
                                 "the length of the final heap's deposit on the floor (scenes that ask for `runout`): "
                                 "the balls in order along the floor, a deposit is a run of them in which each ball's "
                                 "left edge lies within {:g} mean diameter of the farthest right edge before it; the "
                                 "heap's is the run that holds the highest ball, its length from its leftmost edge to "
                                 "its rightmost (balls that rolled away from the heap are not in it)",
                                 kRunoutGap)),
                             kReal),
                  "runout (m)", "runout", false)};
  f.applies = [](const Scene& scene) { return Applies{scene.metrics.runout, ""}; };
  f.make = [](const Scene& scene, const MetricsConfig&) { return std::make_unique<RunoutMeter>(scene); };
  return f;
}

}  // namespace ballbench

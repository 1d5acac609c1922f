// Slip at the walls (metrics/slip.h) over the sampled states: the last sample's largest, and the
// time from which every ball on a wall rolls. Scenes that rotate and have walls.
#include <fmt/format.h>

#include "metrics/meter.h"
#include "metrics/slip.h"

namespace ballbench {
namespace {

class SlipMeter final : public Meter {
 public:
  SlipMeter(const Scene& scene, const MetricsConfig& config)
      : tracker_(scene, config.contact_tolerance, config.roll_tolerance) {}
  void sample(SampleView& v, EventLog&) override { tracker_.observe(v.state); }
  void write(MetricValues& out) const override {
    const SlipSummary s = tracker_.summary();
    out.set(Metric::slip_final_max, s.final_max);
    out.set(Metric::slip_time_to_roll, s.time_to_roll ? nlohmann::json(*s.time_to_roll) : nlohmann::json());
  }

 private:
  SlipTracker tracker_;
};

}  // namespace

MetricFamily slip_metric() {
  MetricFamily f;
  f.name = "slip";
  f.order = 30;
  f.stage = MetricStage::sample;
  f.rows = {
      shown(metric_row(Metric::slip_final_max, "m/s",
                       [](const MetricsConfig& cfg) {
                         return fmt::format(
                             "the largest slip |v . t - w r| (the speed of the contact point along the wall; t: the "
                             "wall's inward normal turned a quarter counter-clockwise) of a ball within r (1 + {:g}%) "
                             "of a wall, at the last sample: 0 when every such ball rolls. Scenes that rotate and have "
                             "walls",
                             100 * cfg.contact_tolerance);
                       },
                       kReal),
            "slip at end (m/s)", "slip", true),
      shown(metric_row(Metric::slip_time_to_roll, "s",
                       [](const MetricsConfig& cfg) {
                         return fmt::format("the time from which on no ball on a wall slips faster than {:g} m/s "
                                            "(never, null in the JSON: the last sample still slips)",
                                            cfg.roll_tolerance);
                       },
                       kReal),
            "time to roll (s)", "t.roll", false),
  };
  f.rows.back().null_text = "never";
  f.applies = [](const Scene& scene) {
    if (scene.features().rotation && scene.container.kind == ContainerKind::Box) return Applies{};
    return Applies{false, "slip and time to roll: only for scenes that rotate and have walls"};
  };
  f.make = [](const Scene& scene, const MetricsConfig& config) { return std::make_unique<SlipMeter>(scene, config); };
  return f;
}

}  // namespace ballbench

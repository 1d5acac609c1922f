// One ball on the floor (scenes that ask for `rolling`): its final speed along x, beside the
// closed forms it is judged against (metrics/rolling.h).
#include "metrics/meter.h"
#include "metrics/rolling.h"

namespace ballbench {
namespace {

class RollingMeter final : public Meter {
 public:
  explicit RollingMeter(const Scene& scene) : closed_(rolling_closed_form(scene)) {}
  void final_state(const State& s) override { speed_ = s.vel(0, 0); }
  void write(MetricValues& out) const override {
    out.set("rolling.speed", speed_);
    out.set("rolling.expected_speed", closed_.speed);
    out.set("rolling.expected_time_to_roll",
            closed_.time_to_roll ? nlohmann::json(*closed_.time_to_roll) : nlohmann::json());
  }

 private:
  RollingClosedForm closed_;
  double speed_ = 0;
};

}  // namespace

MetricFamily rolling_metric() {
  MetricFamily f;
  f.name = "rolling";
  f.order = 80;
  f.stage = MetricStage::final_state;
  // The closed forms are the scene's, the same in every row: the friction section states them once
  // above its table, and the scene's table leaves them to its appendix.
  f.rows = {
      shown(metric_row("rolling.speed", "m/s",
                       fixed("one ball on the floor (scenes that ask for `rolling`): its velocity along x in the final "
                             "state, to judge against the closed form"),
                       kReal),
            "final speed (m/s)", "v.final", false),
      shown(metric_row("rolling.expected_speed", "m/s",
                       fixed("the closed form it must end at, rolling: v_roll = (v0 - k r w0) / (1 + k) for I = k m "
                             "r^2 (its angular momentum about the contact point is kept; slide to roll: v0 / (1 + k))"),
                       kReal),
            "closed-form speed (m/s)", "", false, MeaningfulOn::no_scene),
      shown(metric_row("rolling.expected_time_to_roll", "s",
                       fixed("the closed form of the time it starts to roll: the slip u = v + w r after its first "
                             "contact over mu g (1 + 1 / k), the rate sliding friction takes it off (slide to roll: v0 "
                             "k / ((1 + k) mu g)); a drop with restitution 0 adds the fall and the impact's Coulomb "
                             "impulse; none for a ball that bounces"),
                       kReal),
            "closed-form time to roll (s)", "", false, MeaningfulOn::no_scene),
  };
  f.applies = [](const Scene& scene) { return Applies{scene.metrics.rolling, ""}; };
  f.make = [](const Scene& scene, const MetricsConfig&) { return std::make_unique<RollingMeter>(scene); };
  return f;
}

}  // namespace ballbench

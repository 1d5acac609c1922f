// Balls on the floor (scenes that ask for `rolling`): each ball's final speed along x against its own
// closed form (metrics/rolling.h), reported for the ball farthest from it, the one that decides
// whether the scene's balls roll as they must.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "metrics/meter.h"
#include "metrics/rolling.h"

namespace ballbench {
namespace {

class RollingMeter final : public Meter {
 public:
  explicit RollingMeter(const Scene& scene) {
    for (int i = 0; i < scene.n(); ++i) closed_.push_back(rolling_closed_form(scene, i));
    // The scene's balls all roll by the latest of their times; a ball that bounces has none, so
    // neither has the scene.
    for (const RollingClosedForm& c : closed_) {
      if (!c.time_to_roll) {
        latest_roll_.reset();
        break;
      }
      latest_roll_ = std::max(latest_roll_.value_or(0.0), *c.time_to_roll);
    }
  }

  void final_state(const State& s) override {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double worst_rank = -1;
    worst_ = -1;
    for (int i = 0; i < static_cast<int>(closed_.size()); ++i) {
      const double expected = closed_[i].speed, v = s.vel(i, 0);
      // A closed form of 0 has no relative error, nor has a velocity that is not a number: either
      // ranks above every measured one and leaves the scene's error none.
      const double error = expected == 0 ? kInf : std::abs(v - expected) / std::abs(expected);
      const double rank = std::isnan(error) ? kInf : error;
      if (rank > worst_rank) worst_ = i, worst_rank = rank, speed_ = v, error_ = error;
    }
  }

  void write(MetricValues& out) const override {
    const bool measured = worst_ >= 0;
    out.set(Metric::rolling_speed, measured ? nlohmann::json(speed_) : nlohmann::json());
    out.set(Metric::rolling_expected_speed, measured ? nlohmann::json(closed_[worst_].speed) : nlohmann::json());
    out.set(Metric::rolling_error, measured && std::isfinite(error_) ? nlohmann::json(error_) : nlohmann::json());
    out.set(Metric::rolling_expected_time_to_roll, latest_roll_ ? nlohmann::json(*latest_roll_) : nlohmann::json());
  }

 private:
  std::vector<RollingClosedForm> closed_;
  std::optional<double> latest_roll_;
  int worst_ = -1;  // the ball farthest from its closed form; -1 before the final state
  double speed_ = 0, error_ = 0;
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
      shown(metric_row(Metric::rolling_speed, "m/s",
                       fixed("balls on the floor (scenes that ask for `rolling`): the velocity along x in the final "
                             "state of the ball farthest from its closed form (the largest relative error, below), "
                             "the only ball of a one-ball scene"),
                       kReal),
            "final speed (m/s)", "v.final", false),
      shown(metric_row(Metric::rolling_expected_speed, "m/s",
                       fixed("the closed form that ball must end at, rolling: v_roll = (v0 - k r w0) / (1 + k) for "
                             "I = k m r^2 (its angular momentum about the contact point is kept; slide to roll: v0 / "
                             "(1 + k))"),
                       kReal),
            "closed-form speed (m/s)", "", false, MeaningfulOn::no_scene),
      shown(metric_row(Metric::rolling_error, "",
                       fixed("the largest relative error of a ball's final velocity along x against its own closed "
                             "form, |v - v_roll| / |v_roll| over the balls (the accuracy spec's `rolling`); none "
                             "when a ball's closed form is 0"),
                       kReal),
            "closed-form error", "roll.err", true),
      shown(metric_row(Metric::rolling_expected_time_to_roll, "s",
                       fixed("the closed form of the time the balls all roll by, the latest over the balls: each "
                             "ball's slip u = v + w r after its first contact over mu g (1 + 1 / k), the rate sliding "
                             "friction takes it off (slide to roll: v0 k / ((1 + k) mu g)); a drop with restitution 0 "
                             "adds the fall and the impact's Coulomb impulse; none when a ball bounces"),
                       kReal),
            "closed-form time to roll (s)", "", false, MeaningfulOn::no_scene),
  };
  f.applies = [](const Scene& scene) { return Applies{scene.metrics.rolling, ""}; };
  f.make = [](const Scene& scene, const MetricsConfig&) { return std::make_unique<RollingMeter>(scene); };
  return f;
}

}  // namespace ballbench

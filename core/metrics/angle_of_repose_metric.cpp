// The final heap's angle of repose (scenes that ask for `angle_of_repose`; metrics/angle_of_repose.h).
#include <fmt/format.h>

#include "metrics/angle_of_repose.h"
#include "metrics/meter.h"

namespace ballbench {
namespace {

class AngleOfReposeMeter final : public Meter {
 public:
  explicit AngleOfReposeMeter(const Scene& scene) : scene_(scene) {}
  void final_state(const State& s) override { angle_ = angle_of_repose(s, scene_), done_ = true; }
  void write(MetricValues& out) const override {
    out.set(Metric::angle_of_repose, angle_ ? nlohmann::json(*angle_) : nlohmann::json());
  }
  std::vector<std::string> notes() const override {
    if (!done_ || angle_) return {};
    return {fmt::format("{}: no flank of the final heap had {} columns within [{:g} H, {:g} H] of its height H (a "
                        "layer spread flat, or a column standing)",
                        kReposeUnmeasuredNote, kReposeMinColumns, kReposeBandLow, kReposeBandHigh)};
  }

 private:
  const Scene& scene_;
  std::optional<double> angle_;
  bool done_ = false;
};

}  // namespace

MetricFamily angle_of_repose_metric() {
  MetricFamily f;
  f.name = "angle_of_repose";
  f.order = 90;
  f.stage = MetricStage::final_state;
  f.rows = {shown(metric_row(Metric::angle_of_repose, "deg",
                             fixed(fmt::format(
                                 "the slope of the final heap's flanks (scenes that ask for `angle_of_repose`): the "
                                 "floor cut into columns one mean diameter wide, each column's height the top of its "
                                 "highest ball; on each side of the highest column (height H), a least-squares line "
                                 "through the columns from it outward whose height is within [{0:g} H, {1:g} H] (at "
                                 "least {2}; the walk stops at the first column below {0:g} H), its angle atan "
                                 "|slope|; the mean over both flanks (none: neither had {2} columns in the band). A "
                                 "heap spread flat measures near 0, or none",
                                 kReposeBandLow, kReposeBandHigh, kReposeMinColumns)),
                             kReal),
                  "angle of repose (deg)", "repose", false)};
  f.applies = [](const Scene& scene) { return Applies{scene.metrics.angle_of_repose, ""}; };
  f.make = [](const Scene& scene, const MetricsConfig&) { return std::make_unique<AngleOfReposeMeter>(scene); };
  return f;
}

}  // namespace ballbench

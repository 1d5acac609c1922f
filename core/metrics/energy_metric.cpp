// Energy (metrics/energy.h) over the sampled states: its start, its end, its drift; a run whose
// energy grows past MetricsConfig::divergence_energy_factor has blown up and stops.
#include <cmath>

#include <fmt/format.h>

#include "metrics/energy.h"
#include "metrics/meter.h"
#include "result.h"

namespace ballbench {
namespace {

class EnergyMeter final : public Meter {
 public:
  EnergyMeter(const Scene& scene, const MetricsConfig& config)
      : scene_(scene), factor_(config.divergence_energy_factor), reference_(energy_reference(scene)) {}

  void sample(SampleView& v, EventLog&) override {
    const double e = total_energy(v.state, scene_, reference_);
    if (v.first) initial_ = e, ke0_ = kinetic_energy(v.state, scene_);
    final_ = e;
    max_abs_drift_ = std::max(max_abs_drift_, std::abs(e - initial_));
  }

  // Zero only for a scene with nothing moving or falling.
  std::optional<std::string> stop() const override {
    const double base = initial_ + ke0_;
    if (base > 0 && final_ > factor_ * base) return fmt::format("energy above {} x its initial value", factor_);
    return std::nullopt;
  }

  void write(MetricValues& out) const override {
    out.set(Metric::energy_initial, initial_);
    out.set(Metric::energy_final, final_);
    out.set(Metric::energy_max_rel_drift, initial_ > 0 ? nlohmann::json(max_abs_drift_ / initial_) : nlohmann::json());
    out.set(Metric::energy_max_abs_drift, max_abs_drift_);
    out.set(Metric::energy_reference, reference_);
  }

 private:
  const Scene& scene_;
  double factor_, reference_;
  double initial_ = 0, final_ = 0, max_abs_drift_ = 0, ke0_ = 0;
};

}  // namespace

MetricFamily energy_metric() {
  MetricFamily f;
  f.name = "energy";
  f.order = 10;
  f.stage = MetricStage::sample;
  MetricDef e_final_ratio = shown(derived_row( "", fixed("the energy left at the end, E final / E0")), "E final / E0",
                                  "", false, MeaningfulOn::inelastic_scenes);
  e_final_ratio.get = [](const Result& r) {
    const auto ratio = r.metrics.energy_ratio();
    return ratio ? nlohmann::json(*ratio) : nlohmann::json(nullptr);
  };
  MetricDef rel_drift = shown(metric_row(Metric::energy_max_rel_drift, "",
                                         fixed("max over samples of |E - E0| / E0 (none when E0 = 0). Restitution "
                                               "below 1 loses energy by design, so compare engines on the same scene, "
                                               "not against zero"),
                                         kReal),
                              "energy drift (max rel)", "E drift", false, MeaningfulOn::elastic_scenes);
  rel_drift.ensemble = "E drift";
  f.rows = {
      metric_row(Metric::energy_initial, "J",
                 fixed("E0: E = sum m |v|^2 / 2 + I w^2 / 2 + m |g| h at the start, h measured from the container's "
                       "floor (from the lowest initial ball in open space), I = k m r^2 (the rotation term only for a "
                       "scene that rotates)"),
                 kReal),
      metric_row(Metric::energy_final, "J", fixed("E at the last sample"), kReal),
      rel_drift,
      e_final_ratio,
      metric_row(Metric::energy_max_abs_drift, "J", fixed("max over samples of |E - E0|"), kReal),
      metric_row(Metric::energy_reference, "J/kg",
                 fixed("-g . x_ref: the potential per unit mass at the height E is measured from")),
  };
  f.make = [](const Scene& scene, const MetricsConfig& config) { return std::make_unique<EnergyMeter>(scene, config); };
  return f;
}

}  // namespace ballbench

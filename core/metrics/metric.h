#pragma once
// Every metric a meter stores, as a name the compiler checks: a run's values are read and written
// by these (MetricValues), and each is a row of the catalog (metrics/catalog.h), which gives its
// unit, definition and columns. The table gives each its key, its dotted path in the result JSON
// and its name in a baseline; a test holds the table and the catalog's keyed rows to one set.
#include <optional>
#include <string_view>

#include "enum_words.h"

namespace ballbench {

enum class Metric {
  angle_of_repose,
  angular_momentum_centre,
  angular_momentum_final,
  angular_momentum_initial,
  angular_momentum_max_abs_drift,
  energy_final,
  energy_initial,
  energy_max_abs_drift,
  energy_max_rel_drift,
  energy_reference,
  jitter,
  momentum_final,
  momentum_initial,
  momentum_max_abs_drift,
  penetration_after_start,
  penetration_initial,
  penetration_max,
  penetration_mean,
  rolling_error,
  rolling_expected_speed,
  rolling_expected_time_to_roll,
  rolling_speed,
  runout,
  samples,
  slip_final_max,
  slip_time_to_roll,
  speed_ks,
  speed_ks_critical,
  sticking_pair,
  sticking_wall,
  tunnelling_pair,
  tunnelling_wall,
};

inline constexpr EnumWords<Metric, 32> kMetricKeys{
    "metric",
    {{{Metric::angle_of_repose, "angle_of_repose"},
      {Metric::angular_momentum_centre, "angular_momentum.centre"},
      {Metric::angular_momentum_final, "angular_momentum.final"},
      {Metric::angular_momentum_initial, "angular_momentum.initial"},
      {Metric::angular_momentum_max_abs_drift, "angular_momentum.max_abs_drift"},
      {Metric::energy_final, "energy.final"},
      {Metric::energy_initial, "energy.initial"},
      {Metric::energy_max_abs_drift, "energy.max_abs_drift"},
      {Metric::energy_max_rel_drift, "energy.max_rel_drift"},
      {Metric::energy_reference, "energy.reference"},
      {Metric::jitter, "jitter"},
      {Metric::momentum_final, "momentum.final"},
      {Metric::momentum_initial, "momentum.initial"},
      {Metric::momentum_max_abs_drift, "momentum.max_abs_drift"},
      {Metric::penetration_after_start, "penetration.after_start"},
      {Metric::penetration_initial, "penetration.initial"},
      {Metric::penetration_max, "penetration.max"},
      {Metric::penetration_mean, "penetration.mean"},
      {Metric::rolling_error, "rolling.error"},
      {Metric::rolling_expected_speed, "rolling.expected_speed"},
      {Metric::rolling_expected_time_to_roll, "rolling.expected_time_to_roll"},
      {Metric::rolling_speed, "rolling.speed"},
      {Metric::runout, "runout"},
      {Metric::samples, "samples"},
      {Metric::slip_final_max, "slip.final_max"},
      {Metric::slip_time_to_roll, "slip.time_to_roll"},
      {Metric::speed_ks, "speed_ks"},
      {Metric::speed_ks_critical, "speed_ks_critical"},
      {Metric::sticking_pair, "sticking.pair"},
      {Metric::sticking_wall, "sticking.wall"},
      {Metric::tunnelling_pair, "tunnelling.pair"},
      {Metric::tunnelling_wall, "tunnelling.wall"}}}};

// "energy.final" for Metric::energy_final.
inline const char* metric_key(Metric m) { return kMetricKeys.word(m); }

// The metric of a key, none for a key that names none.
inline std::optional<Metric> metric_of_key(std::string_view key) {
  for (const auto& [m, k] : kMetricKeys.words)
    if (key == k) return m;
  return std::nullopt;
}

}  // namespace ballbench

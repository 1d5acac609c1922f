#pragma once
// A run's metrics (metrics/metric.h: Metric::energy_final, Metric::tunnelling_pair): what its
// meters measured, in the form the result JSON holds them (numbers, counts, [x, y] vectors, null for
// none). A metric no meter wrote has no value: the scene did not call for it, or the run was not
// measured.
#include <map>
#include <optional>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "metrics/metric.h"

namespace ballbench {

class MetricValues {
 public:
  void set(Metric m, nlohmann::json value) { values_.insert_or_assign(m, std::move(value)); }
  // The value, or null where there is none.
  const nlohmann::json& at(Metric m) const;
  bool has(Metric m) const { return !at(m).is_null(); }
  // A number, or none (no value, or null: a drift relative to no energy).
  std::optional<double> number(Metric m) const;
  // The same, 0 where there is none: for the counts and figures every measured run has
  // (Result::measured tells a run that has none).
  double value(Metric m) const { return number(m).value_or(0.0); }
  long count(Metric m) const { return static_cast<long>(value(m)); }
  Eigen::Vector2d vec(Metric m) const;
  // The figures derived from two values, computed here once: balls that passed through a wall or
  // another ball within a step (tunnelling wall + pair), stuck episodes (sticking wall + pair), and
  // the energy ratio.
  long tunnelled() const { return count(Metric::tunnelling_wall) + count(Metric::tunnelling_pair); }
  long stuck() const { return count(Metric::sticking_wall) + count(Metric::sticking_pair); }
  // The energy left at the end, E final / E0; none where the run started with none.
  std::optional<double> energy_ratio() const {
    const double e0 = value(Metric::energy_initial);
    return e0 > 0 ? std::optional(value(Metric::energy_final) / e0) : std::nullopt;
  }

  const std::map<Metric, nlohmann::json>& all() const { return values_; }
  bool operator==(const MetricValues&) const = default;

 private:
  std::map<Metric, nlohmann::json> values_;
};

}  // namespace ballbench

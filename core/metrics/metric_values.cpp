#include "metrics/metric_values.h"

namespace ballbench {

const nlohmann::json& MetricValues::at(Metric m) const {
  static const nlohmann::json none;
  const auto it = values_.find(m);
  return it == values_.end() ? none : it->second;
}

std::optional<double> MetricValues::number(Metric m) const {
  const nlohmann::json& v = at(m);
  if (!v.is_number()) return std::nullopt;
  return v.get<double>();
}

Eigen::Vector2d MetricValues::vec(Metric m) const {
  const nlohmann::json& v = at(m);
  if (!v.is_array() || v.size() != 2) return {0, 0};
  return {v[0].get<double>(), v[1].get<double>()};
}

}  // namespace ballbench

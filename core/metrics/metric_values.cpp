#include "metrics/metric_values.h"

#include <stdexcept>

#include "metrics/catalog.h"

namespace ballbench {
namespace {

void check_key(std::string_view key) {
  if (!is_metric_key(key)) throw std::logic_error("no metric '" + std::string(key) + "' in the catalog");
}

}  // namespace

void MetricValues::set(std::string_view key, nlohmann::json value) {
  check_key(key);
  values_.insert_or_assign(std::string(key), std::move(value));
}

const nlohmann::json& MetricValues::at(std::string_view key) const {
  static const nlohmann::json none;
  check_key(key);
  const auto it = values_.find(key);
  return it == values_.end() ? none : it->second;
}

std::optional<double> MetricValues::number(std::string_view key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_number()) return std::nullopt;
  return v.get<double>();
}

Eigen::Vector2d MetricValues::vec(std::string_view key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_array() || v.size() != 2) return {0, 0};
  return {v[0].get<double>(), v[1].get<double>()};
}

}  // namespace ballbench

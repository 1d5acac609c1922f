#pragma once
// A run's metrics by catalog key ("energy.final", "tunnelling.pair"): what its meters measured, in
// the form the result JSON holds them (numbers, counts, [x, y] vectors, null for none). A key no
// meter wrote has no value: the scene did not call for that metric, or the run was not measured.
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace ballbench {

class MetricValues {
 public:
  // Every key is a catalog key (metrics/catalog.h): any other is a programming error and throws
  // std::logic_error, so a misspelt key fails its first test instead of reading as "none".
  void set(std::string_view key, nlohmann::json value);
  // The value, or null where there is none.
  const nlohmann::json& at(std::string_view key) const;
  bool has(std::string_view key) const { return !at(key).is_null(); }
  // A number, or none (no value, or null: a drift relative to no energy).
  std::optional<double> number(std::string_view key) const;
  // The same, 0 where there is none: for the counts and figures every measured run has
  // (Result::measured tells a run that has none).
  double value(std::string_view key) const { return number(key).value_or(0.0); }
  long count(std::string_view key) const { return static_cast<long>(value(key)); }
  Eigen::Vector2d vec(std::string_view key) const;
  // The figures derived from two values, computed here once: balls that passed through a wall or
  // another ball within a step (tunnelling wall + pair), stuck episodes (sticking wall + pair), and
  // the energy ratio.
  long tunnelled() const { return count("tunnelling.wall") + count("tunnelling.pair"); }
  long stuck() const { return count("sticking.wall") + count("sticking.pair"); }
  // The energy left at the end, E final / E0; none where the run started with none.
  std::optional<double> energy_ratio() const {
    const double e0 = value("energy.initial");
    return e0 > 0 ? std::optional(value("energy.final") / e0) : std::nullopt;
  }

  const std::map<std::string, nlohmann::json, std::less<>>& all() const { return values_; }
  bool operator==(const MetricValues&) const = default;

 private:
  std::map<std::string, nlohmann::json, std::less<>> values_;
};

}  // namespace ballbench

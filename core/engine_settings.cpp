#include "engine_settings.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {

SettingsReader::SettingsReader(std::string engine, const nlohmann::json& overrides)
    : engine_(std::move(engine)), overrides_(overrides.is_null() ? nlohmann::json::object() : overrides) {}

void SettingsReader::fail(const std::string& key, const std::string& why) const {
  throw InputError(fmt::format("settings.{}.{}: {}", engine_, key, why));
}

const nlohmann::json* SettingsReader::find(const char* key) {
  known_.emplace_back(key);
  const auto it = overrides_.find(key);
  return it == overrides_.end() ? nullptr : &*it;
}

void SettingsReader::get(const char* key, double& value) {
  if (const auto* v = find(key)) {
    if (!v->is_number()) fail(key, fmt::format("expected a number, got {}", v->dump()));
    value = v->get<double>();
    if (!std::isfinite(value)) fail(key, "must be finite");
  }
}

void SettingsReader::get(const char* key, int& value) {
  if (const auto* v = find(key)) {
    const auto out_of_range = [&] {
      fail(key, fmt::format("{} is out of range (a whole number from {} to {})", v->dump(),
                            std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    };
    // A whole number written as a float (16.0, or 1e9 from `--set`) is that number.
    if (v->is_number_float()) {
      const double d = v->get<double>();
      if (!std::isfinite(d) || d != std::floor(d)) fail(key, fmt::format("expected a whole number, got {}", v->dump()));
      if (std::fabs(d) > std::numeric_limits<int>::max()) out_of_range();
      value = static_cast<int>(d);
      return;
    }
    if (!v->is_number_integer()) fail(key, fmt::format("expected a whole number, got {}", v->dump()));
    // get<int>() would wrap a 64-bit number silently (4294967297 becomes 1).
    const auto wide = v->get<long long>();
    const bool unsigned_big = v->is_number_unsigned() && v->get<unsigned long long>() > 2147483647ULL;
    if (unsigned_big || wide > std::numeric_limits<int>::max() || wide < std::numeric_limits<int>::min()) out_of_range();
    value = static_cast<int>(wide);
  }
}

void SettingsReader::get(const char* key, bool& value) {
  if (const auto* v = find(key)) {
    if (!v->is_boolean()) fail(key, fmt::format("expected true or false, got {}", v->dump()));
    value = v->get<bool>();
  }
}

void SettingsReader::get(const char* key, std::string& value) {
  if (const auto* v = find(key)) {
    if (!v->is_string()) fail(key, fmt::format("expected a string, got {}", v->dump()));
    value = v->get<std::string>();
  }
}

void SettingsReader::get(const char* key, std::string& value, const std::vector<const char*>& choices) {
  std::string s = value;
  get(key, s);
  if (std::none_of(choices.begin(), choices.end(), [&](const char* c) { return s == c; }))
    fail(key, fmt::format("'{}' is not one of: {}", s, fmt::join(choices, ", ")));
  value = s;
}

void SettingsReader::finish() const {
  for (const auto& [k, v] : overrides_.items())
    if (std::find(known_.begin(), known_.end(), k) == known_.end())
      fail(k, fmt::format("unknown setting{} (known: {})", did_you_mean(k, known_), fmt::join(known_, ", ")));
}

namespace {

std::string refusal(const std::string& range, const char* why) {
  return *why ? fmt::format("must be {} ({})", range, why) : fmt::format("must be {}", range);
}

}  // namespace

Bound at_least(double lo, const char* why) {
  const std::string range = fmt::format(">= {}", lo);
  return {[lo](double x) { return x >= lo; }, range, refusal(range, why)};
}

Bound above(double lo, const char* why) {
  const std::string range = fmt::format("> {}", lo);
  return {[lo](double x) { return x > lo; }, range, refusal(range, why)};
}

Bound within(double lo, double hi) {
  const std::string range = fmt::format("[{}, {}]", lo, hi);
  return {[lo, hi](double x) { return x >= lo && x <= hi; }, range, refusal(range, "")};
}

Bound inside(double lo, double hi) {
  const std::string range = fmt::format("({}, {})", lo, hi);
  return {[lo, hi](double x) { return x > lo && x < hi; }, range, refusal(range, "")};
}

Bound bound(std::function<bool(double)> holds, std::string range, std::string refusal) {
  return {std::move(holds), std::move(range), std::move(refusal)};
}

}  // namespace ballbench

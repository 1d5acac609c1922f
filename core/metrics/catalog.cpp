#include "metrics/catalog.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "json_value.h"
#include "metrics/meter.h"
#include "metrics/meter_set.h"
#include "result.h"

namespace ballbench {
namespace {

using nlohmann::json;

std::vector<MetricDef> build_catalog() {
  std::vector<MetricDef> c;
  for (const MetricFamily& f : metric_families())
    for (MetricDef m : f.rows) {
      if (!m.get) m.get = [metric = *m.metric](const Result& r) { return r.metrics.at(metric); };
      c.push_back(std::move(m));
    }
  return c;
}

// "a.b" -> "/a/b"
json::json_pointer pointer(const std::string& key) {
  std::string p = "/" + key;
  for (char& ch : p)
    if (ch == '.') ch = '/';
  return json::json_pointer(p);
}

}  // namespace

std::function<std::string(const MetricsConfig&)> fixed(std::string text) {
  return [text = std::move(text)](const MetricsConfig&) { return text; };
}

MetricDef metric_row(Metric metric, std::string unit, std::function<std::string(const MetricsConfig&)> definition,
                     std::optional<Tolerance> regress) {
  MetricDef m = derived_row(std::move(unit), std::move(definition));
  m.metric = metric, m.key = metric_key(metric), m.regress = regress;
  return m;
}

MetricDef derived_row(std::string unit, std::function<std::string(const MetricsConfig&)> definition) {
  MetricDef m;
  m.unit = std::move(unit), m.definition = std::move(definition);
  return m;
}

MetricDef total_row(std::string ensemble, std::string definition, long (MetricValues::*total)() const) {
  MetricDef m = derived_row("", fixed(std::move(definition)));
  m.ensemble = std::move(ensemble);
  m.get = [total](const Result& r) { return json((r.metrics.*total)()); };
  return m;
}

MetricDef shown(MetricDef m, std::string column, std::string heading, bool ranked, MeaningfulOn meaningful) {
  m.column = std::move(column), m.heading = std::move(heading), m.ranked = ranked, m.meaningful = meaningful;
  return m;
}

bool meaningful_on(MeaningfulOn where, const SceneFeatures& f, bool chaotic) {
  switch (where) {
    case MeaningfulOn::every_scene: return true;
    case MeaningfulOn::elastic_scenes: return f.elastic;
    case MeaningfulOn::inelastic_scenes: return !f.elastic;
    case MeaningfulOn::open_space_without_gravity: return !f.walls && !f.gravity;
    case MeaningfulOn::predictable_scenes: return !chaotic;
    case MeaningfulOn::no_scene: return false;
  }
  return true;
}

const std::vector<MetricDef>& metric_catalog() {
  static const std::vector<MetricDef> catalog = build_catalog();
  return catalog;
}

std::string metric_text(const json& v) {
  if (v.is_null()) return "-";
  if (v.is_number_integer()) return fmt::format("{}", v.get<long>());
  if (v.is_number()) return fmt::format("{:.3g}", v.get<double>());
  if (v.is_array() && v.size() == 2) return fmt::format("({}, {})", metric_text(v[0]), metric_text(v[1]));
  return json_text(v);
}

void put_metrics(const Result& r, json& j) {
  for (const MetricDef& m : metric_catalog())
    if (!m.key.empty()) j[pointer(m.key)] = r.measured() ? m.get(r) : json(nullptr);
}

void take_metrics(const json& j, Result& r) {
  // Each value of the kind its meter writes (a vector or a number): another is a type error, which
  // the file's reader names by its field.
  static const MetricValues kinds = resting_values();
  for (const MetricDef& m : metric_catalog()) {
    if (!m.metric) continue;
    const json::json_pointer p = pointer(m.key);
    if (!j.contains(p) || j.at(p).is_null()) continue;
    const json& v = j.at(p);
    if (kinds.at(*m.metric).is_array()) (void)v.get<std::array<double, 2>>();
    else (void)v.get<double>();
    r.metrics.set(*m.metric, v);
  }
}

}  // namespace ballbench

#pragma once
// Every metric a run's states yield, declared once: where it goes in the result JSON, its unit, its
// definition, how the tables show it and how `ballbench regress` compares it. The result's JSON
// writer and reader, the regression record and its default tolerances, the report's per-scene
// columns and glossary, `ballbench run`'s table and `ballbench list --metrics` all derive from
// metric_catalog(): adding a metric is one entry there (and the code that measures it).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "metrics/metrics.h"
#include "scene.h"

namespace ballbench {

struct Result;

// A regression tolerance: a value passes if |now - baseline| <= abs + rel |baseline|.
struct Tolerance {
  double rel = 0, abs = 0;
};

// The scenes on which a metric with a report column means something: there it is in the scene's
// table, elsewhere in the scene's appendix (a momentum drift where walls and gravity push the balls
// says nothing of the engine).
enum class MeaningfulOn {
  every_scene,
  elastic_scenes,       // restitution 1: energy should be conserved
  inelastic_scenes,     // restitution below 1: energy is lost by design
  open_space_without_gravity,  // nothing outside the balls acts on them: momentum should be conserved
  no_scene,             // detail behind another column: the appendix only
};
bool meaningful_on(MeaningfulOn where, const SceneFeatures& f);

struct MetricDef {
  // Dotted path in the result JSON, also the metric's name in the baseline: "energy.final"; empty
  // for a figure the tables derive from others (E final / E0), which is not stored.
  std::string key;
  std::string unit;  // "J", "kg m/s", "" for counts and ratios
  // What it means, for the report's glossary and `list --metrics`; the config gives the tolerances
  // a definition quotes.
  std::function<std::string(const MetricsConfig&)> definition;
  std::string column;   // its column in the report's per-scene table, or "" for none
  std::string heading;  // its column in `ballbench run`'s table, or "" for none
  bool ranked = false;  // smaller is better: the report marks the best run in bold
  MeaningfulOn meaningful = MeaningfulOn::every_scene;  // where the report's scene table shows its column
  std::optional<Tolerance> regress;  // compared by `ballbench regress`; none: not compared
  // The value of a run (null where the run has none: a drift of zero energy, the slip of a scene
  // that does not rotate), and how a value read back from JSON sets it (never called with null).
  std::function<nlohmann::json(const Result&)> get;
  std::function<void(Result&, const nlohmann::json&)> set;
};

const std::vector<MetricDef>& metric_catalog();

// The metric's value as the tables print it: integers as they are, reals to 3 significant
// figures, vectors as (x, y), null as "-".
std::string metric_text(const nlohmann::json& value);

// Writes every metric of `r` into `j` at its key (creating the enclosing objects): null, each of
// them, for a run that was not measured (Result::measured).
void put_metrics(const Result& r, nlohmann::json& j);
// Sets every metric of `r` found in `j`; a metric missing or null there keeps its default (result
// files written before it existed).
void take_metrics(const nlohmann::json& j, Result& r);

}  // namespace ballbench

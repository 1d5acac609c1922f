#pragma once
// Every metric a run's states yield, declared once: where it goes in the result JSON, its unit, its
// definition, how the tables show it and how `ballbench regress` compares it. The rows come from
// the metric families (metrics/meter.h: each row beside the meter that measures it); the result's
// JSON writer and reader, the regression record and its default tolerances, the report's per-scene
// columns and glossary, the seed ensembles' columns, `ballbench run`'s table, `ballbench list
// --metrics` and docs/results.md's metrics table all derive from metric_catalog().
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "metrics/metric.h"
#include "metrics/metric_values.h"
#include "metrics/metrics_config.h"
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
  // Scenes whose runs stay near the reference: on a chaotic one every engine parts from it, and the
  // horizon, not the final error, says how well it did.
  predictable_scenes,
  no_scene,             // detail behind another column: the appendix only
};
// `chaotic`: every run compared with the reference parted from it (the report judges it from them).
bool meaningful_on(MeaningfulOn where, const SceneFeatures& f, bool chaotic = false);

struct MetricDef {
  // The metric a meter stores, none for a figure the tables derive from others (E final / E0).
  std::optional<Metric> metric;
  // Its dotted path in the result JSON, also its name in the baseline (metric_key: "energy.final");
  // empty for a derived figure, which is not stored.
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
  std::string ensemble;  // its column in the seed ensembles' tables (ensemble.h), or "" for none
  // How the tables print a measured run's null, where it has a meaning of its own ("never" for a
  // time that never came); "" for "n/a".
  std::string null_text;
  // The value of a run (null where the run has none: a drift of zero energy, the slip of a scene
  // that does not rotate). A row with a key reads the run's MetricValues at it unless it says
  // otherwise; a row without one says how it derives its figure.
  std::function<nlohmann::json(const Result&)> get;
};

const std::vector<MetricDef>& metric_catalog();

// Declaring rows (the metric families' files).
// Counts and the outcome of a run move only when its behaviour does, never by round-off.
inline constexpr Tolerance kExact{0.0, 0.0};
// Real-valued metrics of our double solvers: the same source gives the same bits on every build we
// make (-ffp-contract=off); 1e-9 leaves room for a compiler reordering a sum, while a change of
// algorithm or constant moves them far more. The absolute floor is for round-off around zero (the
// momentum drift of a conserving solver).
inline constexpr Tolerance kReal{1e-9, 1e-12};
// A definition that quotes no tolerance.
std::function<std::string(const MetricsConfig&)> fixed(std::string text);
// A row for the metric `m`, stored at its key of the result JSON, with no column.
MetricDef metric_row(Metric m, std::string unit, std::function<std::string(const MetricsConfig&)> definition,
                     std::optional<Tolerance> regress = std::nullopt);
// A row that stores nothing: its `get` derives its figure.
MetricDef derived_row(std::string unit, std::function<std::string(const MetricsConfig&)> definition);
// A derived row for the seed ensembles' column `ensemble`: a total of MetricValues (walls and pairs
// together: MetricValues::tunnelled).
MetricDef total_row(std::string ensemble, std::string definition, long (MetricValues::*total)() const);
// The same row with its report column, its `ballbench run` heading (either may be ""), whether
// smaller is better and where the report's scene table shows it.
MetricDef shown(MetricDef m, std::string column, std::string heading, bool ranked,
                MeaningfulOn meaningful = MeaningfulOn::every_scene);

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

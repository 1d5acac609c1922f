#pragma once
// Seed ensembles (`run --seeds K`, the report's seed scenes): one scene's random placement drawn K
// times, every engine and profile run on each. A metric's figure is its mean over the placements
// with a 95% percentile-bootstrap confidence interval (Efron and Tibshirani, "An Introduction to
// the Bootstrap", 1993, ch. 13), and a run is compared with our solver's on the same placements:
// the difference is significant when the bootstrap interval of the mean paired difference leaves
// out 0. Resampling is seeded, so the same results give the same intervals.
#include <optional>
#include <string>
#include <vector>

#include "result.h"

namespace ballbench {

struct Interval {
  double mean = 0, lo = 0, hi = 0;  // the mean and its 95% confidence interval
  int n = 0;                        // values it is over
};

// Percentile bootstrap of the mean (2000 resamples); an empty input gives n = 0.
Interval bootstrap_mean(const std::vector<double>& values);

struct MetricDef;

// A metric an ensemble summarises: a catalog row with an ensemble column (metrics/catalog.h).
struct EnsembleMetric {
  std::string name;  // the column
  const MetricDef* def;
  // Its figure in a result: none where the run did not measure it.
  std::optional<double> read(const Result& r) const;
};
const std::vector<EnsembleMetric>& ensemble_metrics();

struct EnsembleRow {
  std::string label;                       // engine/profile
  int placements = 0;                      // results with status ok
  std::vector<std::optional<Interval>> metrics;  // per ensemble_metrics(), over the ok results
  // Per metric: "" when not compared; "+" / "-" when significantly above / below ours on the same
  // placements; "=" when not significantly different.
  std::vector<std::string> versus_ours;
};

// One row per engine and profile in first-seen order. `ours` is the label compared against ("" for
// none); placements are matched by seed_offset.
std::vector<EnsembleRow> summarise_ensemble(const std::vector<Result>& results, const std::string& ours);

// "1.23e-05 [1.1e-05, 1.4e-05]": a mean and its interval, in a table cell.
std::string interval_text(const Interval& i);

}  // namespace ballbench

#include "spec_verdict.h"

#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "metrics/meter_set.h"
#include "result.h"

namespace ballbench {
namespace {

// The metric whose meter measures a term, none for the terms against the reference.
std::optional<Metric> term_metric(SpecTerm t) {
  switch (t) {
    case SpecTerm::overlap: return Metric::penetration_after_start;
    case SpecTerm::tunnelling: return Metric::tunnelling_wall;
    case SpecTerm::sticking: return Metric::sticking_wall;
    case SpecTerm::rest_speed: return Metric::jitter;
    case SpecTerm::energy_drift: return Metric::energy_max_rel_drift;
    case SpecTerm::energy_error:
    case SpecTerm::horizon: return std::nullopt;
    case SpecTerm::rolling: return Metric::rolling_error;
  }
  return std::nullopt;
}

// A term's figure from the run's metric values alone (none for the terms against the reference):
// the counts of walls and pairs together, the others their metric's value.
std::optional<double> metric_figure(SpecTerm t, const MetricValues& v) {
  if (t == SpecTerm::tunnelling) return static_cast<double>(v.tunnelled());
  if (t == SpecTerm::sticking) return static_cast<double>(v.stuck());
  const auto m = term_metric(t);
  return m ? v.number(*m) : std::nullopt;
}

}  // namespace

std::optional<std::string> grown_past(const AccuracySpec& spec, const MeterSet& meters) {
  for (const SpecTermDef& d : spec_terms()) {
    const auto& bound = spec[d.term];
    const auto metric = term_metric(d.term);
    if (!bound || !d.grows || d.at_least || !metric) continue;
    if (const auto figure = metric_figure(d.term, meters.values_of(*metric)); figure && *figure > *bound)
      return fmt::format("{} {:.3g} > {:g}", d.key, *figure, *bound);
  }
  return std::nullopt;
}

std::optional<double> spec_figure(SpecTerm t, const Result& r) {
  if (r.steps_done < 1) return std::nullopt;
  switch (t) {
    case SpecTerm::energy_error:
      if (!r.reference.available) return std::nullopt;
      return r.reference.energy_rel_max;
    case SpecTerm::horizon:
      if (!r.reference.available) return std::nullopt;
      // Never left the tolerance: the whole run compared (up to a reference that failed).
      if (!r.reference.horizon)
        return (r.reference.reference_failed_step >= 0 ? r.reference.reference_failed_step : r.steps_done) * r.dt;
      return *r.reference.horizon;
    default: return metric_figure(t, r.metrics);
  }
}

SpecVerdict judge(const AccuracySpec& spec, const Result& r) {
  SpecVerdict v;
  std::vector<std::string> fails;
  if (r.status != RunStatus::ok)
    fails.push_back(std::string(run_status_text(r.status)) + (r.error.empty() ? "" : ": " + r.error));
  for (const SpecTermDef& d : spec_terms()) {
    const auto& bound = spec[d.term];
    if (!bound) continue;
    const auto figure = spec_figure(d.term, r);
    v.figures[d.key] = figure ? nlohmann::json(*figure) : nlohmann::json();
    // A run stopped where it missed is judged by its status alone: its other figures are of a
    // state before the end.
    if (r.status == RunStatus::missed) continue;
    if (!figure) {
      fails.push_back(fmt::format("{} not measured", d.key));
      continue;
    }
    const bool ok = d.at_least ? *figure >= *bound : *figure <= *bound;
    if (!ok) fails.push_back(fmt::format("{} {:.3g} {} {:g}", d.key, *figure, d.at_least ? "<" : ">", *bound));
  }
  v.met = fails.empty();
  v.why_not = fmt::format("{}", fmt::join(fails, "; "));
  return v;
}

}  // namespace ballbench

#include "spec_verdict.h"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "result.h"

namespace ballbench {

std::optional<double> spec_figure(SpecTerm t, const Result& r) {
  if (r.steps_done < 1) return std::nullopt;
  const MetricValues& m = r.metrics;
  switch (t) {
    case SpecTerm::overlap: return m.number("penetration.after_start");
    case SpecTerm::tunnelling: return double(m.count("tunnelling.wall") + m.count("tunnelling.pair"));
    case SpecTerm::sticking: return double(m.count("sticking.wall") + m.count("sticking.pair"));
    case SpecTerm::rest_speed: return m.number("jitter");
    case SpecTerm::energy_drift: return m.number("energy.max_rel_drift");
    case SpecTerm::energy_error:
      if (!r.reference.available) return std::nullopt;
      return r.reference.energy_rel_max;
    case SpecTerm::horizon:
      if (!r.reference.available) return std::nullopt;
      // Never left the tolerance: the whole run compared (up to a reference that failed).
      if (!r.reference.horizon)
        return (r.reference.reference_failed_step >= 0 ? r.reference.reference_failed_step : r.steps_done) * r.dt;
      return *r.reference.horizon;
    case SpecTerm::rolling:
      {
        const auto speed = m.number("rolling.speed"), expected = m.number("rolling.expected_speed");
        if (!speed || !expected || *expected == 0) return std::nullopt;
        return std::abs(*speed - *expected) / std::abs(*expected);
      }
  }
  return std::nullopt;
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

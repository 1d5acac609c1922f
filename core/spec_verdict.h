#pragma once
// Judging a run against an accuracy spec (accuracy_spec.h): each term's figure comes from what the
// harness measured from the run's states, never from an engine's own claims.
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "accuracy_spec.h"

namespace ballbench {

struct Result;
class MeterSet;

// One term's figure for a run: measured by the harness from the run's states; none where the run
// has none (no reference ran, the scene asks no rolling, nothing was stepped).
std::optional<double> spec_figure(SpecTerm t, const Result& r);

// The first term of `spec` whose figure only grows (SpecTermDef::grows) and is already past its
// bound in the meters' values so far, as "overlap 0.0123 > 0.01"; none while the run can still
// meet every such term.
std::optional<std::string> grown_past(const AccuracySpec& spec, const MeterSet& meters);

struct SpecVerdict {
  bool met = false;
  // Why not, one clause per failing term ("overlap 0.056 > 0.01"), or the run's status.
  std::string why_not;
  // Every bound term's figure (null where unmeasured), keyed as spec_terms().
  nlohmann::json figures = nlohmann::json::object();
};
// Whether `r` meets `spec`: a run that did not end ok never does; an unmeasured term fails.
SpecVerdict judge(const AccuracySpec& spec, const Result& r);

// A verdict in one line, as the step benchmark labels its runs: "met: overlap 0.004 (<= 0.01)" or
// "not met: overlap 0.031 > 0.01"; verdict_detail reads back what follows the verdict.
inline constexpr std::string_view kVerdictMet = "met: ", kVerdictNotMet = "not met: ";
inline std::string verdict_line(bool met, std::string_view detail) {
  return std::string(met ? kVerdictMet : kVerdictNotMet) + std::string(detail);
}
inline std::string_view verdict_detail(std::string_view line) {
  for (const std::string_view prefix : {kVerdictNotMet, kVerdictMet})
    if (line.starts_with(prefix)) return line.substr(prefix.size());
  return line;
}

}  // namespace ballbench

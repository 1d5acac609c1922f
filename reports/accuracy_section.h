#pragma once
// The report's equal-accuracy section (from results/match-SCENE.json, `ballbench match`): per
// scene, each engine and profile's cheapest configuration that meets the scene's spec, our
// solver's ratio to the cheapest external engine, and the work-precision front of every try.
#include <optional>
#include <string>
#include <vector>

#include "match_result.h"
#include "ratio_text.h"
#include "report_writer.h"

namespace ballbench {

// What became of one engine and profile's search, as a reader needs it.
enum class MatchVerdict {
  met,          // a configuration met the spec
  cut_short,    // one met, but the search stopped (budget, interrupt) before trying every configuration
  over_ceiling, // one met, at a cost timed alone past the match's ceiling
  outpaced,     // one met, at a cost timed alone past `within` times the cheapest of its role's (outpace_ns)
  not_reached,  // it ran, but no configuration tried met the spec
  unsupported,  // the engine refused the scene at every configuration
  failed,       // no configuration ran to its end (crashed, timed out, diverged at every step size)
};
MatchVerdict verdict_of(const MatchResult& m, const MatchOutcome& oc);

// One phrase for an outcome that did not meet the spec: its nearest miss with one figure and the
// finest step tried ("overlap 0.034 at dt/64"), or why it did not run ("unsupported", "diverged
// at every step size down to dt/64").
std::string miss_text(const MatchResult& m, const MatchOutcome& oc);

// "**48x cheaper**" for the other's cost over ours at 48, "**3.0x costlier**" at 1/3.
std::string cheaper_text(double ratio);

// "**over 50x cheaper**": ratio_at_least as the tables print it.
std::string at_least_text(double ratio);

// The heading of a scene's equal-accuracy section and its anchor (GitHub's rule: lower case, spaces
// to '-', punctuation dropped), for links from the summary.
std::string accuracy_heading(const std::string& scene);
std::string accuracy_anchor(const std::string& scene);

// One scene's equal-accuracy section.
std::string accuracy_section(const ReportInputs& in, const MatchResult& m, const std::vector<Figure>& figures);

}  // namespace ballbench

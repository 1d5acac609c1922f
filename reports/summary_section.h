#pragma once
// The report's first screen: for each use case (an equal-accuracy scene), its spec in words, the
// external engine to pick (the cheapest configuration that meets it), ours against it, the search's
// budget and when and by which build it was measured. Every claim links to the scene's page.
#include <string>
#include <vector>

#include "accuracy_spec.h"
#include "report_writer.h"

namespace ballbench {

// "overlap ≤ 1% of a radius, no tunnelling": a spec as a reader of game-physics docs says it.
std::string spec_words(const AccuracySpec& spec);

std::string summary_section(const ReportInputs& in, const std::vector<Figure>& figures);

}  // namespace ballbench

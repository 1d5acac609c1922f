#pragma once
// The report's friction section: every engine and profile on the scenes that ask for the rolling
// closed forms (a ball sliding to roll, a spinning ball dropped) and for the angle of repose (a
// heap with friction beside its frictionless twin), from the result files alone.
#include <string>
#include <vector>

#include "result.h"

namespace ballbench {

// Markdown ("## Friction" and its tables), or "" when no result holds a rolling or repose metric.
// `scene_order`: the report's scene order; the results are the scenes' own placements (offset 0).
std::string friction_section(const std::vector<Result>& results, const std::vector<std::string>& scene_order);

}  // namespace ballbench

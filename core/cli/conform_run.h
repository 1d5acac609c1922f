#pragma once
// Runs the closed-form checks (adapters/conformance.h) on engines, each case of each profile: the
// rows of `ballbench conform` and of the report's conform part.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conform_result.h"
#include "engine.h"

namespace ballbench::cli {

// Each row printed as it is measured, unless quiet. An engine that is not available here is one
// failed row (check "available"). Stops at an interrupt, the result marked.
ConformResult run_conform(const std::vector<const EngineEntry*>& engines, const std::string& profile,
                          const nlohmann::json& context, bool print);

}  // namespace ballbench::cli

#pragma once
// Runs the closed-form checks (adapters/conformance.h) on engines, each case of each profile: the
// rows of `ballbench conform` and of the report's conform part.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conform_result.h"
#include "engine.h"
#include "try_store.h"

namespace ballbench::cli {

// Each row printed as it is measured, unless quiet. An engine that is not available here is one
// failed row (check "available"). Stops at an interrupt, the result marked.
ConformResult run_conform(const std::vector<const EngineEntry*>& engines, const std::string& profile,
                          const nlohmann::json& context, bool print);

// Keeps each engine and profile's refuted claims (refuted_claims) in `store`, keyed by the engine,
// its version, the profile and this build, for the tables of `run` and `match` to mark. An
// interrupted result keeps nothing: its profiles may lack cases.
void keep_claim_checks(const TryStore& store, const ConformResult& c, const std::vector<const EngineEntry*>& engines);

// Under each table of runs or searches: every row's engine whose claims a closed form refuted
// (as `conform` or a report of this build found them), and in one line the engines not yet checked
// by this build, with the command that checks them. The rows: `engines`, each with its profiles
// that `profile` names ("all", or one).
void print_claim_checks(const TryStore& store, const std::vector<const EngineEntry*>& engines, const std::string& profile);

}  // namespace ballbench::cli

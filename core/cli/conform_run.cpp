#include "conform_run.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "conformance.h"
#include "input_error.h"
#include "interrupt.h"
#include "machine_info.h"
#include "registry.h"
#include "result.h"
#include "run_engines.h"

namespace ballbench::cli {
namespace {


ConformRow check(const EngineEntry& e, const std::string& profile, const ConformCaseDef& d) {
  ConformRow row;
  row.engine = e.info.name, row.profile = profile, row.check = d.key, row.tolerance = d.tolerance;
  try {
    const double figure = conform_figure(e, profile, d.c);
    row.figure = figure;
    row.verdict = figure <= d.tolerance ? ConformVerdict::pass : ConformVerdict::fail;
    if (*d.capability && claims(e.info.caps, d.capability) && !(figure < d.refutes)) row.refuted = d.capability;
  } catch (const SceneUnsupported& refused) {  // a case it says it cannot run: neither a pass nor a refuted claim
    row.verdict = ConformVerdict::refused, row.why = refused.what();
  } catch (const InputError&) {
    throw;  // the user's settings: one line for the whole command
  } catch (const std::exception& failed) {  // the engine failed the case: a failure with its error, the others run
    row.verdict = ConformVerdict::fail, row.why = fmt::format("the engine failed: {}", failed.what());
  }
  return row;
}

void print_row(const ConformRow& r) {
  const ConformCaseDef* d = nullptr;
  for (const ConformCaseDef& c : conform_cases())
    if (c.key == r.check) d = &c;
  const std::string figure = conform_figure_text(r.figure);
  std::string verdict = r.verdict == ConformVerdict::pass ? "pass" : r.verdict == ConformVerdict::fail ? "FAIL" : "refused";
  if (!r.why.empty()) verdict += ": " + r.why;
  if (!r.refuted.empty() && d)
    verdict += fmt::format(" (refutes its claim of {}: {} or more)", r.refuted, conform_figure_text(d->refutes));
  fmt::print("{:<18} {:<22} {:>10} {:>10}  {}\n", run_label(r.engine, r.profile), r.check, figure,
             conform_figure_text(r.tolerance), verdict);
}

}  // namespace

ConformResult run_conform(const std::vector<const EngineEntry*>& engines, const std::string& profile,
                          const nlohmann::json& context, bool print) {
  ConformResult out;
  out.context = context;
  for (const EngineEntry* e : engines) {
    if (!e->info.unavailable.empty()) {
      out.rows.push_back({e->info.name, "", "available", 0, std::nullopt, ConformVerdict::fail, "", e->info.unavailable});
      if (print) fmt::print("{:<18} unavailable: {}\n", e->info.name, e->info.unavailable);
      continue;
    }
    for (const std::string& p : profiles_for(*e, profile))
      for (const ConformCaseDef& d : conform_cases()) {
        if (interrupt_signal()) {
          out.interrupted = interrupt_name();
          return out;
        }
        out.rows.push_back(check(*e, p, d));
        if (print) print_row(out.rows.back());
      }
  }
  return out;
}

namespace {

nlohmann::json claim_key(const EngineEntry& e, const std::string& profile) {
  return {{"kind", "conform"}, {"engine", e.info.name}, {"version", e.info.version}, {"profile", profile},
          {"build", build_id()}};
}

}  // namespace

void keep_claim_checks(const TryStore& store, const ConformResult& c, const std::vector<const EngineEntry*>& engines) {
  if (!store.enabled() || !c.interrupted.empty()) return;
  for (const EngineEntry* e : engines) {
    if (!e->info.unavailable.empty()) continue;
    for (const std::string& p : e->info.profiles)
      if (std::any_of(c.rows.begin(), c.rows.end(), [&](const ConformRow& r) { return r.engine == e->info.name && r.profile == p; }))
        store.keep(claim_key(*e, p), {{"refuted", refuted_claims(c, e->info.name, p)}});
  }
}

void print_claim_checks(const TryStore& store, const std::vector<const EngineEntry*>& engines, const std::string& profile) {
  if (!store.enabled()) return;
  std::vector<std::string> unchecked;
  for (const EngineEntry* e : engines) {
    if (!e->info.unavailable.empty()) continue;
    for (const std::string& p : profiles_for(*e, profile)) {
      const auto found = store.find(claim_key(*e, p));
      if (!found) {
        if (std::find(unchecked.begin(), unchecked.end(), e->info.name) == unchecked.end()) unchecked.push_back(e->info.name);
        continue;
      }
      const auto refuted = found->value("refuted", std::vector<std::string>{});
      if (!refuted.empty())
        fmt::print("{}: its closed forms refute its claim of {} (ballbench conform --engine {})\n",
                   run_label(e->info.name, p), fmt::join(refuted, ", "), e->info.name);
    }
  }
  if (!unchecked.empty())
    fmt::print("not yet checked against the closed forms by this build: {} (ballbench conform --engine {})\n",
               fmt::join(unchecked, ", "), fmt::join(unchecked, ","));
}

}  // namespace ballbench::cli

// `ballbench conform`: the closed-form checks (adapters/conformance.h) on any engine, built in or
// from an engines file: one line per check with its figure, its tolerance and pass or fail, and a
// capability the engine's handshake claims that a case refutes named as such.
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "conformance.h"
#include "engine.h"
#include "input_error.h"
#include "interrupt.h"
#include "registry.h"
#include "result.h"
#include "run_engines.h"

namespace ballbench::cli {
namespace {

struct ConformArgs {
  std::string engines, profile = "all";
  bool quiet = false;
};

std::string figure_text(double x) { return std::isfinite(x) ? fmt::format("{:.3g}", x) : "inf"; }

void conform(const ConformArgs& a) {
  install_interrupt_handlers();
  const std::vector<const EngineEntry*> engines = parse_engine_list(a.engines);
  check_profile(engines, a.profile);
  int failed = 0, refuted = 0, refusals = 0, checks = 0;
  fmt::print("{:<18} {:<22} {:>10} {:>10}  {}\n", "engine/profile", "case", "figure", "tolerance", "verdict");
  for (const EngineEntry* e : engines) {
    if (!e->info.unavailable.empty()) {
      fmt::print("{:<18} unavailable: {}\n", e->info.name, e->info.unavailable);
      ++checks, ++failed;
      continue;
    }
    for (const std::string& profile : profiles_for(*e, a.profile))
      for (const ConformCaseDef& d : conform_cases()) {
        if (interrupt_signal()) break;
        double figure = 0;
        try {
          figure = conform_figure(*e, profile, d.c);
        } catch (const SceneUnsupported& refused) {
          // A case the engine says it cannot run: neither a pass nor a refuted claim.
          fmt::print("{:<18} {:<22} {:>10} {:>10}  refused: {}\n", run_label(e->info.name, profile), d.key, "-",
                     figure_text(d.tolerance), refused.what());
          ++checks, ++refusals;
          continue;
        }
        const bool pass = figure <= d.tolerance;
        const bool claimed = *d.capability && claims(e->info.caps, d.capability);
        const bool refutes = claimed && !(figure < d.refutes);
        ++checks, failed += !pass, refuted += refutes;
        fmt::print("{:<18} {:<22} {:>10} {:>10}  {}{}\n", run_label(e->info.name, profile), d.key, figure_text(figure),
                   figure_text(d.tolerance), pass ? "pass" : "FAIL",
                   refutes ? fmt::format(" (refutes its claim of {}: {} or more)", d.capability, figure_text(d.refutes))
                           : "");
      }
  }
  fmt::print("{} checks: {} passed, {} failed, {} refused{}\n", checks, checks - failed - refusals, failed, refusals,
             refuted ? fmt::format("; {} refute a capability the engine claims", refuted) : "");
  fmt::print("the closed forms:\n");
  for (const ConformCaseDef& d : conform_cases()) fmt::print("  {:<22} {}\n", d.key, d.closed_form);
  exit_if_interrupted("the checks above ran");
  if (failed > 0) throw CheckFailed{1};
}

}  // namespace

void add_conform(CLI::App& app) {
  auto a = std::make_shared<ConformArgs>();
  auto* cmd = app.add_subcommand(
      "conform", "the closed-form checks on any engine: one line per check, exit 1 where one fails");
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, process:CMD, or all")->required();
  cmd->add_option("--profile", a->profile, "settings profile, comma-separated profiles, or all (default: all)");
  add_quiet(cmd, a->quiet);
  cmd->callback([a] { conform(*a); });
}

}  // namespace ballbench::cli

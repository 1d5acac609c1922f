// `ballbench conform`: the closed-form checks (adapters/conformance.h) on any engine, built in or
// from an engines file: one line per check with its figure, its tolerance and pass or fail, and a
// capability the engine's handshake claims that a case refutes named as such.
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "conform_run.h"
#include "data_file.h"
#include "conformance.h"
#include "engine.h"
#include "input_error.h"
#include "interrupt.h"
#include "registry.h"
#include "result.h"
#include "run_engines.h"
#include "try_store.h"

namespace ballbench::cli {
namespace {

struct ConformArgs {
  std::string engines, profile = "all";
  std::string json;  // the rows as JSON (core/conform_result.h), or ""
  bool quiet = false;
};

void conform(const ConformArgs& a) {
  install_interrupt_handlers();
  const std::vector<const EngineEntry*> engines = parse_engine_list(a.engines);
  check_profile(engines, a.profile);
  if (!a.json.empty()) {
    std::vector<PathUse> uses = noted_input_files();
    uses.push_back({"--json", a.json, true});
    check_path_clashes(uses);
    check_writable(a.json, "the conformance results", true);
  }
  fmt::print("{:<18} {:<22} {:>10} {:>10}  {}\n", "engine/profile", "case", "figure", "tolerance", "verdict");
  const ConformResult c = run_conform(engines, a.profile, run_context(), true);
  keep_claim_checks(TryStore(TryStore::default_dir(), false), c, engines);
  size_t failed = 0, refused = 0, refuted = 0;
  for (const ConformRow& r : c.rows)
    failed += r.verdict == ConformVerdict::fail, refused += r.verdict == ConformVerdict::refused,
        refuted += !r.refuted.empty();
  fmt::print("{} checks: {} passed, {} failed, {} refused{}\n", c.rows.size(), c.rows.size() - failed - refused, failed,
             refused, refuted ? fmt::format("; {} refute a capability the engine claims", refuted) : "");
  fmt::print("the closed forms:\n");
  for (const ConformCaseDef& d : conform_cases()) fmt::print("  {:<22} {}\n", d.key, d.closed_form);
  if (!a.json.empty()) write_conform_file(a.json, c);
  exit_if_interrupted(a.json.empty() ? "the checks above ran" : "the checks above ran, and are in " + a.json);
  if (failed > 0) throw CheckFailed{1};
}

}  // namespace

void add_conform(CLI::App& app) {
  auto a = std::make_shared<ConformArgs>();
  auto* cmd = app.add_subcommand(
      "conform", "the closed-form checks on any engine: one line per check, exit 1 where one fails");
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, process:CMD, or all")->required();
  cmd->add_option("--profile", a->profile, "settings profile, comma-separated profiles, or all (default: all)");
  cmd->add_option("--json", a->json, "also write every check as JSON (what the report's engines page reads)");
  add_quiet(cmd, a->quiet);
  cmd->callback([a] { conform(*a); });
}

}  // namespace ballbench::cli

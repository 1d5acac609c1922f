// `ballbench list`: the built-in scenes and the engines with their versions and profiles;
// `ballbench list --metrics`: every metric of a run's JSON (core/metrics/catalog.h).
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "input_error.h"
#include "metrics/catalog.h"
#include "registry.h"
#include "scene_loader.h"

namespace ballbench::cli {
namespace {

void list() {
  fmt::print("scenes (built-in, in {}):\n", scenario_dir());
  for (const auto& name : builtin_scene_names()) {
    try {
      const Scene s = load_scene(name);
      fmt::print("  {:<16} {:>7} balls, dt {}, {} steps\n", name, s.n(), s.dt, s.steps());
    } catch (const InputError& e) {
      fmt::print("  {:<16} (invalid: {})\n", name, printable(e.what()));
    }
  }
  fmt::print("engines:\n");
  for (const auto& e : engine_registry()) {
    if (!e.info.unavailable.empty()) {
      fmt::print("  {:<12} {:<14} unavailable: {}\n", printable(e.info.name), "-", printable(e.info.unavailable));
      continue;
    }
    fmt::print("  {:<12} {:<14} {:<9} profiles: {:<14} {}\n", printable(e.info.name), printable(e.info.version),
               role_name(e.info.role), printable(fmt::format("{}", fmt::join(e.info.profiles, ","))),
               printable(e.info.summary));
  }
}

// One line per metric: its JSON key, unit, how `regress` compares it, and what it means.
void list_metrics() {
  const MetricsConfig cfg;
  for (const MetricDef& m : metric_catalog()) {
    if (m.key.empty()) continue;  // derived for a table only
    const std::string regress = !m.regress                                  ? "not compared"
                                : m.regress->rel == 0 && m.regress->abs == 0 ? "regress: exact"
                                                                             : fmt::format("regress: rel {:g}, abs {:g}",
                                                                                           m.regress->rel, m.regress->abs);
    fmt::print("{:<32} {:<9} {:<28} {}\n", m.key, m.unit.empty() ? "-" : m.unit, regress, m.definition(cfg));
  }
}

}  // namespace

void add_list(CLI::App& app) {
  auto* cmd = app.add_subcommand("list", "print the built-in scenes and the engines with their versions");
  auto metrics = std::make_shared<bool>(false);
  cmd->add_flag("--metrics", *metrics, "print every metric of a run's JSON instead: key, unit, regression tolerance, definition");
  cmd->callback([metrics] { *metrics ? list_metrics() : list(); });
}

}  // namespace ballbench::cli

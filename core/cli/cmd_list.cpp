// `ballbench list`: the built-in scenes and the engines with their versions and profiles;
// `ballbench list --metrics`: every metric of a run's JSON (core/metrics/catalog.h);
// `ballbench list --settings ENGINE`: the engine's user settings (EngineInfo::settings).
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "progress.h"
#include "input_error.h"
#include "interrupt.h"
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

// One line per user setting of the engine: its key, its default (before a profile), the values it
// takes, its unit and what it does. An engine without a settings table lists none.
void list_settings(const std::string& name) {
  const EngineEntry& e = find_engine(name);
  if (e.info.settings.empty()) {
    fmt::print("{}: no settings table (its settings: adapters' README)\n", e.info.name);
    return;
  }
  fmt::print("{} settings (--set {}.KEY=VALUE; default: before a profile changes it):\n", e.info.name, e.info.name);
  for (const SettingInfo& s : e.info.settings)
    fmt::print("  {:<36} {:<10} {:<22} {:<6} {}\n", s.name, s.default_value.dump(), s.range.empty() ? "-" : s.range,
               s.unit.empty() ? "-" : s.unit, s.doc);
}

}  // namespace

void add_list(CLI::App& app) {
  auto* cmd = app.add_subcommand("list", "print the built-in scenes and the engines with their versions");
  auto metrics = std::make_shared<bool>(false);
  cmd->add_flag("--metrics", *metrics, "print every metric of a run's JSON instead: key, unit, regression tolerance, definition");
  auto settings = std::make_shared<std::string>();
  cmd->add_option("--settings", *settings, "print ENGINE's settings instead: key, default, values, unit, what it does")
      ->type_name("ENGINE");
  add_quiet(cmd, Progress::quiet);
  cmd->callback([metrics, settings] {
    // A stop request ends a wait for an engine's handshake at once (interrupt.h), and the command
    // with the signal's status.
    install_interrupt_handlers();
    if (!settings->empty()) list_settings(*settings);
    else *metrics ? list_metrics() : list();
    exit_if_interrupted("the list above was printed whole");
  });
}

}  // namespace ballbench::cli

// `ballbench list`: the built-in scenes and the engines with their versions and profiles;
// `ballbench list --metrics`: every metric of a run's JSON (core/metrics/catalog.h);
// `ballbench list --settings ENGINE`: the engine's user settings (EngineInfo::settings).
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "progress.h"
#include "input_error.h"
#include "interrupt.h"
#include "markdown_cell.h"
#include "metrics/catalog.h"
#include "metrics/meter.h"
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

// How `regress` compares a metric: "exact", "rel 1e-09, abs 1e-12", or "not compared".
std::string tolerance_text(const MetricDef& m) {
  if (!m.regress) return "not compared";
  if (m.regress->rel == 0 && m.regress->abs == 0) return "exact";
  return fmt::format("rel {:g}, abs {:g}", m.regress->rel, m.regress->abs);
}

const char* stage_text(MetricStage s) {
  switch (s) {
    case MetricStage::sample: return "every sample";
    case MetricStage::motion: return "every step's motion";
    case MetricStage::final_state: return "the final state";
  }
  return "";
}

// One line per metric: its JSON key, unit, how `regress` compares it, and what it means; as
// Markdown, a table with the file that measures it and the stage it watches (docs/metrics.md holds
// it).
void list_metrics(bool markdown) {
  const MetricsConfig cfg;
  if (markdown)
    fmt::print("| key | unit | measured by | at | regress | definition |\n|---|---|---|---|---|---|\n");
  for (const MetricFamily& f : metric_families())
    for (const MetricDef& m : f.rows) {
      if (m.key.empty()) continue;  // derived for a table only
      if (markdown)
        fmt::print("| `{}` | {} | core/metrics/{}_metric.cpp | {} | {} | {} |\n", m.key, m.unit.empty() ? "-" : m.unit,
                   f.name, stage_text(f.stage), tolerance_text(m), markdown_cell(m.definition(cfg)));
      else
        fmt::print("{:<32} {:<9} {:<28} {}\n", m.key, m.unit.empty() ? "-" : m.unit,
                   m.regress ? "regress: " + tolerance_text(m) : tolerance_text(m), m.definition(cfg));
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
  auto markdown = std::make_shared<bool>(false);
  cmd->add_flag("--markdown", *markdown, "with --metrics: as a Markdown table with the file and stage of each (docs/metrics.md)")
      ->needs(cmd->get_option("--metrics"));
  auto settings = std::make_shared<std::string>();
  cmd->add_option("--settings", *settings, "print ENGINE's settings instead: key, default, values, unit, what it does")
      ->type_name("ENGINE");
  add_quiet(cmd, Progress::quiet);
  cmd->callback([metrics, markdown, settings] {
    // A stop request ends a wait for an engine's handshake at once (interrupt.h), and the command
    // with the signal's status.
    install_interrupt_handlers();
    if (!settings->empty()) list_settings(*settings);
    else *metrics ? list_metrics(*markdown) : list();
    exit_if_interrupted("the list above was printed whole");
  });
}

}  // namespace ballbench::cli

// `ballbench list`: the built-in scenes and the engines with their versions and profiles.
#include <fmt/format.h>

#include "commands.h"
#include "input_error.h"
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
      fmt::print("  {:<16} (invalid: {})\n", name, e.what());
    }
  }
  fmt::print("engines:\n");
  for (const auto& e : engine_registry()) {
    if (!e.info.unavailable.empty()) {
      fmt::print("  {:<12} {:<14} unavailable: {}\n", e.info.name, "-", e.info.unavailable);
      continue;
    }
    fmt::print("  {:<12} {:<14} {:<9} profiles: {:<14} {}\n", e.info.name, e.info.version, role_name(e.info.role),
               fmt::format("{}", fmt::join(e.info.profiles, ",")), e.info.summary);
  }
}

}  // namespace

void add_list(CLI::App& app) {
  app.add_subcommand("list", "print the built-in scenes and the engines with their versions")->callback(list);
}

}  // namespace ballbench::cli

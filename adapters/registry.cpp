#include "registry.h"

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "adapter_engines.h"
#include "data_file.h"
#include "input_error.h"
#include "process/engines_file.h"
#include "process/process_engine.h"
#include "solver/exact.h"
#include "solver/home.h"
#include "solver/home_seed.h"

namespace ballbench {
namespace {

// Our solvers, then the adapters (each folder's CMakeLists.txt registers its own).
const std::vector<EngineEntry>& builtin_engines() {
  static const std::vector<EngineEntry> engines = [] {
    std::vector<EngineEntry> all = {home_seed_engine(), home_engine(), exact_engine()};
    for (EngineEntry& e : adapter_engines()) all.push_back(std::move(e));
    return all;
  }();
  return engines;
}

std::vector<std::string>& user_engines_files() {
  static std::vector<std::string> files;
  return files;
}

// Built-ins, then one entry per engines-file engine, filled in from its handshake on first lookup.
struct Registry {
  std::vector<EngineEntry> entries;        // never resized after construction: pointers stay valid
  size_t builtins = 0;
  std::vector<ProcessEngineSpec> external;  // entries[builtins + k] is external[k]'s
  std::vector<bool> resolved;
  std::deque<std::pair<std::string, EngineEntry>> commands;  // `process:CMD` entries, by CMD as typed

  Registry() {
    entries = builtin_engines();
    builtins = entries.size();
    std::vector<std::string> files;
    const char* env = std::getenv("BALLBENCH_ENGINES");
    if (env) {
      if (*env) files.push_back(env);
    } else if (std::error_code ec; std::filesystem::exists(BALLBENCH_ENGINES_FILE, ec)) {
      files.push_back(BALLBENCH_ENGINES_FILE);
    }
    // An input no output may overwrite (the user's --engines files are noted where they are given).
    if (!files.empty()) note_input_file("the engines file", files.front());
    for (const auto& f : user_engines_files()) files.push_back(f);
    for (const auto& f : files)
      for (auto& spec : read_engines_file(f)) {
        const auto clash = std::find_if(entries.begin(), entries.end(), [&](const EngineEntry& e) { return e.info.name == spec.name; });
        if (clash != entries.end())
          throw InputError(fmt::format("{}: engine.name: '{}' is already an engine's name", spec.source, spec.name));
        EngineEntry placeholder;
        placeholder.info.name = spec.name;
        entries.push_back(std::move(placeholder));
        external.push_back(std::move(spec));
      }
    resolved.assign(external.size(), false);
  }

  void resolve(const std::vector<size_t>& which) {
    std::vector<ProcessEngineSpec> specs;
    for (size_t k : which) specs.push_back(external[k]);
    std::vector<EngineEntry> made = process_engine_entries(specs);
    for (size_t j = 0; j < which.size(); ++j) {
      EngineEntry& e = entries[builtins + which[j]];
      e = std::move(made[j]), resolved[which[j]] = true;
      if (specs[j].file != BALLBENCH_ENGINES_FILE) e.engines_file = specs[j].file;
    }
  }
  void resolve_all() {
    std::vector<size_t> which;
    for (size_t k = 0; k < external.size(); ++k)
      if (!resolved[k]) which.push_back(k);
    if (!which.empty()) resolve(which);
  }
};

bool& registry_built() {
  static bool built = false;
  return built;
}

Registry& registry() {
  static Registry r = [] {
    Registry made;
    registry_built() = true;
    return made;
  }();
  return r;
}

const EngineEntry& find_command_engine(const std::string& text) {
  Registry& reg = registry();
  for (const auto& [typed, entry] : reg.commands)
    if (typed == text) return entry;
  EngineEntry e = process_engine_entry(parse_process_engine(text));
  for (const auto& name : engine_names())
    if (name == e.info.name)
      throw InputError(fmt::format("--engine '{}': the process calls itself '{}', already an engine's name", text, name));
  reg.commands.emplace_back(text, std::move(e));
  return reg.commands.back().second;
}

}  // namespace

const std::vector<EngineEntry>& engine_registry() {
  Registry& reg = registry();
  reg.resolve_all();
  return reg.entries;
}

std::vector<std::string> engine_names() {
  std::vector<std::string> names;
  for (const auto& e : registry().entries) names.push_back(e.info.name);
  for (const auto& [typed, e] : registry().commands) names.push_back(e.info.name);
  return names;
}

bool is_builtin_engine(const std::string& name) {
  const auto& b = builtin_engines();
  return std::any_of(b.begin(), b.end(), [&](const EngineEntry& e) { return e.info.name == name; });
}

void use_engines_file(const std::string& path) {
  if (registry_built()) throw InputError(fmt::format("--engines {}: given after the engines were read", path));
  user_engines_files().push_back(path);
}

const EngineEntry* reference_engine() {
  Registry& reg = registry();
  for (size_t i = 0; i < reg.builtins; ++i)
    if (reg.entries[i].info.role == EngineRole::reference) return &reg.entries[i];
  return nullptr;
}

const EngineEntry* converged_reference_engine() { return &find_engine("chipmunk"); }

void use_reference(RunOptions& options) {
  options.reference = reference_engine();
  options.converged_reference = converged_reference_engine();
}

std::map<std::string, EngineRole> engine_roles() {
  // The built-ins only: an engine of an engines file is external (the default), and reading its
  // role must not start its process for the handshake.
  std::map<std::string, EngineRole> roles;
  for (const auto& e : builtin_engines()) roles[e.info.name] = e.info.role;
  return roles;
}

const EngineEntry& find_engine(const std::string& name) {
  if (name.rfind("process:", 0) == 0) return find_command_engine(name);
  Registry& reg = registry();
  for (size_t i = 0; i < reg.entries.size(); ++i) {
    if (reg.entries[i].info.name != name) continue;
    if (i >= reg.builtins && !reg.resolved[i - reg.builtins]) reg.resolve({i - reg.builtins});
    return reg.entries[i];
  }
  for (const auto& [typed, e] : reg.commands)  // a `process:CMD` engine named before, by the name it gave
    if (e.info.name == name) return e;
  const std::vector<std::string> names = engine_names();
  throw InputError(fmt::format("--engine: unknown engine '{}'{} (known: {}, process:CMD, or all)", name,
                               did_you_mean(name, names), fmt::join(names, ", ")));
}

std::vector<const EngineEntry*> parse_engine_list(const std::string& list) {
  std::vector<const EngineEntry*> out;
  if (list == "all") {
    for (const auto& e : engine_registry()) out.push_back(&e);
    return out;
  }
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name.empty()) throw InputError(fmt::format("--engine: empty name in '{}'", list));
    const EngineEntry* e = &find_engine(name);
    if (std::find(out.begin(), out.end(), e) != out.end())
      throw InputError(fmt::format("--engine: '{}' is named twice", name));
    out.push_back(e);
  }
  if (out.empty()) throw InputError("--engine: no engine named");
  return out;
}

}  // namespace ballbench

#include "registry.h"

#include <algorithm>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "box2d/box2d_engine.h"
#include "bullet/bullet_engine.h"
#include "chipmunk/chipmunk_engine.h"
#include "input_error.h"
#include "ode/ode_engine.h"
#include "solver/exact.h"
#include "solver/home.h"
#include "solver/home_seed.h"

namespace ballbench {

const std::vector<EngineEntry>& engine_registry() {
  static const std::vector<EngineEntry> engines = {
      home_seed_engine(),
      home_engine(),
      exact_engine(),
      box2d_engine(),
      bullet_engine(),
      chipmunk_engine(),
      ode_engine(),
  };
  return engines;
}

const EngineEntry* reference_engine() {
  for (const auto& e : engine_registry())
    if (e.info.role == EngineRole::reference) return &e;
  return nullptr;
}

std::map<std::string, EngineRole> engine_roles() {
  std::map<std::string, EngineRole> roles;
  for (const auto& e : engine_registry()) roles[e.info.name] = e.info.role;
  return roles;
}

const EngineEntry& find_engine(const std::string& name) {
  const auto& all = engine_registry();
  const auto it = std::find_if(all.begin(), all.end(), [&](const EngineEntry& e) { return e.info.name == name; });
  if (it != all.end()) return *it;
  std::vector<std::string> names;
  for (const auto& e : all) names.push_back(e.info.name);
  throw InputError(fmt::format("--engine: unknown engine '{}'{} (known: {}, or all)", name, did_you_mean(name, names),
                               fmt::join(names, ", ")));
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

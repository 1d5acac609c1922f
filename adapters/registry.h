#pragma once
// Every engine the harness knows: our own solvers and the adapters. Adding an engine is one folder
// under adapters/ and one line in registry.cpp.
#include <map>
#include <string>
#include <vector>

#include "engine.h"

namespace ballbench {

const std::vector<EngineEntry>& engine_registry();

// The engine errors are measured against (role `reference`: `exact`, event-driven), or null if
// none is built in.
const EngineEntry* reference_engine();

// Engine name -> role, for the report (which reads result files and knows engines only by name).
std::map<std::string, EngineRole> engine_roles();

// By name; throws InputError naming the known engines.
const EngineEntry& find_engine(const std::string& name);

// "home,box2d" or "all" -> entries, in the order given; throws InputError for an unknown name or
// a name given twice.
std::vector<const EngineEntry*> parse_engine_list(const std::string& list);

}  // namespace ballbench

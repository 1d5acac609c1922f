#pragma once
// Every engine the harness knows: our own solvers and the adapters (adding one is one folder under
// adapters/ whose CMakeLists.txt registers it: adapters/CMakeLists.txt), then the external engines of the engines files
// (adapters/process/engines_file.h): the project's engines.toml and one a user passes with
// --engines. The registry is built once, on first use; an external engine's process is started
// for its handshake only when its entry is first looked up.
#include <map>
#include <string>
#include <vector>

#include "engine.h"
#include "runner.h"

namespace ballbench {

// Every engine, built-ins first; the external ones' handshakes are made here (all at once).
const std::vector<EngineEntry>& engine_registry();

// Every engine's name, without starting any process.
std::vector<std::string> engine_names();

// True for our solvers and the adapters linked into ballbench; false for engines in processes.
bool is_builtin_engine(const std::string& name);

// Adds a user's engines file (--engines FILE) to the project's; call it before the registry's
// first use (a later call is an InputError). BALLBENCH_ENGINES, if set, replaces the project's
// file ("" for none).
void use_engines_file(const std::string& path);

// The engine errors are measured against (role `reference`: `exact`, event-driven), or null if
// none is built in.
const EngineEntry* reference_engine();

// The engine whose converged run (RunOptions::converged_reference) stands in for `exact` on a scene
// exact refuses: Chipmunk, double precision, whose single contacts are exact impulses (slide to
// roll to 1e-15 of the closed form) and which runs friction at 1 - 3 us per ball-step.
const EngineEntry* converged_reference_engine();

// Sets `options`' reference (exact) and its stand-in for scenes exact refuses.
void use_reference(RunOptions& options);

// Engine name -> role of the built-ins, for the report (which reads result files and knows engines
// only by name); every other engine is external.
std::map<std::string, EngineRole> engine_roles();

// By name, or `process:CMD` for a command speaking adapters/process/PROTOCOL.md; throws
// InputError naming the known engines.
const EngineEntry& find_engine(const std::string& name);

// "home,box2d" or "all" -> entries, in the order given; throws InputError for an unknown name or
// a name given twice.
std::vector<const EngineEntry*> parse_engine_list(const std::string& list);

}  // namespace ballbench

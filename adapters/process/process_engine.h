#pragma once
// An engine in another process, in any language, driven through the engine process protocol
// (PROTOCOL.md beside this file): `ballbench run --engine process:CMD`, or named in an engines
// file (engines_file.h). Its EngineInfo comes from the process's handshake.
#include <string>
#include <vector>

#include "engine.h"

namespace ballbench {

struct ProcessEngineSpec {
  std::string name;                  // registered name; "" takes the one the handshake gives
  std::vector<std::string> command;  // argv; argv[0] is looked up on PATH
  std::string cwd;                   // folder the command runs in ("" = this process's)
  double timeout_s = 60;             // the longest wait for any one reply (s); a hang past it is an error
  std::string source;                // where it was named, for messages: "engines.toml:12", "--engine"
  std::string file;                  // the engines file that names it, as given ("" for `process:CMD`)
};

// Starts the command, asks for its handshake, and builds the entry. Never throws for what the
// process does: an engine that cannot start or answer is an entry whose info.unavailable gives
// the reason (its rows are then unsupported, with that reason). The process stays for the first
// run, and every run's process is kept after it for the next scene (a new scene replaces the
// world), so a sequence of runs in one harness process starts the engine once.
EngineEntry process_engine_entry(const ProcessEngineSpec& spec);

// The same for several, their processes started together so their start-up times overlap.
std::vector<EngineEntry> process_engine_entries(const std::vector<ProcessEngineSpec>& specs);

// The longest a handshake made by process_engine_entries may take (s), below each engine's own reply
// limit: a command's --timeout, which bounds everything an engine does for it.
void limit_handshake_seconds(double seconds);

// "process:python3 my_engine.py" -> the spec of an engine named on the command line (argv split at
// spaces, run in the current folder); InputError for an empty command.
ProcessEngineSpec parse_process_engine(const std::string& text);

}  // namespace ballbench

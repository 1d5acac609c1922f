#pragma once
// An engines file (TOML) names external engines, each a command speaking PROTOCOL.md, so they join
// the registry like built-ins: the project's engines.toml, and one a user passes with --engines.
//
//   [[engine]]
//   name = "rapier"                               # as typed after --engine
//   command = ["node", "adapters/node/rapier.js"]  # run in the file's folder; argv[0] on PATH
//   timeout_s = 60                                 # optional: the longest wait for one reply (s)
#include <string>
#include <vector>

#include "process_engine.h"

namespace ballbench {

// The engines of one file, in order; InputError (FILE:LINE: what: why) for a missing or malformed
// file, an unknown key or a name given twice.
std::vector<ProcessEngineSpec> read_engines_file(const std::string& path);

}  // namespace ballbench

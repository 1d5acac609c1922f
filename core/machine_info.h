#pragma once
// Where a result was measured: recorded in every report so numbers can be read in context.
#include <string>

namespace ballbench {

struct MachineInfo {
  std::string cpu;        // model name from /proc/cpuinfo
  unsigned cores = 0;     // hardware threads
  std::string os;         // kernel release
  std::string compiler;   // compiler and version
  std::string build_type; // CMake build type
  std::string flags;      // optimisation flags of that build type
  std::string build;      // build_id()
};

MachineInfo machine_info();

// The running binary: XXH3-64 of its bytes (/proc/self/exe), 16 hex digits, "unknown" where it
// cannot be read. Two results of one build id were computed by the same code.
const std::string& build_id();

}  // namespace ballbench

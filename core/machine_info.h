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
};

MachineInfo machine_info();

}  // namespace ballbench

#include "machine_info.h"

#include <sys/utsname.h>

#include <fstream>
#include <memory>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <xxhash.h>

namespace ballbench {

MachineInfo machine_info() {
  MachineInfo m;
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) {
      m.cpu = line.substr(line.find(':') + 2);
      break;
    }
  if (m.cpu.empty()) m.cpu = "unknown";
  m.cores = std::thread::hardware_concurrency();
  utsname u{};
  if (uname(&u) == 0) m.os = std::string(u.sysname) + " " + u.release + " " + u.machine;
#if defined(__clang__)
  m.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
  m.compiler = "g++ " __VERSION__;
#else
  m.compiler = "unknown";
#endif
  m.build_type = BALLBENCH_BUILD_TYPE;
  m.flags = BALLBENCH_CXX_FLAGS;
  m.build = build_id();
  return m;
}

const std::string& build_id() {
  // Hashed in blocks as read: every command computes it, and a sanitized executable is tens of MB.
  static const std::string id = [] {
    std::ifstream exe("/proc/self/exe", std::ios::binary);
    std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(), &XXH3_freeState);
    if (!exe || !state || XXH3_64bits_reset(state.get()) != XXH_OK) return std::string("unknown");
    std::vector<char> block(1 << 20);
    std::size_t total = 0;
    while (exe.read(block.data(), std::streamsize(block.size())) || exe.gcount() > 0) {
      XXH3_64bits_update(state.get(), block.data(), std::size_t(exe.gcount()));
      total += std::size_t(exe.gcount());
    }
    return total == 0 ? std::string("unknown") : fmt::format("{:016x}", XXH3_64bits_digest(state.get()));
  }();
  return id;
}

}  // namespace ballbench

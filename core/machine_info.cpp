#include "machine_info.h"

#include <sys/utsname.h>

#include <fstream>
#include <iterator>
#include <thread>

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
  static const std::string id = [] {
    std::ifstream exe("/proc/self/exe", std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(exe), std::istreambuf_iterator<char>()};
    return bytes.empty() ? std::string("unknown") : fmt::format("{:016x}", XXH3_64bits(bytes.data(), bytes.size()));
  }();
  return id;
}

}  // namespace ballbench

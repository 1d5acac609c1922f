#include "core_wait.h"

#include <fcntl.h>
#include <unistd.h>

#include <charconv>
#include <string>

namespace ballbench {

CoreWait::CoreWait(pid_t pid) {
  const std::string path = "/proc/" + std::to_string(pid) + "/schedstat";
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
}

CoreWait::~CoreWait() {
  if (fd_ >= 0) ::close(fd_);
}

// "ON_CPU_NS WAITED_NS TIMESLICES\n": the second field.
std::optional<double> CoreWait::waited_s() const {
  if (fd_ < 0) return std::nullopt;
  char buf[96];
  const ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
  if (n <= 0) return std::nullopt;
  const char* p = buf;
  const char* end = buf + n;
  unsigned long long on_cpu = 0, waited = 0;
  auto r = std::from_chars(p, end, on_cpu);
  if (r.ec != std::errc() || r.ptr == end || *r.ptr != ' ') return std::nullopt;
  r = std::from_chars(r.ptr + 1, end, waited);
  if (r.ec != std::errc()) return std::nullopt;
  return static_cast<double>(waited) * 1e-9;
}

}  // namespace ballbench

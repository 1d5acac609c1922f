#include "core_affinity.h"

#include <sched.h>

#include <algorithm>
#include <thread>

namespace ballbench {
namespace {

bool run_on(const std::vector<int>& cores) {
  cpu_set_t set;
  CPU_ZERO(&set);
  for (int c : cores)
    if (c >= 0 && c < CPU_SETSIZE) CPU_SET(c, &set);
  return ::sched_setaffinity(0, sizeof set, &set) == 0;
}

}  // namespace

std::vector<int> allowed_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> out;
  if (::sched_getaffinity(0, sizeof set, &set) != 0) return out;
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &set)) out.push_back(c);
  return out;
}

int core_count() {
  const size_t allowed = allowed_cores().size();
  return allowed > 0 ? int(allowed) : std::max(1, int(std::thread::hardware_concurrency()));
}

CorePin::CorePin(int core) {
  if (core < 0) return;
  before_ = allowed_cores();
  if (before_.empty() || !run_on({core})) before_.clear();
}

CorePin::~CorePin() {
  if (!before_.empty()) run_on(before_);
}

}  // namespace ballbench

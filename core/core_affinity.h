#pragma once
// Which cores a run may use. A timing is spread over the cores in turn: on a shared host one core
// can run the same steps over a quarter slower than the other for minutes at a time (this 2-core VM:
// our solver's pile read 0.44 s on core 0 and 0.35 s on core 1, run after run), so where a timing
// lands decides its figure unless it visits each.
#include <vector>

namespace ballbench {

// The cores this process may run on (its affinity mask), in order; empty where it cannot be read.
std::vector<int> allowed_cores();

// How many runs go side by side by default: the cores this process may run on, at least one.
int core_count();

// Runs the calling thread on `core` only until this is destroyed, then as before (core < 0: no
// change). Where the system refuses, the thread runs where it did.
class CorePin {
 public:
  explicit CorePin(int core);
  ~CorePin();
  CorePin(const CorePin&) = delete;
  CorePin& operator=(const CorePin&) = delete;

 private:
  std::vector<int> before_;  // the cores it ran on before; empty: nothing to restore
};

}  // namespace ballbench

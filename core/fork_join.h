#pragma once
// A fixed team of threads for per-ball loops (the home solver's step, the harness's tunnelling
// check): run(f) calls f(part) for every part 0 .. parts() - 1, part 0 on the calling thread, and
// returns when all are done.
//
// Why not OpenMP: the runner isolates each engine run in a fork()ed child (core/isolated_run.cpp),
// and GCC's libgomp hangs in a child forked after the parent used a parallel region (measured on
// this machine with a ten-line program). Here the threads belong to the object that uses them (an
// engine, a tunnelling check), so one built in the child has its own.
//
// Determinism: callers give each part a fixed, contiguous range of work and never reduce floating
// point sums across parts; results are then the same for any number of parts.
#include <atomic>
#include <functional>
#include <thread>
#include <vector>

namespace ballbench {

class ForkJoin {
 public:
  // `threads` parts in all (the caller counts as one); 1 runs everything inline.
  explicit ForkJoin(int threads);
  ~ForkJoin();
  ForkJoin(const ForkJoin&) = delete;
  ForkJoin& operator=(const ForkJoin&) = delete;

  int parts() const { return static_cast<int>(workers_.size()) + 1; }
  void run(const std::function<void(int part)>& f);

  // [begin, end) of part p when n items are split into parts() contiguous ranges.
  static long range_begin(long n, int p, int parts) { return n * p / parts; }

  // How many threads a team for n balls should have: `requested` if positive, else one below
  // `parallel_from` balls (waking a thread costs more than it saves there) and the machine's cores
  // (at most 8) from there on. Each user measures its own `parallel_from`.
  static int threads_for(int n, int parallel_from, int requested);

 private:
  void work(int part);

  std::vector<std::thread> workers_;
  const std::function<void(int)>* job_ = nullptr;
  std::atomic<unsigned> generation_{0};  // bumped for every job (and at shutdown)
  std::atomic<int> pending_{0};          // workers still running the current job
  bool stop_ = false;
};

}  // namespace ballbench

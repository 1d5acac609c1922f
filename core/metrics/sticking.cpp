#include "metrics/sticking.h"

namespace ballbench {

void StickingTracker::observe(const std::vector<Overlap>& deep_pairs, const std::vector<char>& deep_in_wall) {
  const long long n = static_cast<long long>(wall_run_.size());
  next_run_.clear();
  for (const Overlap& o : deep_pairs) {
    const long long key = o.i * n + o.j;
    const auto it = pair_run_.find(key);
    const int run = (it == pair_run_.end() ? 0 : it->second) + 1;
    if (run == max_samples_ + 1) ++pair_events_;
    next_run_[key] = run;
  }
  pair_run_.swap(next_run_);  // pairs no longer overlapping end their run
  for (size_t i = 0; i < wall_run_.size(); ++i) {
    wall_run_[i] = deep_in_wall[i] ? wall_run_[i] + 1 : 0;
    if (wall_run_[i] == max_samples_ + 1) ++wall_events_;
  }
}

}  // namespace ballbench

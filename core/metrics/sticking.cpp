#include "metrics/sticking.h"

namespace ballbench {

int StickingTracker::advance(int run, bool leaving, int& events) const {
  if (run < 0) return run - 1;  // counted already: the episode goes on
  ++run;
  if (run > max_samples_ && !leaving) {
    ++events;
    return -run;
  }
  return run;
}

void StickingTracker::observe(const std::vector<Overlap>& deep_pairs, const std::vector<char>& pair_leaving,
                              const std::vector<char>& deep_in_wall, const std::vector<char>& wall_leaving) {
  const long long n = static_cast<long long>(wall_run_.size());
  next_run_.clear();
  counted_pairs_.clear(), counted_walls_.clear();
  for (size_t k = 0; k < deep_pairs.size(); ++k) {
    const Overlap& o = deep_pairs[k];
    const long long key = o.i * n + o.j;
    const auto it = pair_run_.find(key);
    const int before = pair_events_;
    next_run_[key] = advance(it == pair_run_.end() ? 0 : it->second, pair_leaving[k], pair_events_);
    if (pair_events_ != before) counted_pairs_.push_back({o.i, o.j});
  }
  pair_run_.swap(next_run_);  // pairs no longer overlapping end their run
  for (size_t i = 0; i < wall_run_.size(); ++i) {
    const int before = wall_events_;
    wall_run_[i] = deep_in_wall[i] ? advance(wall_run_[i], wall_leaving[i], wall_events_) : 0;
    if (wall_events_ != before) counted_walls_.push_back(static_cast<int>(i));
  }
}

}  // namespace ballbench

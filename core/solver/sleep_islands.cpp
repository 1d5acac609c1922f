#include "solver/sleep_islands.h"

#include <algorithm>

#include "solver/contact.h"

namespace ballbench {

SleepIslands::SleepIslands(int n, double speed, double time)
    : n_(n), speed_(speed), time_(time), state_(n, kAwake), still_for_(n, 0.0), island_of_(n, -1) {}

template <class F>
void SleepIslands::for_awake(F&& f) const {
  if (sleeping_ > 0)
    for (int i : awake_) f(i);
  else
    for (int i = 0; i < n_; ++i) f(i);
}

void SleepIslands::wake_touched(const std::vector<SoftContact>& contacts, const double* vx, const double* vy) {
  woken_.clear();
  waking_islands_.clear();
  const double limit2 = speed_ * speed_;
  for (const SoftContact& c : contacts) {
    if (c.j < 0 || (state_[c.i] == kAsleep) == (state_[c.j] == kAsleep)) continue;
    const double wx = vx[c.i] - vx[c.j], wy = vy[c.i] - vy[c.j];
    if (wx * wx + wy * wy <= limit2) continue;
    const int64_t island = island_of_[state_[c.i] == kAsleep ? c.i : c.j];
    if (std::find(waking_islands_.begin(), waking_islands_.end(), island) == waking_islands_.end())
      waking_islands_.push_back(island);
  }
  if (waking_islands_.empty()) return;
  for (int b = 0; b < n_; ++b)
    if (state_[b] == kAsleep &&
        std::find(waking_islands_.begin(), waking_islands_.end(), island_of_[b]) != waking_islands_.end()) {
      state_[b] = kWoken, still_for_[b] = 0, --sleeping_;
      woken_.push_back(b);
    }
}

void SleepIslands::finish_waking() {
  for (int i : woken_) state_[i] = kAwake;
}

const std::vector<int>& SleepIslands::awake(const double* inv_mass, double inv_mass0) {
  awake_.clear();
  if (sleeping_ == 0) return awake_;
  held_inv_mass_.resize(n_);
  for (int i = 0; i < n_; ++i) {
    held_inv_mass_[i] = state_[i] != kAwake ? 0.0 : inv_mass ? inv_mass[i] : inv_mass0;
    if (state_[i] == kAwake) awake_.push_back(i);
  }
  return awake_;
}

void SleepIslands::fall_asleep(const std::vector<SoftContact>& contacts, double* vx, double* vy, double dt) {
  const double limit2 = speed_ * speed_;
  bool any_still = false;
  for_awake([&](int i) {
    const bool slow = vx[i] * vx[i] + vy[i] * vy[i] <= limit2;
    still_for_[i] = slow ? still_for_[i] + dt : 0.0;
    any_still = any_still || still_for_[i] >= time_;
  });
  if (!any_still) return;
  // Union-find (path halving) over the awake balls; each root holds its island's least still time.
  root_.resize(n_);
  for_awake([&](int i) { root_[i] = i; });
  const auto root = [&](int i) {
    while (root_[i] != i) i = root_[i] = root_[root_[i]];
    return i;
  };
  for (const SoftContact& c : contacts)
    if (c.j >= 0 && c.impulse > 0 && state_[c.i] == kAwake && state_[c.j] == kAwake) {
      const int a = root(c.i), b = root(c.j);
      if (a != b) root_[std::max(a, b)] = std::min(a, b);
    }
  island_still_.resize(n_);
  for_awake([&](int i) { island_still_[i] = kNever; });
  for_awake([&](int i) {
    double& t = island_still_[root(i)];
    t = std::min(t, still_for_[i]);
  });
  // Island labels stay unique across steps: this step's roots offset past every earlier label.
  falling_.clear();
  for_awake([&](int i) {
    const int r = root(i);
    if (island_still_[r] < time_) return;
    island_of_[i] = islands_ + r;
    falling_.push_back(i);
  });
  islands_ += n_;
  for (int i : falling_) state_[i] = kAsleep, vx[i] = vy[i] = 0, ++sleeping_;
}

}  // namespace ballbench

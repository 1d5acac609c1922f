#pragma once
// The impulses the home solver's contact pass ended the last step with, for warm starting (Catto,
// "Iterative Dynamics with Temporal Coherence", GDC 2005), looked up by contact: ball i and partner
// j (a ball if j >= 0, a wall code if j < 0).
//
// Stored by first ball in compressed rows, rebuilt by a counting sort: O(balls + contacts) per step,
// a lookup scans the few contacts of one ball. 4 bytes per ball and 12 per contact; the
// std::unordered_map it replaces took a node (~40 bytes) and a hash per contact.
#include <vector>

namespace ballbench {

class WarmStart {
 public:
  struct Entry {
    int i, j;
    double impulse;
  };

  // Replaces the contents with `entries` (any order; one entry per (i, j)) for balls 0 .. n-1.
  void assign(int n, const std::vector<Entry>& entries) {
    if (entries.empty()) {
      first_.clear(), j_.clear(), impulse_.clear();
      return;
    }
    first_.assign(static_cast<size_t>(n) + 1, 0);
    for (const Entry& e : entries) ++first_[e.i + 1];
    for (int i = 0; i < n; ++i) first_[i + 1] += first_[i];
    fill_.assign(first_.begin(), first_.end() - 1);
    j_.resize(entries.size()), impulse_.resize(entries.size());
    for (const Entry& e : entries) {
      const int k = fill_[e.i]++;
      j_[k] = e.j, impulse_[k] = e.impulse;
    }
  }

  // The impulse stored for (i, j), or a negative number if there is none.
  double find(int i, int j) const {
    if (first_.empty()) return -1.0;
    for (int k = first_[i]; k < first_[i + 1]; ++k)
      if (j_[k] == j) return impulse_[k];
    return -1.0;
  }

  // Calls f(Entry) for every stored contact.
  template <class F>
  void for_each(F&& f) const {
    if (first_.empty()) return;
    for (int i = 0; i + 1 < static_cast<int>(first_.size()); ++i)
      for (int k = first_[i]; k < first_[i + 1]; ++k) f(Entry{i, j_[k], impulse_[k]});
  }

 private:
  std::vector<int> first_;  // (balls + 1) prefix sums; empty when nothing is stored
  std::vector<int> fill_;   // scratch for the scatter
  std::vector<int> j_;
  std::vector<double> impulse_;
};

}  // namespace ballbench

#pragma once
// The impulses the home solver's contact pass ended the last step with, for warm starting (Catto,
// "Iterative Dynamics with Temporal Coherence", GDC 2005), looked up by contact: ball i and partner
// j (a ball if j >= 0, a wall code if j < 0).
//
// An open-addressing hash table (linear probing) over the stored contacts only: O(contacts) per
// step to rebuild, and no array over every ball (rows by ball would take a counting sort over all
// balls every step, ~2 ms at 10^6 bowl balls with a few thousand contacts stored), nor a node and
// an allocation per contact (std::unordered_map).
#include <cstdint>
#include <utility>
#include <vector>

namespace ballbench {

class WarmStart {
 public:
  struct Entry {
    int i, j;
    double impulse;       // normal (N s)
    double tangent = 0;   // friction's, along the tangent (-n_y, n_x) (N s)
  };

  // Replaces the contents with `entries` (any order; one entry per (i, j)).
  void assign(const std::vector<Entry>& entries) {
    entries_ = entries;
    size_t size = 16;
    int bits = 4;
    while (size < 2 * entries_.size()) size *= 2, ++bits;  // at most half full: short probes
    mask_ = size - 1, shift_ = 64 - bits;
    slot_.assign(size, kEmpty);
    for (size_t k = 0; k < entries_.size(); ++k) {
      size_t s = hash(entries_[k].i, entries_[k].j);
      while (slot_[s] != kEmpty) s = (s + 1) & mask_;
      slot_[s] = static_cast<int>(k);
    }
  }

  // The entry stored for (i, j), or null if there is none.
  const Entry* entry(int i, int j) const {
    if (entries_.empty()) return nullptr;
    for (size_t s = hash(i, j);; s = (s + 1) & mask_) {
      const int k = slot_[s];
      if (k == kEmpty) return nullptr;
      if (entries_[k].i == i && entries_[k].j == j) return &entries_[k];
    }
  }
  // The normal impulse stored for (i, j), or a negative number if there is none.
  double find(int i, int j) const {
    const Entry* e = entry(i, j);
    return e ? e->impulse : -1.0;
  }

  // The balls were renumbered (new_number[old ball]): the stored contacts follow them, a pair keyed
  // with its lower number first if `lower_first`. `scratch` is reused.
  void renumber(const int* new_number, bool lower_first, std::vector<Entry>& scratch) {
    scratch.clear();
    for (const Entry& e : entries_) {
      int i = new_number[e.i], j = e.j >= 0 ? new_number[e.j] : e.j;
      if (lower_first && j >= 0 && i > j) std::swap(i, j);
      scratch.push_back({i, j, e.impulse, e.tangent});
    }
    assign(scratch);
  }

  // Calls f(Entry) for every stored contact.
  template <class F>
  void for_each(F&& f) const {
    for (const Entry& e : entries_) f(e);
  }

 private:
  static constexpr int kEmpty = -1;
  // Fibonacci hashing of the pair (Knuth, TAOCP vol. 3, 6.4): the top bits of a multiplicative hash.
  size_t hash(int i, int j) const {
    const uint64_t key = (static_cast<uint64_t>(static_cast<uint32_t>(i)) << 32) | static_cast<uint32_t>(j);
    return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  std::vector<Entry> entries_;
  std::vector<int> slot_;  // entry index or kEmpty
  size_t mask_ = 0;
  int shift_ = 60;  // 64 - log2(slots): the hash's top bits index a slot
};

}  // namespace ballbench

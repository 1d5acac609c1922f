#include "solver/neighbour_list.h"

#include <algorithm>

namespace ballbench {

namespace {

// The pairs of slots [s0, s1) closer than r_a + r_b + skin, appended to `out` as consecutive
// (a, b) slots; returns how much of `out` they fill. Every candidate is written and the end moves
// on only if it is close: no branch on the test, which a dilute gas passes for a coin-toss share of
// candidates. Pointers and the output's end live in locals, so the walk keeps them in registers
// (through the captures it reloaded them for every candidate).
template <bool kEqualRadii>
size_t close_pairs(const HomeGrid& grid, int s0, int s1, double r0, double skin, std::vector<int>& out) {
  const double* __restrict x = grid.x();
  const double* __restrict y = grid.y();
  const double* __restrict r = grid.r();
  const double lim0 = 2 * r0 + skin, lim0_2 = lim0 * lim0;
  if (out.size() < 64) out.resize(64);
  int* o = out.data();
  size_t size = 0, cap = out.size();
  grid.for_each_forward_pair(s0, s1, [&](int a, int b) {
    const double dx = x[a] - x[b], dy = y[a] - y[b];
    double lim2 = lim0_2;
    if constexpr (!kEqualRadii) {
      const double lim = r[a] + r[b] + skin;
      lim2 = lim * lim;
    }
    if (size + 2 > cap) [[unlikely]] {
      out.resize(2 * cap);
      o = out.data(), cap = out.size();
    }
    o[size] = a, o[size + 1] = b;
    size += 2 * (dx * dx + dy * dy < lim2);
  });
  return size;
}

}  // namespace

void NeighbourList::build(const HomeGrid& grid, bool equal_radii, double r0, double skin, ForkJoin& pool) {
  const int parts = pool.parts();
  const int slots = grid.balls();
  found_.resize(parts);
  count_.resize(parts);
  pool.run([&](int p) {
    const int s0 = static_cast<int>(ForkJoin::range_begin(slots, p, parts));
    const int s1 = static_cast<int>(ForkJoin::range_begin(slots, p + 1, parts));
    count_[p] = equal_radii ? close_pairs<true>(grid, s0, s1, r0, skin, found_[p])
                            : close_pairs<false>(grid, s0, s1, r0, skin, found_[p]);
  });
  const int* id = grid.id();
  first_.clear(), second_.clear();
  for (int p = 0; p < parts; ++p) {
    const std::vector<int>& found = found_[p];
    for (size_t k = 0; k < count_[p]; k += 2) {
      first_.push_back(id[found[k]]);
      second_.push_back(id[found[k + 1]]);
    }
  }
}

}  // namespace ballbench

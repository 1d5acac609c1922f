#include "solver/neighbour_list.h"

#include <algorithm>

namespace ballbench {

void NeighbourList::build(const HomeGrid& grid, bool equal_radii, double r0, double skin, ForkJoin& pool) {
  const int parts = pool.parts();
  const int slots = grid.balls();
  found_.resize(parts);
  count_.resize(parts);
  const double* x = grid.x();
  const double* y = grid.y();
  const double* r = grid.r();
  pool.run([&](int p) {
    std::vector<int>& out = found_[p];
    const int s0 = static_cast<int>(ForkJoin::range_begin(slots, p, parts));
    const int s1 = static_cast<int>(ForkJoin::range_begin(slots, p + 1, parts));
    const double lim0 = 2 * r0 + skin, lim0_2 = lim0 * lim0;
    // Every candidate is written and the end moves on only if it is close: no branch on the test,
    // which a dilute gas passes for a coin-toss share of candidates.
    size_t size = 0;
    if (out.size() < 64) out.resize(64);
    grid.for_each_forward_pair(s0, s1, [&](int a, int b) {
      const double dx = x[a] - x[b], dy = y[a] - y[b];
      double lim2 = lim0_2;
      if (!equal_radii) {
        const double lim = r[a] + r[b] + skin;
        lim2 = lim * lim;
      }
      if (size + 2 > out.size()) [[unlikely]] out.resize(2 * out.size());
      out[size] = a, out[size + 1] = b;
      size += 2 * (dx * dx + dy * dy < lim2);
    });
    count_[p] = size;
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

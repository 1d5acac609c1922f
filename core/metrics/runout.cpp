#include "metrics/runout.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace ballbench {

std::optional<double> runout(const State& s, const Eigen::VectorXd& radius) {
  const int n = s.n();
  if (n == 0) return std::nullopt;
  const auto left = [&](int i) { return s.pos(i, 0) - radius(i); };
  const auto right = [&](int i) { return s.pos(i, 0) + radius(i); };
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return left(a) < left(b); });
  const double gap = kRunoutGap * 2 * radius.mean();
  int highest = 0;
  for (int i = 1; i < n; ++i)
    if (s.pos(i, 1) + radius(i) > s.pos(highest, 1) + radius(highest)) highest = i;
  double start = left(order[0]), end = right(order[0]);
  bool holds_highest = order[0] == highest;
  for (int q = 1; q < n; ++q) {
    const int i = order[q];
    if (left(i) > end + gap) {  // a new run: the one before was the heap's if it held the highest ball
      if (holds_highest) break;
      start = left(i), end = right(i);
    }
    end = std::max(end, right(i));
    holds_highest = holds_highest || i == highest;
  }
  return end - start;
}

}  // namespace ballbench

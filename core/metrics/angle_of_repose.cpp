#include "metrics/angle_of_repose.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ballbench {

HeapProfile heap_profile(const State& s, const Eigen::VectorXd& radius, const Container& box) {
  HeapProfile p;
  p.x0 = box.min.x();
  p.width = 2 * radius.mean();
  // A box a whole number of diameters wide has that many columns, not one more from round-off.
  const int columns = std::max(1, static_cast<int>(std::ceil((box.max.x() - box.min.x()) / p.width - 1e-9)));
  p.height.assign(columns, 0.0);
  for (int i = 0; i < s.n(); ++i) {
    const int k = std::clamp(static_cast<int>(std::floor((s.pos(i, 0) - p.x0) / p.width)), 0, columns - 1);
    p.height[k] = std::max(p.height[k], s.pos(i, 1) + radius(i) - box.min.y());
  }
  return p;
}

std::optional<double> angle_of_repose(const HeapProfile& p) {
  const auto top = std::max_element(p.height.begin(), p.height.end());
  if (top == p.height.end() || !(*top > 0)) return std::nullopt;
  const int peak = static_cast<int>(top - p.height.begin()), n = static_cast<int>(p.height.size());
  const double lo = kReposeBandLow * *top, hi = kReposeBandHigh * *top;
  double sum = 0;
  int flanks = 0;
  for (const int dir : {-1, 1}) {
    // Least squares h = a + b x over the flank's columns within the band.
    double sx = 0, sh = 0, sxx = 0, sxh = 0;
    int m = 0;
    for (int k = peak + dir; k >= 0 && k < n && p.height[k] >= lo; k += dir) {
      if (p.height[k] > hi) continue;
      const double x = p.x0 + (k + 0.5) * p.width, h = p.height[k];
      sx += x, sh += h, sxx += x * x, sxh += x * h, ++m;
    }
    if (m < kReposeMinColumns) continue;
    const double slope = (m * sxh - sx * sh) / (m * sxx - sx * sx);
    sum += std::atan(std::abs(slope)), ++flanks;
  }
  if (flanks == 0) return std::nullopt;
  return sum / flanks * 180 / std::numbers::pi;
}

std::optional<double> angle_of_repose(const State& s, const Scene& scene) {
  return angle_of_repose(heap_profile(s, scene.radius, scene.container));
}

}  // namespace ballbench

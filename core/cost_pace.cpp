#include "cost_pace.h"

#include <algorithm>
#include <cmath>

namespace ballbench {

std::optional<CostPace> CostPace::from_points(const std::vector<double>& seconds) {
  if (seconds.size() != size_t(kPacePoints) || !(seconds.front() >= 0) || !(seconds.back() > 0) ||
      !std::is_sorted(seconds.begin(), seconds.end()) || !std::isfinite(seconds.back()))
    return std::nullopt;
  CostPace p;
  p.s_ = seconds;
  return p;
}

double CostPace::project(double spent, double share) const {
  if (s_.empty() || !(share > 0) || share >= 1) return spent;
  // The pace's time at `share`: linear between its points (0 at the start).
  const double x = share * double(s_.size());
  const size_t i = size_t(x);
  const double lo = i == 0 ? 0.0 : s_[i - 1];
  const double at = lo + (s_[i] - lo) * (x - double(i));
  return at > 0 ? spent * s_.back() / at : spent;
}

}  // namespace ballbench

#include "cost_pace.h"

#include <algorithm>
#include <cmath>

namespace ballbench {

std::optional<CostPace> CostPace::from_points(const std::vector<double>& seconds) {
  if (seconds.size() < size_t(kPaceFrom * kPacePoints) || seconds.size() > size_t(kPacePoints) ||
      !(seconds.front() >= 0) || !(seconds.back() > 0) || !std::is_sorted(seconds.begin(), seconds.end()) ||
      !std::isfinite(seconds.back()))
    return std::nullopt;
  CostPace p;
  p.s_ = seconds;
  return p;
}

double CostPace::at(double share) const {
  const size_t m = s_.size();
  const double x = share * double(kPacePoints);
  if (x < double(m)) {  // linear between its points
    const size_t i = size_t(x);
    const double lo = i == 0 ? 0.0 : s_[i - 1];
    return lo + (s_[i] - lo) * (x - double(i));
  }
  const size_t j = std::max<size_t>(1, m / 4);
  const double rate = (s_[m - 1] - (m > j ? s_[m - 1 - j] : 0.0)) / double(j);  // per point
  return s_.back() + rate * (x - double(m));
}

double CostPace::project(double spent, double share) const {
  if (s_.empty() || !(share > 0) || share >= 1) return spent;
  const double a = at(share);
  return a > 0 ? spent * at(1.0) / a : spent;
}

std::optional<double> whole_run_cost(double spent, double share, const CostPace* pace) {
  if (!(share >= kPaceFrom)) return std::nullopt;
  return pace ? pace->project(spent, share) : spent / std::min(1.0, share);
}

const CostPace* nearest_pace(const std::map<int, int>& own, const std::map<int, int>& as_is,
                             const std::map<int, CostPace>& paces, int k, const CostPace* first) {
  for (const auto* ladder : {&own, &as_is})
    for (auto it = ladder->rbegin(); it != ladder->rend(); ++it)
      if (const auto p = paces.find(it->second); (it->first < k || (ladder == &as_is && it->first == k)) && p != paces.end())
        return &p->second;
  return first;
}

}  // namespace ballbench

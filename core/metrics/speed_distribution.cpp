#include "metrics/speed_distribution.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ballbench {

bool speed_distribution_applies(const Scene& scene) {
  const SceneFeatures f = scene.features();
  return f.elastic && !f.gravity && f.equal_masses && scene.n() >= 100;
}

double rayleigh_ks_statistic(const State& s) {
  const int n = s.n();
  if (n == 0) return 0;
  Eigen::VectorXd speed = s.vel.rowwise().norm();
  const double two_s2 = speed.squaredNorm() / n;  // 2 s^2 = <|v|^2>
  if (two_s2 == 0) return 1;
  std::vector<double> v(speed.data(), speed.data() + n);
  std::sort(v.begin(), v.end());
  double d = 0;
  for (int k = 0; k < n; ++k) {
    const double f = 1.0 - std::exp(-v[k] * v[k] / two_s2);
    d = std::max({d, std::abs(f - double(k) / n), std::abs(double(k + 1) / n - f)});
  }
  return d;
}

double rayleigh_ks_critical(int n) { return 1.63 / std::sqrt(static_cast<double>(std::max(n, 1))); }

}  // namespace ballbench

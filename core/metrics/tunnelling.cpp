#include "metrics/tunnelling.h"

#include <algorithm>
#include <cmath>

namespace ballbench {

bool beyond_wall(const Eigen::Vector2d& p, const Container& box) {
  return box.kind == ContainerKind::Box && ((p.array() < box.min.array()).any() || (p.array() > box.max.array()).any());
}

int wall_escapes(const State& prev, const State& cur, const Container& box) {
  if (box.kind != ContainerKind::Box) return 0;
  int count = 0;
  for (int i = 0; i < cur.n(); ++i)
    if (!beyond_wall(prev.pos.row(i).transpose(), box) && beyond_wall(cur.pos.row(i).transpose(), box)) ++count;
  return count;
}

double closest_approach(const Eigen::Vector2d& d0, const Eigen::Vector2d& d1) {
  const Eigen::Vector2d w = d1 - d0;
  const double ww = w.squaredNorm();
  const double s = ww > 0 ? std::clamp(-d0.dot(w) / ww, 0.0, 1.0) : 0.0;
  return (d0 + s * w).norm();
}

int pair_passthroughs(const State& prev, const State& cur, const Eigen::VectorXd& radius, double tolerance,
                      UniformGrid& grid) {
  const int n = cur.n();
  if (n < 2) return 0;
  // Each ball sweeps a segment within half its displacement of the midpoint, so a pair whose
  // segments come within r_i + r_j has midpoints within 2 r_max + d_max: one grid cell.
  const Eigen::MatrixX2d mid = 0.5 * (prev.pos + cur.pos);
  const double dmax = std::sqrt((cur.pos - prev.pos).rowwise().squaredNorm().maxCoeff());
  grid.build(mid, 2.0 * radius.maxCoeff() + dmax);
  const double h = cur.t - prev.t;
  int count = 0;
  grid.for_each_candidate_pair([&](int i, int j) {
    const double rs = radius(i) + radius(j);
    const Eigen::Vector2d d0 = (prev.pos.row(i) - prev.pos.row(j)).transpose();
    const Eigen::Vector2d d1 = (cur.pos.row(i) - cur.pos.row(j)).transpose();
    if (d0.norm() < rs || d1.norm() < rs) return;  // overlapping in a sample: sticking's business
    const double bend = 0.25 * h * ((cur.vel.row(i) - cur.vel.row(j)) - (prev.vel.row(i) - prev.vel.row(j))).norm();
    if (closest_approach(d0, d1) < (1.0 - tolerance) * rs - bend) ++count;
  });
  return count;
}

}  // namespace ballbench

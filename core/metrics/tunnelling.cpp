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
                      PassthroughScratch& scratch) {
  const int n = cur.n();
  if (n < 2) return 0;
  // A straight relative path that starts and ends at least r_i + r_j apart but comes within
  // (1 - tolerance)(r_i + r_j) of contact crosses that circle along a chord at least
  // 2 s (r_i + r_j) long, s = sqrt(1 - (1 - tolerance)^2), so the two balls moved at least that much
  // between them. Pairs that moved less cannot count; in most steps of most scenes no ball moves
  // that far, and the search is skipped.
  const double s = std::sqrt(1.0 - (1.0 - tolerance) * (1.0 - tolerance));
  Eigen::VectorXd& moved = scratch.moved;
  moved.resize(n);
  moved.noalias() = (cur.pos - prev.pos).rowwise().norm();
  const double dmax = moved.maxCoeff();
  // One of the two moved at least s (r_i + r_j) >= 2 s r_min: the search starts from those balls
  // only (in most steps of most scenes, none).
  const double mover = 2.0 * s * radius.minCoeff();
  if (dmax < mover) return 0;
  // Each ball sweeps a segment within half its displacement of the midpoint, so a pair whose
  // segments come within r_i + r_j has midpoints within 2 r_max + d_max: adjacent grid cells.
  Eigen::MatrixX2d& mid = scratch.mid;
  mid.resize(n, 2);
  mid.noalias() = 0.5 * (prev.pos + cur.pos);
  UniformGrid& grid = scratch.grid;
  grid.build(mid, 2.0 * radius.maxCoeff() + dmax);
  const double h = cur.t - prev.t;
  const auto& order = grid.order();
  // Plain references, not a structured binding: clang 14 (the fuzz preset) cannot capture those.
  std::vector<double>&sx = scratch.sx, &sy = scratch.sy, &smoved = scratch.smoved, &sr = scratch.sradius;
  std::vector<int>& sid = scratch.sid;
  sx.resize(n), sy.resize(n), smoved.resize(n), sr.resize(n), sid.resize(n);
  for (int a = 0; a < n; ++a) {
    const int i = order[a];
    sx[a] = mid(i, 0), sy[a] = mid(i, 1), smoved[a] = moved(i), sr[a] = radius(i), sid[a] = i;
  }
  int count = 0;
  for (int a = 0; a < n; ++a) {
    if (smoved[a] < mover) continue;
    grid.for_each_near_range(sx[a], sy[a], [&](int begin, int end) {
      for (int b = begin; b < end; ++b) {
        if (b == a || (smoved[b] >= mover && b < a)) continue;  // a pair of movers is seen from one side
        const double rs = sr[a] + sr[b], travel = smoved[a] + smoved[b];
        if (travel < 2.0 * s * rs) continue;
        const double dx = sx[a] - sx[b], dy = sy[a] - sy[b], reach = rs + 0.5 * travel;
        if (dx * dx + dy * dy >= reach * reach) continue;  // the segments never come within rs
        const int i = sid[a], j = sid[b];
        const Eigen::Vector2d d0 = (prev.pos.row(i) - prev.pos.row(j)).transpose();
        const Eigen::Vector2d d1 = (cur.pos.row(i) - cur.pos.row(j)).transpose();
        if (d0.squaredNorm() < rs * rs || d1.squaredNorm() < rs * rs) continue;  // overlapping: sticking's business
        const double bend =
            0.25 * h * ((cur.vel.row(i) - prev.vel.row(i)).norm() + (cur.vel.row(j) - prev.vel.row(j)).norm());
        if (closest_approach(d0, d1) < (1.0 - tolerance) * rs - bend) ++count;
      }
    });
  }
  return count;
}

}  // namespace ballbench

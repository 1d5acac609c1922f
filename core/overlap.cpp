#include "overlap.h"

#include <cmath>

namespace ballbench {

void overlapping_pairs(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius, OverlapScratch& scratch,
                       std::vector<Overlap>& out) {
  out.clear();
  const int n = static_cast<int>(pos.rows());
  if (n < 2) return;
  UniformGrid& grid = scratch.grid;
  grid.build(pos, 2.0 * radius.maxCoeff());
  const int* order = grid.order().data();
  CellOrderedBalls& balls = scratch.balls;
  balls.resize(n);
  balls.gather(order, pos, radius, 0, n);
  const double *x = balls.x.data(), *y = balls.y.data(), *r = balls.r.data();
  // The same pairs in the same order as for_each_candidate_pair (the rest of a ball's cell, the
  // next cell in its row, the three cells of the next row), as runs over the copies.
  grid.for_each_forward_range([&](int a, int begin, int end) {
    const double xa = x[a], ya = y[a], ra = r[a];
    for (int b = begin; b < end; ++b) {
      const double dx = xa - x[b], dy = ya - y[b], rs = ra + r[b], d2 = dx * dx + dy * dy;
      if (d2 < rs * rs) [[unlikely]] {
        const int i = order[a], j = order[b];
        out.push_back({std::min(i, j), std::max(i, j), rs - std::sqrt(d2)});
      }
    }
  });
}

std::optional<std::pair<int, int>> first_overlapping_pair(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius) {
  OverlapScratch scratch;
  std::vector<Overlap> found;
  overlapping_pairs(pos, radius, scratch, found);
  if (found.empty()) return std::nullopt;
  auto best = found.front();
  for (const auto& o : found)
    if (o.i < best.i || (o.i == best.i && o.j < best.j)) best = o;
  return std::make_pair(best.i, best.j);
}

void OverlapIndex::insert(const Eigen::Vector2d& p) {
  cells_[key(std::llround(std::floor(p.x() / cell_)), std::llround(std::floor(p.y() / cell_)))].push_back(count_++);
}

bool OverlapIndex::overlaps(const Eigen::Vector2d& p, double r, const std::vector<Eigen::Vector2d>& pos,
                            const std::vector<double>& radius) const {
  const long long cx = std::llround(std::floor(p.x() / cell_)), cy = std::llround(std::floor(p.y() / cell_));
  for (long long dy = -1; dy <= 1; ++dy)
    for (long long dx = -1; dx <= 1; ++dx) {
      const auto it = cells_.find(key(cx + dx, cy + dy));
      if (it == cells_.end()) continue;
      for (int j : it->second) {
        const double rs = r + radius[j];
        if ((p - pos[j]).squaredNorm() < rs * rs) return true;
      }
    }
  return false;
}

}  // namespace ballbench

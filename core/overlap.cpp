#include "overlap.h"

#include <cmath>

#include "uniform_grid.h"

namespace ballbench {

void overlapping_pairs(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius, UniformGrid& grid,
                       std::vector<Overlap>& out) {
  out.clear();
  if (pos.rows() < 2) return;
  grid.build(pos, 2.0 * radius.maxCoeff());
  grid.for_each_candidate_pair([&](int i, int j) {
    const double dx = pos(i, 0) - pos(j, 0), dy = pos(i, 1) - pos(j, 1);
    const double rs = radius(i) + radius(j);
    const double d2 = dx * dx + dy * dy;
    if (d2 < rs * rs) out.push_back({std::min(i, j), std::max(i, j), rs - std::sqrt(d2)});
  });
}

std::optional<std::pair<int, int>> first_overlapping_pair(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius) {
  UniformGrid grid;
  std::vector<Overlap> found;
  overlapping_pairs(pos, radius, grid, found);
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

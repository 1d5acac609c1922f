#pragma once
// Finding balls that overlap: at load time (the scene must not start overlapping unless it says
// so) and in metrics (sticking, penetration).
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "uniform_grid.h"

namespace ballbench {

// The overlapping pair (i < j) with the smallest i, then j, or none.
std::optional<std::pair<int, int>> first_overlapping_pair(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius);

struct Overlap {
  int i, j;       // i < j
  double depth;   // r_i + r_j - |x_i - x_j| (m), > 0
};

// What overlapping_pairs works in, kept by the caller across calls (no allocation once warm): a
// grid, and the positions and radii copied in its cell order.
struct OverlapScratch {
  UniformGrid grid;
  CellOrderedBalls balls;
};

// Every overlapping pair, via a grid with a cell of twice the largest radius, in the grid's visiting
// order (UniformGrid::for_each_candidate_pair's).
void overlapping_pairs(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius, OverlapScratch& scratch,
                       std::vector<Overlap>& out);

// An incremental spatial hash for placing balls one at a time (random scenes without overlap).
class OverlapIndex {
 public:
  explicit OverlapIndex(double cell) : cell_(cell) {}
  void insert(const Eigen::Vector2d& p);
  // Does a ball at p with radius r overlap any inserted ball? (positions and radii by insertion order)
  bool overlaps(const Eigen::Vector2d& p, double r, const std::vector<Eigen::Vector2d>& pos,
                const std::vector<double>& radius) const;

 private:
  long long key(long long cx, long long cy) const { return cx * 73856093LL ^ cy * 19349663LL; }
  double cell_;
  int count_ = 0;
  std::unordered_map<long long, std::vector<int>> cells_;
};

}  // namespace ballbench

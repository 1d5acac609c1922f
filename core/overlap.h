#pragma once
// Finding balls that overlap: at load time (the scene must not start overlapping unless it says
// so) and in metrics (sticking, penetration).
#include <cstddef>
#include <optional>
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

// An incremental spatial hash for placing balls one at a time (random scenes without overlap):
// open addressing over flat arrays sized for `expected` balls up front, so that placing millions
// neither stalls on a rehash nor frees millions of small blocks when done.
class OverlapIndex {
 public:
  OverlapIndex(double cell, size_t expected);
  void insert(const Eigen::Vector2d& p);
  // Does a ball at p with radius r overlap any inserted ball? (positions and radii by insertion order)
  bool overlaps(const Eigen::Vector2d& p, double r, const std::vector<Eigen::Vector2d>& pos,
                const std::vector<double>& radius) const;

 private:
  // Up to six balls of one cell, and the cell's block before it (-1: none): a cell's balls are
  // read a block at a time, not one dependent load per ball.
  struct Block {
    int next = -1, count = 0;
    int ball[6];
  };
  long long key(long long cx, long long cy) const { return cx * 73856093LL ^ cy * 19349663LL; }
  size_t slot(long long key) const;  // the slot holding `key`, or the empty one where it would go
  void grow();
  double cell_;
  size_t cells_ = 0;             // slots in use
  int balls_ = 0;                // inserted so far
  std::vector<long long> keys_;  // per slot: its cell's key
  std::vector<int> head_;        // per slot: its cell's newest block, or -1 (an empty slot)
  std::vector<Block> blocks_;
};

}  // namespace ballbench

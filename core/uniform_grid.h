#pragma once
// A uniform grid over ball centres, rebuilt from scratch by a counting sort (O(n), no allocation
// once warm). Two balls closer than `cell` are always in the same or adjacent cells, so candidate
// pairs come from a 3 x 3 block. Used by metrics and the scene loader; the home solver has its own
// grid specialised for its hot loop (core/solver/home_grid.h); both size their cells by grid_cell.
// (exact's grid, fixed over the container and crossed by events, tiles the container with cells
// of its own rule: its trajectories advance at every crossing, so another tiling changes their
// round-off, and the reference's figures on chaotic scenes with it.)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace ballbench {

// The cell rule of the grids over ball centres: cells at least `cell` wide (m), doubled while a
// grid over a w x h spread of n centres (its first cell at the least centre) would have more than
// about 4 cells per ball, so sparse or far-flung scenes cost no more memory than dense ones.
// Larger cells stay correct: they only add candidates.
inline double grid_cell(double w, double h, double cell, int n) {
  const double max_cells = 4.0 * n + 16;
  cell = std::max(cell, 1e-300);
  while ((std::floor(w / cell) + 1) * (std::floor(h / cell) + 1) > max_cells) cell *= 2;
  return cell;
}

class UniformGrid {
 public:
  // Sorts balls into cells of at least `cell` (m). The cell grows if needed to keep the number of
  // cells near the number of balls, so sparse or far-flung scenes cost no more memory than dense ones.
  void build(const Eigen::MatrixX2d& pos, double cell);

  // Calls f(i, j) once for every pair i < j in the same or adjacent cells.
  template <class F>
  void for_each_candidate_pair(F&& f) const {
    for (int cy = 0; cy < ny_; ++cy)
      for (int cx = 0; cx < nx_; ++cx) {
        const int c = cy * nx_ + cx;
        for (int a = start_[c]; a < start_[c + 1]; ++a) {
          const int i = order_[a];
          for (int b = a + 1; b < start_[c + 1]; ++b) f(i, order_[b]);
          // Half of the 8 neighbours, so each pair of cells is visited once.
          visit_cell(cx + 1, cy, i, f);
          visit_cell(cx - 1, cy + 1, i, f);
          visit_cell(cx, cy + 1, i, f);
          visit_cell(cx + 1, cy + 1, i, f);
        }
      }
  }

  // Every ball within `reach` of point (x, y), and others, as runs of positions in order(): f(begin,
  // end) once per row of the cells that overlap the square of side 2 reach around the point.
  template <class F>
  void for_each_within_range(double x, double y, double reach, F&& f) const {
    const int x0 = cell_x(x - reach), x1 = cell_x(x + reach);
    for (int iy = cell_y(y - reach); iy <= cell_y(y + reach); ++iy) f(start_[iy * nx_ + x0], start_[iy * nx_ + x1 + 1]);
  }

  // Every pair of positions in order() in the same or adjacent cells, as runs: f(a, begin, end)
  // for each position a and each run [begin, end) of later partners (the rest of a's cell and the
  // next cell in its row; the three cells below in the next row). Each pair lies in exactly one run.
  // Only the positions a in rows [row_begin, row_end) of cells: disjoint row ranges give disjoint
  // pairs (so parts of a thread team can share the work).
  template <class F>
  void for_each_forward_range(F&& f) const {
    for_each_forward_range(0, ny_, f);
  }
  template <class F>
  void for_each_forward_range(int row_begin, int row_end, F&& f) const {
    for (int cy = row_begin; cy < row_end; ++cy)
      for (int cx = 0; cx < nx_; ++cx) {
        const int c = cy * nx_ + cx;
        const int row_end = start_[cy * nx_ + (cx + 1 < nx_ ? cx + 2 : cx + 1)];
        const bool below = cy + 1 < ny_;
        const int lo = below ? start_[(cy + 1) * nx_ + (cx > 0 ? cx - 1 : 0)] : 0;
        const int hi = below ? start_[(cy + 1) * nx_ + (cx + 1 < nx_ ? cx + 2 : cx + 1)] : 0;
        for (int a = start_[c]; a < start_[c + 1]; ++a) {
          f(a, a + 1, row_end);
          if (lo < hi) f(a, lo, hi);
        }
      }
  }

  // Ball indices sorted by cell: the balls of one cell, and of a row of cells, are contiguous.
  const std::vector<int>& order() const { return order_; }

  double cell() const { return cell_; }
  int rows() const { return ny_; }

 private:
  template <class F>
  void visit_cell(int cx, int cy, int i, F& f) const {
    if (cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) return;
    const int c = cy * nx_ + cx;
    for (int b = start_[c]; b < start_[c + 1]; ++b) f(i, order_[b]);
  }
  int cell_x(double x) const { return clamp_cell((x - x0_) * inv_cell_, nx_); }
  int cell_y(double y) const { return clamp_cell((y - y0_) * inv_cell_, ny_); }
  // floor(c) clamped to [0, n - 1], by truncation: the same for c >= 0, and a negative c clamps to
  // 0 either way. std::floor is a library call without SSE4.1, and cost more than the rest of a build.
  static int clamp_cell(double c, int n) { return c < 0 ? 0 : c >= n ? n - 1 : static_cast<int>(c); }

  double x0_ = 0, y0_ = 0, cell_ = 1, inv_cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<int> start_;  // (cells + 1) prefix sums: balls of cell c are order_[start_[c] .. start_[c+1])
  std::vector<int> order_;  // ball indices sorted by cell
  std::vector<int> cell_of_;
  std::vector<int> fill_;   // scratch of build(), kept: no allocation per build once warm
};

// Positions and radii copied into a grid's cell order (slot a holds ball order[a], the grid's slot
// -> ball map), so that a ball's candidate partners are contiguous runs of memory instead of balls
// at random in the scene's order: the overlap metric, the tunnelling check and the home solver's
// neighbour-list build walk these instead of the scene's arrays.
struct CellOrderedBalls {
  std::vector<double> x, y, r;

  // Without `radii` (all equal, known elsewhere) r stays empty and gather skips it.
  void resize(int n, bool radii = true) { x.resize(n), y.resize(n), r.resize(radii ? n : 0); }
  // Slots [begin, end), after resize: disjoint ranges may be filled in parallel.
  void gather(const int* order, const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius, long begin, long end) {
    for (long a = begin; a < end; ++a) x[a] = pos(order[a], 0), y[a] = pos(order[a], 1);
    if (!r.empty())
      for (long a = begin; a < end; ++a) r[a] = radius(order[a]);
  }
};

}  // namespace ballbench

#include "solver/home_grid.h"

#include <algorithm>

namespace ballbench {

void HomeGrid::build(const Eigen::MatrixX2d& pos, const Eigen::MatrixX2d& vel, const Eigen::VectorXd& radius,
                     double cell, ForkJoin& pool) {
  const int n = static_cast<int>(pos.rows());
  const int parts = pool.parts();
  if (n == 0) {
    nx_ = ny_ = 0;
    start_.assign(1, 0);
    id_.clear();
    cell_of_.clear();
    cell_sorted_.clear();
    return;
  }
  // Bounds: min and max are exact in any order, so parts may reduce them.
  std::vector<double> lo_x(parts), lo_y(parts), hi_x(parts), hi_y(parts);
  const double* px = pos.col(0).data();
  const double* py = pos.col(1).data();
  pool.run([&](int p) {
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    double ax = px[b], ay = py[b], bx = px[b], by = py[b];
    for (long i = b; i < e; ++i) {
      ax = std::min(ax, px[i]), bx = std::max(bx, px[i]);
      ay = std::min(ay, py[i]), by = std::max(by, py[i]);
    }
    lo_x[p] = ax, lo_y[p] = ay, hi_x[p] = bx, hi_y[p] = by;
  });
  x0_ = *std::min_element(lo_x.begin(), lo_x.end()), y0_ = *std::min_element(lo_y.begin(), lo_y.end());
  const double w = *std::max_element(hi_x.begin(), hi_x.end()) - x0_;
  const double h = *std::max_element(hi_y.begin(), hi_y.end()) - y0_;
  // As UniformGrid::build: at most ~4 cells per ball (larger cells stay correct).
  const double max_cells = 4.0 * n + 16;
  cell = std::max(cell, 1e-300);
  while ((std::floor(w / cell) + 1) * (std::floor(h / cell) + 1) > max_cells) cell *= 2;
  inv_cell_ = 1.0 / cell;
  nx_ = static_cast<int>(std::floor(w / cell)) + 1 + 2;  // + the empty ring
  ny_ = static_cast<int>(std::floor(h / cell)) + 1 + 2;

  cell_of_.resize(n);
  pool.run([&](int p) {
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long i = b; i < e; ++i) cell_of_[i] = cell_y(py[i]) * nx_ + cell_x(px[i]);
  });
  // Counting sort, stable: within a cell, balls keep their order. Counts, then running sums (each
  // cell's end), then balls placed from the last backwards, which leaves each cell's first slot
  // behind: no second copy of the cell array.
  start_.assign(static_cast<size_t>(nx_) * ny_ + 1, 0);
  for (int i = 0; i < n; ++i) ++start_[cell_of_[i]];
  for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  id_.resize(n);
  cell_sorted_.resize(n);
  for (int i = n - 1; i >= 0; --i) {
    const int s = --start_[cell_of_[i]];
    id_[s] = i, cell_sorted_[s] = cell_of_[i];
  }

  x_.resize(n), y_.resize(n), vx_.resize(n), vy_.resize(n);
  r_.resize(radius.size() ? n : 0);
  const double* vxp = vel.col(0).data();
  const double* vyp = vel.col(1).data();
  pool.run([&](int p) {
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long s = b; s < e; ++s) {
      const int i = id_[s];
      x_[s] = px[i], y_[s] = py[i], vx_[s] = vxp[i], vy_[s] = vyp[i];
    }
    if (!r_.empty())
      for (long s = b; s < e; ++s) r_[s] = radius(id_[s]);
  });
}

}  // namespace ballbench

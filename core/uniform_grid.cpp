#include "uniform_grid.h"

#include <algorithm>

namespace ballbench {

void UniformGrid::build(const Eigen::MatrixX2d& pos, double cell) {
  const int n = static_cast<int>(pos.rows());
  if (n == 0) {
    nx_ = ny_ = 0;
    start_.assign(1, 0);
    order_.clear();
    return;
  }
  x0_ = pos.col(0).minCoeff(), y0_ = pos.col(1).minCoeff();
  const double w = pos.col(0).maxCoeff() - x0_, h = pos.col(1).maxCoeff() - y0_;
  cell = grid_cell(w, h, cell, n);
  cell_ = cell, inv_cell_ = 1.0 / cell;
  nx_ = static_cast<int>(std::floor(w / cell)) + 1;
  ny_ = static_cast<int>(std::floor(h / cell)) + 1;

  start_.assign(static_cast<size_t>(nx_) * ny_ + 1, 0);
  cell_of_.resize(n);
  for (int i = 0; i < n; ++i) {
    cell_of_[i] = cell_y(pos(i, 1)) * nx_ + cell_x(pos(i, 0));
    ++start_[cell_of_[i] + 1];
  }
  for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  order_.resize(n);
  fill_.assign(start_.begin(), start_.end() - 1);
  for (int i = 0; i < n; ++i) order_[fill_[cell_of_[i]]++] = i;
}

}  // namespace ballbench

#include "solver/home_grid.h"

#include <algorithm>

namespace ballbench {

void HomeGrid::build(const Eigen::MatrixX2d& pos, const Eigen::MatrixX2d& vel, const Eigen::VectorXd& radius,
                     double cell, ForkJoin& pool, bool velocities, const std::array<double, 4>* bounds) {
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
  const double* px = pos.col(0).data();
  const double* py = pos.col(1).data();
  double w, h;
  if (bounds) {
    x0_ = (*bounds)[0], y0_ = (*bounds)[1];
    w = (*bounds)[2] - x0_, h = (*bounds)[3] - y0_;
  } else {
    std::vector<double> lo_x(parts), lo_y(parts), hi_x(parts), hi_y(parts);
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
    w = *std::max_element(hi_x.begin(), hi_x.end()) - x0_;
    h = *std::max_element(hi_y.begin(), hi_y.end()) - y0_;
  }
  // As UniformGrid::build: at most ~4 cells per ball (larger cells stay correct).
  const double max_cells = 4.0 * n + 16;
  cell = std::max(cell, 1e-300);
  while ((std::floor(w / cell) + 1) * (std::floor(h / cell) + 1) > max_cells) cell *= 2;
  inv_cell_ = 1.0 / cell;
  nx_ = static_cast<int>(std::floor(w / cell)) + 1 + 2;  // + the empty ring
  ny_ = static_cast<int>(std::floor(h / cell)) + 1 + 2;

  const size_t cells = static_cast<size_t>(nx_) * ny_;
  id_.resize(n);
  cell_sorted_.resize(n);
  x_.resize(n), y_.resize(n), vx_.resize(n), vy_.resize(n);
  r_.resize(radius.size() ? n : 0);
  cell_of_.resize(n);
  const double* vxp = vel.col(0).data();
  const double* vyp = vel.col(1).data();
  const double* rp = radius.size() ? radius.data() : nullptr;
  // Positions and velocities (and radii) in slot order, each part over its fixed range of slots.
  auto gather = [&] {
    pool.run([&](int p) {
      const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
      if (velocities)
        for (long s = b; s < e; ++s) {
          const int i = id_[s];
          x_[s] = px[i], y_[s] = py[i], vx_[s] = vxp[i], vy_[s] = vyp[i];
        }
      else
        for (long s = b; s < e; ++s) x_[s] = px[id_[s]], y_[s] = py[id_[s]];
      if (rp)
        for (long s = b; s < e; ++s) r_[s] = rp[id_[s]];
    });
  };
  // Counting sort, stable: within a cell, balls keep their order.
  if (parts == 1) {
    // The parallel sort below on one part, with the cell index computed in the counting pass
    // instead of a pass of its own: the grid path's step at 10^4 gas balls 39.5 against 40.8 ns
    // (three alternating runs). Counts, then running sums (each cell's end), then balls placed
    // from the last backwards, which leaves each cell's first slot behind.
    start_.assign(cells + 1, 0);
    for (int i = 0; i < n; ++i) ++start_[cell_of_[i] = cell_y(py[i]) * nx_ + cell_x(px[i])];
    for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    for (int i = n - 1; i >= 0; --i) {
      const int c = cell_of_[i];
      const int s = --start_[c];
      id_[s] = i, cell_sorted_[s] = c;
    }
    gather();
    return;
  }
  // In parallel by ranges of cells:
  // part p owns cells [cb, ce) and their entries of start_. Every part reads every ball's cell
  // (computed in parallel first), counts those in its cells, takes the running sums over them, and
  // places them from the last ball backwards, which leaves each cell's first slot in start_: the
  // same slots on any number of parts, and no histogram beside start_ (a second one cost 4 bytes
  // per cell, ~4.4 per ball at 10^6 bowl balls). Each part reads the n cell indices twice instead
  // of half of them: a few MB, sequentially, against a step of tens of ms at 10^6.
  start_.resize(cells + 1);
  std::vector<long> total(parts + 1, 0);  // balls in each part's cells, then its first slot
  pool.run([&](int p) {
    const size_t cb = ForkJoin::range_begin(cells, p, parts), ce = ForkJoin::range_begin(cells, p + 1, parts);
    std::fill(start_.begin() + cb, start_.begin() + ce, 0);
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long i = b; i < e; ++i) cell_of_[i] = cell_y(py[i]) * nx_ + cell_x(px[i]);
  });
  pool.run([&](int p) {
    const size_t cb = ForkJoin::range_begin(cells, p, parts), ce = ForkJoin::range_begin(cells, p + 1, parts);
    int* count = start_.data();
    for (int i = 0; i < n; ++i) {
      const size_t c = cell_of_[i];
      if (c - cb < ce - cb) ++count[c];  // c in [cb, ce)
    }
    long sum = 0;
    for (size_t c = cb; c < ce; ++c) sum += count[c], count[c] = static_cast<int>(sum);  // ends, from the part's first slot
    total[p + 1] = sum;
  });
  for (int p = 0; p < parts; ++p) total[p + 1] += total[p];
  start_[cells] = n;
  pool.run([&](int p) {
    const size_t cb = ForkJoin::range_begin(cells, p, parts), ce = ForkJoin::range_begin(cells, p + 1, parts);
    const int offset = static_cast<int>(total[p]);
    for (size_t c = cb; c < ce; ++c) start_[c] += offset;
    for (int i = n - 1; i >= 0; --i) {
      const size_t c = cell_of_[i];
      if (c - cb >= ce - cb) continue;  // not this part's cell
      const int s = --start_[c];
      id_[s] = i, cell_sorted_[s] = static_cast<int>(c);
    }
  });
  gather();
}

}  // namespace ballbench

#include "solver/home_grid.h"

#include <algorithm>

namespace ballbench {

void HomeGrid::build(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius, double cell, ForkJoin& pool,
                     bool copy, const Bounds* bounds) {
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
  Bounds measured;
  if (!bounds) {
    std::vector<Bounds> part(parts);
    pool.run([&](int p) {
      const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
      Bounds q;
      for (long i = b; i < e; ++i) q.add(px[i], py[i]);
      part[p] = q;
    });
    for (const Bounds& q : part) measured.merge(q);
    bounds = &measured;
  }
  x0_ = bounds->v[0], y0_ = bounds->v[1];
  const double w = bounds->v[2] - x0_, h = bounds->v[3] - y0_;
  cell = grid_cell(w, h, cell, n);
  inv_cell_ = 1.0 / cell;
  nx_ = static_cast<int>(std::floor(w / cell)) + 1 + 2;  // + the empty ring
  ny_ = static_cast<int>(std::floor(h / cell)) + 1 + 2;

  const size_t cells = static_cast<size_t>(nx_) * ny_;
  id_.resize(n);
  cell_sorted_.resize(n);
  cell_of_.resize(n);
  if (copy) copy_.resize(n, radius.size() > 0);
  // Positions (and radii) in slot order, each part over its fixed range of slots.
  auto gather = [&] {
    if (!copy) return;
    pool.run([&](int p) {
      const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
      copy_.gather(id_.data(), pos, radius, b, e);
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
  // In parallel by ranges of cells: part p owns cells [cut[p], cut[p + 1]) and their entries of
  // start_, and places the balls of those cells; no histogram beside start_ (a second one cost 4
  // bytes per cell, ~4.4 per ball at 10^6 bowl balls). The cuts are the cells of the balls that
  // begin each part's range of balls, so when the balls are nearly in cell order (renumbered in it
  // a few steps ago: every large scene) a part's cells hold nearly its own balls. Each part counts
  // the balls of its range that fall in its cells and lists the others (strays) for their owners;
  // then it counts the strays others listed for it, takes the running sums over its cells, and
  // places its balls from the last backwards (the strays of later ranges, its own range, the strays
  // of earlier ones: ball order), which leaves each cell's first slot in start_. The same slots for
  // any cuts and any number of parts; each part reads n / parts cells plus the strays, instead of
  // every ball's cell twice (counting and placing) for one shared histogram.
  start_.resize(cells + 1);
  pool.run([&](int p) {
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long i = b; i < e; ++i) cell_of_[i] = cell_y(py[i]) * nx_ + cell_x(px[i]);
  });
  std::vector<size_t> cut(parts + 1);
  cut[0] = 0, cut[parts] = cells;
  for (int p = 1; p < parts; ++p)
    cut[p] = std::max<size_t>(cut[p - 1], cell_of_[ForkJoin::range_begin(n, p, parts)]);
  strays_.resize(parts);
  std::vector<long> total(parts + 1, 0);  // balls in each part's cells, then its first slot
  pool.run([&](int p) {
    const size_t cb = cut[p], ce = cut[p + 1];
    int* count = start_.data();
    std::fill(count + cb, count + ce, 0);
    std::vector<int>& strays = strays_[p];
    strays.clear();
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long i = b; i < e; ++i) {
      const size_t c = cell_of_[i];
      if (c - cb < ce - cb) ++count[c];  // c in [cb, ce)
      else strays.push_back(static_cast<int>(i));
    }
  });
  pool.run([&](int p) {
    const size_t cb = cut[p], ce = cut[p + 1];
    int* count = start_.data();
    for (int q = 0; q < parts; ++q)
      if (q != p)
        for (int i : strays_[q])
          if (cell_of_[i] - cb < ce - cb) ++count[cell_of_[i]];
    long sum = 0;
    // Each cell's end, counted from the part's first slot.
    for (size_t c = cb; c < ce; ++c) sum += count[c], count[c] = static_cast<int>(sum);
    total[p + 1] = sum;
  });
  for (int p = 0; p < parts; ++p) total[p + 1] += total[p];
  start_[cells] = n;
  pool.run([&](int p) {
    const size_t cb = cut[p], ce = cut[p + 1];
    const int offset = static_cast<int>(total[p]);
    for (size_t c = cb; c < ce; ++c) start_[c] += offset;
    const auto place = [&](int i) {
      const size_t c = cell_of_[i];
      if (c - cb >= ce - cb) return;  // not this part's cell
      const int s = --start_[c];
      id_[s] = i, cell_sorted_[s] = static_cast<int>(c);
    };
    const auto place_strays = [&](int q) {
      for (auto it = strays_[q].rbegin(); it != strays_[q].rend(); ++it) place(*it);
    };
    for (int q = parts - 1; q > p; --q) place_strays(q);
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long i = e - 1; i >= b; --i) place(static_cast<int>(i));
    for (int q = p - 1; q >= 0; --q) place_strays(q);
  });
  gather();
}

}  // namespace ballbench

#pragma once
// The home solver's broad phase: a uniform grid rebuilt every step by a counting sort, and on
// request a copy of the positions in cell order (for the neighbour list's build).
// The balls themselves are not moved here. The solver renumbers them in the grid's cell order every
// few steps (Home::reorder_by_cell), so between renumberings the slot -> ball map is nearly the
// identity and its pair screen reads the state through it, which costs less than copying positions
// and velocities into cell order every step (core/solver/PERFORMANCE.md, "Broad phase").
//
// Cells follow the project's cell rule (grid_cell, core/uniform_grid.h) and start at the least
// centre, as UniformGrid's do.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "fork_join.h"
#include "uniform_grid.h"

namespace ballbench {

class HomeGrid {
 public:
  // The positions' bounding box: min x, min y, max x, max y. Min and max are exact in any order, so
  // parts of a thread team may each take their own and merge them.
  struct Bounds {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    std::array<double, 4> v = {kInf, kInf, -kInf, -kInf};
    void add(double x, double y) {
      v[0] = std::min(v[0], x), v[1] = std::min(v[1], y);
      v[2] = std::max(v[2], x), v[3] = std::max(v[3], y);
    }
    void merge(const Bounds& o) {
      v[0] = std::min(v[0], o.v[0]), v[1] = std::min(v[1], o.v[1]);
      v[2] = std::max(v[2], o.v[2]), v[3] = std::max(v[3], o.v[3]);
    }
  };

  // Sorts balls into cells of at least `cell` (m), at most ~4 cells per ball. With `copy`, the
  // positions and, unless `radius` is empty (all radii equal), the radii are copied in cell order
  // (x(), y(), r()); without, those are left as they were. `bounds`, if given, were already
  // measured (else they are measured here).
  void build(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius, double cell, ForkJoin& pool, bool copy,
             const Bounds* bounds = nullptr);

  int cells() const { return nx_ * ny_; }
  int balls() const { return static_cast<int>(id_.size()); }
  // Balls of cell c are the slots [first(c), first(c + 1)); slot s is ball id[s].
  int first(int c) const { return start_[c]; }
  const int* id() const { return id_.data(); }
  const double* x() const { return copy_.x.data(); }
  const double* y() const { return copy_.y.data(); }
  const double* r() const { return copy_.r.data(); }

  // Calls f(slot a, slot b) once for every pair of slots a < b in the same or adjacent cells, for
  // the balls in slots [s0, s1), in the order UniformGrid::for_each_candidate_pair visits them.
  // The grid has a ring of empty cells around it, so no neighbour needs a bounds check, and
  // adjacent cells of a row are adjacent in slot order: each ball sees two contiguous runs, the
  // rest of its cell plus the cell to the right, and the three cells above. Walking balls rather
  // than cells skips the empty cells (most of them in a dilute gas) at no cost.
  template <class F>
  void for_each_forward_pair(int s0, int s1, F&& f) const {
    const int* __restrict start = start_.data();
    const int* __restrict cell = cell_sorted_.data();
    const int row = nx_;
    for (int a = s0; a < s1; ++a) {
      const int c = cell[a];
      // One loop over both runs: one loop exit to mispredict per ball instead of two.
      const int n_right = start[c + 2] - (a + 1), up0 = start[c + row - 1];
      const int total = n_right + (start[c + row + 2] - up0), jump = up0 - (a + 1) - n_right;
      for (int k = 0; k < total; ++k) f(a, a + 1 + k + (k < n_right ? 0 : jump));
    }
  }

  // The balls were renumbered in slot order (ball s is the ball in slot s): the grid now says so.
  // `rekey(new_number)` runs first, with new_number[old ball] = its slot, in the ball -> cell array
  // (dead from here on: no copy, at 10^6 balls every copy raises the peak memory).
  template <class F>
  void renumbered(F&& rekey) {
    const int n = balls();
    for (int s = 0; s < n; ++s) cell_of_[id_[s]] = s;
    rekey(static_cast<const int*>(cell_of_.data()));
    cell_of_ = cell_sorted_;
    for (int s = 0; s < n; ++s) id_[s] = s;
  }

  // Calls f(j) for every ball j in the 3 x 3 cells around the cell ball i was sorted into.
  template <class F>
  void for_each_near(int i, F&& f) const {
    const int c = cell_of_[i];
    for (int r = c - nx_; r <= c + nx_; r += nx_)
      for (int s = start_[r - 1]; s < start_[r + 2]; ++s) f(id_[s]);
  }

  // Calls f(slot) for every slot whose ball has x <= ax, x >= bx, y <= ay or y >= by, and for
  // some others in the same cells: the balls of the cells along the grid's edges that can hold
  // such a ball (a cell's bounds are those of cell_x and cell_y, monotone in x and y). Each slot
  // once. A row's cells are contiguous in slot order, so this is a few runs per row.
  template <class F>
  void for_each_slot_beyond(double ax, double bx, double ay, double by, F&& f) const {
    if (nx_ == 0) return;
    const int cxa = cell_x(ax), cxb = cell_x(bx), cya = cell_y(ay), cyb = cell_y(by);
    const auto run = [&](int row, int c0, int c1) {  // columns [c0, c1] of a row
      for (int s = start_[row * nx_ + c0]; s < start_[row * nx_ + c1 + 1]; ++s) f(s);
    };
    for (int cy = 1; cy <= ny_ - 2; ++cy) {
      if (cy <= cya || cy >= cyb || cxb <= cxa + 1) {
        run(cy, 1, nx_ - 2);
      } else {
        run(cy, 1, cxa);
        run(cy, cxb, nx_ - 2);
      }
    }
  }

 private:
  // x >= x0_ (the least x), so truncation is the floor UniformGrid takes; + 1 for the ring.
  int cell_x(double x) const { return clamp_cell((x - x0_) * inv_cell_, nx_ - 2) + 1; }
  int cell_y(double y) const { return clamp_cell((y - y0_) * inv_cell_, ny_ - 2) + 1; }
  static int clamp_cell(double c, int n) { return c < 0 ? 0 : c >= n ? n - 1 : static_cast<int>(c); }

  double x0_ = 0, y0_ = 0, inv_cell_ = 1;
  int nx_ = 0, ny_ = 0;         // cells per row and rows, with the empty ring included
  std::vector<int> start_;    // (cells + 1) prefix sums
  std::vector<int> cell_of_;  // ball -> cell
  std::vector<int> cell_sorted_;  // slot -> cell
  std::vector<int> id_;       // slot -> ball
  std::vector<std::vector<int>> strays_;  // per part of the parallel sort: its balls in others' cells
  CellOrderedBalls copy_;     // positions (and radii) in slot order, as of the last build with `copy`
};

// How much faster than the fastest ball at the start of the step a ball may become through
// collisions before the broad phase must be rebuilt (equal-mass elastic impacts can reach sqrt(2)).
inline constexpr double kSpeedMargin = 1.5;

// What the grid needs from the positions and velocities at the start of a step: the largest
// squared speed and the positions' bounds. Both are exact in any order, so parts may merge them.
struct StartScan {
  double speed2 = 0;
  HomeGrid::Bounds bounds;
  void add(double x, double y, double v2) {
    speed2 = std::max(speed2, v2);
    bounds.add(x, y);
  }
  void merge(const StartScan& o) {
    speed2 = std::max(speed2, o.speed2);
    bounds.merge(o.bounds);
  }
};

}  // namespace ballbench

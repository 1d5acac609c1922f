#pragma once
// exact's neighbour grid: fixed cells at least one diameter wide that tile the container (or, in
// open space, the start with room to spread; the border cells reach to infinity), each ball linked
// into its cell's list. A ball changes cell only at a cell-face event, so the grid is never rebuilt;
// every ball that can touch ball i is in the 3 x 3 block around i's cell.
//
// The cells follow their own rule, not grid_cell (core/uniform_grid.h): cell faces are events at
// which a ball's trajectory is brought up to date, so the tiling decides where its round-off falls,
// and another tiling changes the reference's figures on chaotic scenes. Measured with grid_cell's
// rule over the same extent: cells of 0.5 m instead of 0.3 m in regress-settle, 1.11 instead of
// 0.59 in seed-bowl, and 5 of `ballbench regress`'s 7 exact runs change their checksums (34
// differences, seed-bowl's final energy by 2%).
#include <algorithm>
#include <vector>

#include "scene.h"

namespace ballbench {

struct ExactModel;
struct ExactBalls;

class ExactGrid {
 public:
  // Lays the cells out for the scene and links every ball into its cell. Returns the narrowest
  // cell width in use (m). Throws std::runtime_error if the grid would need more than 1e9 cells.
  double build(const Scene& scene, const ExactModel& model, const ExactBalls& balls);

  // Ball i's cell along `axis` (0: x, 1: y), and the number of cells along it.
  int cell_along(int i, int axis) const { return axis == 0 ? cell_of_[i] % cells_[0] : cell_of_[i] / cells_[0]; }
  int cells_along(int axis) const { return cells_[axis]; }
  // Face of cell index `c` along `axis` (the lower face of c + 1 is the upper face of c: one formula).
  double face(int axis, int c) const { return lo_[axis] + c * width_[axis]; }

  // Ball i crossed the face of its cell along `axis` towards the lower (up = 0) or upper (1) cell.
  void cross(int i, int axis, int up) {
    int c[2] = {cell_of_[i] % cells_[0], cell_of_[i] / cells_[0]};
    c[axis] += up ? 1 : -1;
    unlink(i);
    link(i, c[1] * cells_[0] + c[0]);
  }

  // Calls f(j) for every ball j != i in the 3 x 3 block of cells around ball i's.
  template <class F>
  void for_each_near(int i, F&& f) const {
    const int cx = cell_of_[i] % cells_[0], cy = cell_of_[i] / cells_[0];
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, cells_[1] - 1); ++y)
      for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, cells_[0] - 1); ++x)
        for (int j = head_[y * cells_[0] + x]; j >= 0; j = next_[j])
          if (j != i) f(j);
  }

 private:
  void link(int i, int c) {
    cell_of_[i] = c;
    prev_[i] = -1;
    next_[i] = head_[c];
    if (head_[c] >= 0) prev_[head_[c]] = i;
    head_[c] = i;
  }
  void unlink(int i) {
    if (prev_[i] >= 0) next_[prev_[i]] = next_[i];
    else head_[cell_of_[i]] = next_[i];
    if (next_[i] >= 0) prev_[next_[i]] = prev_[i];
  }

  double lo_[2] = {0, 0}, width_[2] = {1, 1};
  int cells_[2] = {1, 1};
  // Cells indexed y * cells_[0] + x; each holds an intrusive doubly-linked list of its balls.
  std::vector<int> head_;                  // first ball of each cell, -1: empty
  std::vector<int> next_, prev_, cell_of_;  // per ball
};

}  // namespace ballbench

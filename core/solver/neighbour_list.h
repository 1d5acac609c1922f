#pragma once
// The home solver's broad phase for elastic scenes: a neighbour list with a skin (Verlet 1967,
// "Computer 'experiments' on classical fluids", Phys. Rev. 159, 98; Allen & Tildesley, "Computer
// Simulation of Liquids", 2nd ed., section 5.3). Every pair of balls closer than
// r_i + r_j + skin when the list is built is listed; while every ball stays within skin / 2 of
// where it was then, no unlisted pair can touch. The list lasts several steps, so the grid's sort
// and the walk over adjacent cells are paid once per build, not once per step. A ball's own
// neighbours (for predict) come from the grid of the build: its cells, at least 2 r_max + skin
// wide, hold every listed partner in the 3 x 3 block (one compressed row per ball cost more to
// build than the extra candidates cost predict, which runs for a few balls per step).
//
// Only where the order of candidate pairs does not matter: the contact pass adds contacts in the
// grid's order and its Gauss-Seidel solve depends on that order, so scenes with a contact pass keep
// the per-step grid (core/solver/PERFORMANCE.md).
#include <vector>

#include "fork_join.h"
#include "solver/home_grid.h"

namespace ballbench {

class NeighbourList {
 public:
  // Lists every pair in adjacent cells of `grid` closer than r_i + r_j + skin; the grid's cells
  // must be at least 2 r_max + skin wide. Balls are numbered as the grid's id() says. With
  // `equal_radii` every ball's radius is r0 (the grid holds no radii).
  void build(const HomeGrid& grid, bool equal_radii, double r0, double skin, ForkJoin& pool);

  long pairs() const { return static_cast<long>(first_.size()); }
  const int* first() const { return first_.data(); }
  const int* second() const { return second_.data(); }

 private:
  std::vector<std::vector<int>> found_;  // per part: pairs as consecutive (a, b) slots
  std::vector<size_t> count_;            // per part: how much of found_ holds pairs
  std::vector<int> first_, second_;      // the pairs, in ball numbers
};

}  // namespace ballbench

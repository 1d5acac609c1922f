#include "solver/exact_grid.h"

#include <cmath>
#include <stdexcept>

#include "solver/contact.h"
#include "solver/exact_world.h"

namespace ballbench {
namespace {

// Default grid: at most about this many cells per ball (plus a few), so sparse scenes stay small.
constexpr double kCellsPerBall = 4.0;
// Cells are this much wider than the largest diameter, so a ball that round-off leaves a hair
// outside its cell still finds every ball it can touch in the 3 x 3 block.
constexpr double kCellMargin = 1e-9;

}  // namespace

double ExactGrid::build(const Scene& scene, const ExactModel& model, const ExactBalls& balls) {
  const int n = balls.size();
  const double cell_size = model.settings.cell_size;
  const double rmax = n > 0 ? scene.radius.maxCoeff() : 1.0;
  double cell = std::max(cell_size > 0 ? cell_size : 2 * rmax, 2 * rmax * (1 + kCellMargin));
  double lo[2], hi[2];
  if (model.has_walls) {
    for (int k = 0; k < 2; ++k) lo[k] = model.box_lo[k], hi[k] = model.box_hi[k];
  } else {
    // Open space: the grid covers the start with room to spread; the border cells reach to
    // infinity (coordinates are clamped), so a ball far outside is still found, only slower.
    for (int k = 0; k < 2; ++k) {
      lo[k] = n > 0 ? scene.initial.pos.col(k).minCoeff() : 0.0;
      hi[k] = n > 0 ? scene.initial.pos.col(k).maxCoeff() : 0.0;
      const double pad = std::max(0.5 * (hi[k] - lo[k]), 4 * cell);
      lo[k] -= pad, hi[k] += pad;
    }
  }
  double nc[2];
  for (int k = 0; k < 2; ++k) nc[k] = std::max(1.0, std::floor((hi[k] - lo[k]) / cell));
  const double cap = kCellsPerBall * n + 16;
  if (cell_size <= 0 && nc[0] * nc[1] > cap) {
    const double shrink = std::sqrt(nc[0] * nc[1] / cap);
    for (int k = 0; k < 2; ++k) nc[k] = std::max(1.0, std::floor(nc[k] / shrink));
  }
  if (nc[0] * nc[1] > 1e9) throw std::runtime_error("exact: the neighbour grid would need more than 1e9 cells");
  double used = kNever;
  for (int k = 0; k < 2; ++k) {
    cells_[k] = static_cast<int>(nc[k]);
    lo_[k] = lo[k];
    width_[k] = (hi[k] - lo[k]) / nc[k];
    used = std::min(used, width_[k]);
  }
  head_.assign(static_cast<size_t>(cells_[0]) * cells_[1], -1);
  next_.assign(n, -1), prev_.assign(n, -1), cell_of_.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    int c[2];
    for (int k = 0; k < 2; ++k) {
      const double f = std::floor((balls.pos[k][i] - lo_[k]) / width_[k]);
      c[k] = f < 0 ? 0 : f >= cells_[k] ? cells_[k] - 1 : static_cast<int>(f);
    }
    link(i, c[1] * cells_[0] + c[0]);
  }
  return used;
}

}  // namespace ballbench

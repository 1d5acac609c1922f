#pragma once
// Tunnelling, judged from two consecutive samples only (no engine's word is taken).
#include <Eigen/Core>

#include "scene.h"
#include "state.h"
#include "uniform_grid.h"

namespace ballbench {

// Balls whose centre is inside the box (boundary included) in `prev` and beyond a wall in `cur`:
// one event per escape. 0 in open space.
int wall_escapes(const State& prev, const State& cur, const Container& box);

// Is a centre strictly outside the box?
bool beyond_wall(const Eigen::Vector2d& p, const Container& box);

// Pairs apart in both samples (distance >= r_i + r_j) whose relative motion, taken as a straight
// line between the samples, came closer than (1 - tolerance) (r_i + r_j) - (|dv_i| + |dv_j|) h / 4:
// they passed through each other. A resolved bounce of the pair never counts: both samples then
// lie on the outer side of the tangent at the contact point, and so does the line between them.
// When a ball collides between the samples its true path bends: a path with one kink of velocity
// change dv over a sample interval h strays at most |dv| h / 4 from its chord, so that much of a
// dip is explained by the velocities the samples show. Each ball's own change counts, not the
// pair's relative one: a ball struck by its partner and then by a wall can end with the pair's
// relative velocity almost unchanged though both paths bent (measured: `exact` at dt 0.08 on
// seed-box, where |dw| h / 4 flagged such a pair). Two balls that pass through each other without
// interacting keep dv = 0 and are counted in full. Several collisions of one ball within a step
// (fast impacts into a dense pile) can bend its path further than its net dv shows: `exact` got 2
// flags in 300 steps of a 2000-ball bowl with impacts at 80 m/s. `tolerance` absorbs the rounding
// of soft contacts (see MetricsConfig).
// Its working memory lives in `scratch`, kept across calls: it runs every step, and fresh
// allocations of a few MB per step cost page faults that outweigh the search at 10^5 balls.
struct PassthroughScratch {
  UniformGrid grid;
  Eigen::MatrixX2d mid;     // midpoints of each ball's step
  Eigen::VectorXd moved;    // each ball's displacement over the step
  // mid x, mid y, moved, radius and the ball's index, gathered in the grid's cell order, so a ball's
  // neighbourhood is three contiguous runs of memory (random access missed the cache at 10^5).
  std::vector<double> sx, sy, smoved, sradius;
  std::vector<int> sid;
};
int pair_passthroughs(const State& prev, const State& cur, const Eigen::VectorXd& radius, double tolerance,
                      PassthroughScratch& scratch);

// Closest approach over s in [0, 1] of d0 + s (d1 - d0), the relative position moving linearly.
double closest_approach(const Eigen::Vector2d& d0, const Eigen::Vector2d& d1);

}  // namespace ballbench

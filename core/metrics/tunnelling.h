#pragma once
// Tunnelling, judged from two consecutive samples only (no engine's word is taken).
#include <array>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "fork_join.h"
#include "scene.h"
#include "state.h"
#include "uniform_grid.h"

namespace ballbench {

// Balls whose centre is inside the box (boundary included) in `prev` and beyond a wall in `cur`:
// one event per escape. 0 in open space.
int wall_escapes(const State& prev, const State& cur, const Container& box);

// Is a centre strictly outside the box?
bool beyond_wall(const Eigen::Vector2d& p, const Container& box);

// Where the straight step from a (inside the box) to b (beyond it) first crosses a wall.
Eigen::Vector2d wall_crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Container& box);

// Closest approach over s in [0, 1] of d0 + s (d1 - d0), the relative position moving linearly,
// and the s where it happens.
double closest_approach(const Eigen::Vector2d& d0, const Eigen::Vector2d& d1);
double closest_approach_fraction(const Eigen::Vector2d& d0, const Eigen::Vector2d& d1);

// A pair passes through: apart in both samples (distance >= r_i + r_j) and its relative motion,
// taken as a straight line between the samples, came closer than
// (1 - tolerance) (r_i + r_j) - (|dv_i| + |dv_j|) h / 4. A resolved bounce of the pair never counts:
// both samples then lie on the outer side of the tangent at the contact point, and so does the line
// between them. When a ball collides between the samples its true path bends: a path with one kink
// of velocity change dv over a sample interval h strays at most |dv| h / 4 from its chord, so that
// much of a dip is explained by the velocities the samples show. Each ball's own change counts, not
// the pair's relative one: a ball struck by its partner and then by a wall can end with the pair's
// relative velocity almost unchanged though both paths bent (measured: `exact` at dt 0.08 on
// seed-box, where |dw| h / 4 flagged such a pair). Two balls that pass through each other without
// interacting keep dv = 0 and are counted in full. Several collisions of one ball within a step
// (fast impacts into a dense pile) can bend its path further than its net dv shows: `exact` got 2
// flags in 300 steps of a 2000-ball bowl with impacts at 80 m/s. `tolerance` absorbs the rounding
// of soft contacts (see MetricsConfig). This is the definition; the search below must agree with it.
bool passes_through(const State& prev, const State& cur, int i, int j, double rs, double tolerance);

// What one step of motion shows: `finite` false (and nothing counted) when a position or velocity
// of `cur` is not finite.
struct StepTunnelling {
  bool finite = true;
  bool contained = true;  // no centre beyond the box by more than the largest diameter
  int wall = 0, pair = 0;
};

// Tunnelling and finiteness, step by step: one sweep over the states, then a pair search that
// keeps its candidate pairs across steps (a Verlet neighbour list: L. Verlet, Phys. Rev. 159, 98
// (1967)), with the balls that outrun it searched apart. Exact: it counts what passes_through()
// says of every pair, no more and no fewer, because
//  - At a build, every ball gets a reference point (the midpoint of that step) and the list takes
//    every pair whose references are closer than c (r_i + r_j) + 2 a, c = max(1, 1 - tolerance)
//    (times 1 + 1e-6 for rounding), a the allowance.
//  - A ball is contained in a step when both its samples lie within a of its reference; then so
//    does every point of its straight step (a disc is convex). Two contained balls that are not
//    listed stay at least |ref_i - ref_j| - 2 a >= c (r_i + r_j) apart along their straight steps,
//    so their closest approach is no nearer than (1 - tolerance)(r_i + r_j) - bend: they cannot
//    count. Among contained balls, the listed pairs are the only candidates.
//  - The other balls (escaped: fast, kicked, teleported) are searched every step: against contained
//    balls in the grid of references (a contained partner's reference lies within
//    c (r_i + r_j) + a + |step_e| / 2 of the escaped ball's step midpoint), and among themselves in
//    a grid over their step midpoints (midpoints within c (r_i + r_j) + (|step_i| + |step_j|) / 2).
//    A pair with an escaped ball is judged only here, so every pair is judged exactly once.
//  - Filters before passes_through() drop only pairs that cannot count: the relative step must be
//    at least the chord 2 s (r_i + r_j), s = sqrt(1 - (1 - tolerance)^2), and the line through both
//    relative positions must pass within (1 - tolerance)(r_i + r_j); each with a margin of 1e-6
//    (r_i + r_j), far above rounding for coordinates up to ~10^8 radii.
// The list is rebuilt when more than a share of the balls escaped (their search then costs more).
// tests/test_metrics.cpp compares it with the brute-force count over every pair, on one part and
// on several.
//
// Threads: the sweep, the list's build and its check run on a ForkJoin team (from kParallelBalls
// balls by default), each part over a fixed range of balls or of the grid's rows, with a list of
// its own; the counts are integers and the step statistics are summed in part order, so the
// result is the same on any number of parts. The engine's own threads wait meanwhile (the runner
// steps, then checks), so the harness may use the cores the engine uses.
// Working memory lives here, kept across steps: fresh allocations of a few MB per step cost page
// faults that outweigh the search at 10^5 balls.
class TunnellingCheck {
 public:
  // `threads` 0: one below kParallelBalls balls, else the machine's cores (at most 8).
  TunnellingCheck(const Eigen::VectorXd& radius, const Container& box, double tolerance, int threads = 0);
  // Below it the hand-overs cost more than a second core saves (bench/harness_benchmark.cpp).
  static constexpr int kParallelBalls = 50'000;

  StepTunnelling step(const State& prev, const State& cur);

  // The events the last step() counted, as many as its counts: the balls that escaped the box (in
  // ball order) and the pairs that passed through (i < j, ordered by i then j, whatever the number
  // of parts that found them).
  const std::vector<int>& wall_hits() const { return wall_hits_; }
  const std::vector<std::array<int, 2>>& pair_hits() const { return pair_hits_; }

  long rebuilds() const { return rebuilds_; }  // list builds so far (for tests and benchmarks)
  // Allowance as a multiple of the largest radius, and the share of escaped balls that triggers
  // a rebuild. Measured defaults (bench/harness_benchmark.cpp); tests vary them.
  void set_tuning(double allowance_radii, double rebuild_share);

 private:
  struct Sweep {
    bool finite = true;
    bool contained = true;
    int wall = 0;
    double step2_max = 0;  // the longest step of a ball, squared
    double step2_sum = 0;  // the sum of every ball's step squared
  };
  // What one part of the team holds: its pairs of the list (those whose first ball lies in its
  // rows of the grid), its escaped balls of this step (in ball order), its pass-throughs among its
  // listed pairs this step, its scratch.
  struct Part {
    std::vector<std::array<int, 2>> list;
    size_t listed = 0;  // pairs in list (its size is only capacity)
    std::vector<int> survivors;
    std::vector<int> escaped;
    Sweep sweep;
    int pairs = 0;  // pass-throughs among its listed pairs, this step
    std::vector<std::array<int, 2>> hits;  // those pairs
  };
  Sweep sweep(const State& prev, const State& cur, bool contained);
  void rebuild(const State& prev, const State& cur, double step_rms);
  void gather_escaped();
  int count_listed(const State& prev, const State& cur, Part& part);
  int count_escaped(const State& prev, const State& cur);
  double* records();
  const double* records() const { return const_cast<TunnellingCheck*>(this)->records(); }
  bool may_pass(int a, int b, double rs) const;
  bool judge(const State& prev, const State& cur, int a, int b, double rs) const;

  Eigen::VectorXd radius_;
  Container box_;
  double tolerance_;
  double r_min_ = 0, r_max_ = 0;
  bool equal_radii_ = true;
  bool never_ = false;              // tolerance >= 1: nothing can count
  double reach_ = 1;                // c (1 + 1e-6): list range in units of r_i + r_j, before 2 a
  double chord2_ = 0, close2_ = 0;  // filters: (2 s)^2 and (1 - tolerance)^2, with rounding margins
  bool line_filter_ = false;        // the division-free filter of count_listed() holds
  double mover2_ = 0;               // a step shorter than this for every ball: nothing can count
  double allowance_radii_ = 3.0, rebuild_share_ = 0.1;
  double a_ = 0;                    // the allowance of the current list (m)

  bool built_ = false;
  long rebuilds_ = 0;
  Eigen::MatrixX2d ref_;            // reference points of the current list, by ball
  UniformGrid grid_;                // over ref_; its order() maps a slot (position in cell order) to a ball
  CellOrderedBalls slots_;          // reference point and radius by slot of grid_
  ForkJoin pool_;
  std::vector<Part> parts_;          // one per part of pool_
  // Per step, by ball: prev x, prev y, step x, step y side by side, 32-byte aligned: one cache line
  // per ball for the pair filters, which reach balls at random.
  std::vector<double> rec_;
  std::vector<int> escaped_;        // the balls not contained in this step, in ball order
  std::vector<int> wall_hits_;
  std::vector<std::array<int, 2>> pair_hits_;
  std::vector<char> is_escaped_;    // by ball
  UniformGrid escaped_grid_;
  Eigen::MatrixX2d escaped_mid_;
};

}  // namespace ballbench

#pragma once
// A sample of the world: what every engine reads back and the only input metrics see.
#include <Eigen/Core>

namespace ballbench {

struct State {
  double t = 0.0;         // simulated time of the sample (s)
  Eigen::MatrixX2d pos;   // ball centres (n x 2, m); column-major, so x and y are contiguous arrays
  Eigen::MatrixX2d vel;   // ball velocities (n x 2, m/s)

  int n() const { return static_cast<int>(pos.rows()); }
  void resize(int n) {
    pos.resize(n, 2);
    vel.resize(n, 2);
  }
};

}  // namespace ballbench

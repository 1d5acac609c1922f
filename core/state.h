#pragma once
// A sample of the world: what every engine reads back and the only input metrics see.
#include <Eigen/Core>

namespace ballbench {

struct State {
  double t = 0.0;         // simulated time of the sample (s)
  Eigen::MatrixX2d pos;   // ball centres (n x 2, m); column-major, so x and y are contiguous arrays
  Eigen::MatrixX2d vel;   // ball velocities (n x 2, m/s)
  // Rotation, only for a scene that needs it (SceneFeatures::rotation); empty otherwise, so a
  // frictionless scene without spin builds, reads and checks none of it.
  Eigen::VectorXd w;      // angular velocity (n, rad/s, counter-clockwise)
  Eigen::VectorXd angle;  // orientation (n, rad, counter-clockwise from the start), for pictures

  int n() const { return static_cast<int>(pos.rows()); }
  bool rotates() const { return w.size() > 0; }
  void resize(int n, bool rotation = false) {
    pos.resize(n, 2);
    vel.resize(n, 2);
    w.resize(rotation ? n : 0);
    angle.resize(rotation ? n : 0);
  }
};

}  // namespace ballbench

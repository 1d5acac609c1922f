#pragma once
// The world `home` steps: the balls' state as plain structure of arrays, in the solver's own ball
// order (renumbered in cell order from 10^4 balls: `ball_of` maps the scene's order to it), and the
// scene's constants. Every stage of the step reads and writes it; none keeps a copy. Between events
// every ball moves on a straight line: on_line and approach_root below.
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "scene.h"
#include "solver/contact.h"

namespace ballbench {

struct HomeWorld {
  int n = 0;
  Eigen::MatrixX2d p, v;  // positions (m) and velocities (m/s), one row per ball
  // Radius and inverse mass per ball; empty when every ball has r0 (equal_radii) or inv_m0
  // (equal_masses), which saves 8 bytes per ball each.
  Eigen::VectorXd r, inv_m;
  double r0 = 0, inv_m0 = 0;
  bool equal_radii = false, equal_masses = false;
  double rmax = 0, rmin = 0;  // the largest and the smallest radius (m)
  double e = 1;               // restitution
  Eigen::Vector2d g = Eigen::Vector2d::Zero();
  Container box;
  bool walls = false;  // the container is a box
  // Rotation, only for a scene that rotates (SceneFeatures::rotation: friction above 0 or a ball
  // that starts spinning); w and angle are empty otherwise, and nothing about rotation is stepped.
  bool rotation = false;
  Eigen::VectorXd w, angle;  // angular velocity (rad/s) and angle (rad), counter-clockwise
  double mu = 0;             // Coulomb friction coefficient, ball-ball and ball-wall
  double k = 0.5;            // inertia factor: I = k m r^2
  std::vector<int> ball_of;  // scene index -> ball

  HomeWorld() = default;
  HomeWorld(const Scene& scene, bool equal_radii, bool equal_masses)
      : n(scene.n()),
        p(scene.initial.pos),
        v(scene.initial.vel),
        r0(n > 0 ? scene.radius(0) : 0.0),
        inv_m0(n > 0 ? 1.0 / scene.mass(0) : 0.0),
        equal_radii(equal_radii),
        equal_masses(equal_masses),
        rmax(scene.radius.maxCoeff()),
        rmin(n > 0 ? scene.radius.minCoeff() : 0.0),
        e(scene.restitution),
        g(scene.gravity),
        box(scene.container),
        walls(scene.container.kind == ContainerKind::Box),
        rotation(scene.features().rotation),
        mu(scene.friction),
        k(inertia_factor(scene.inertia)),
        ball_of(n) {
    if (rotation) w = scene.initial.rotates() ? scene.initial.w : Eigen::VectorXd::Zero(n), angle = Eigen::VectorXd::Zero(n);
    if (!equal_radii) r = scene.radius;
    if (!equal_masses) inv_m = scene.mass.cwiseInverse();
    for (int i = 0; i < n; ++i) ball_of[i] = i;
  }

  double radius(int i) const { return equal_radii ? r0 : r(i); }
  double inv_mass(int i) const { return equal_masses ? inv_m0 : inv_m(i); }
  // The largest speed now (m/s).
  double max_speed() const { return n > 0 ? std::sqrt(v.rowwise().squaredNorm().maxCoeff()) : 0.0; }
  // Friction acts: the balls rotate and the coefficient is above 0.
  bool rough() const { return rotation && mu > 0; }
  // Gap between ball i and a wall (m): side 0 is the min wall, side 1 the max wall.
  double wall_gap(int i, int axis, int side) const {
    return side == 0 ? p(i, axis) - radius(i) - box.min(axis) : box.max(axis) - radius(i) - p(i, axis);
  }
};

// Where a ball that was at x with velocity v at its own clock t_own is at time t (one coordinate).
// Every advance along a line (the event loop's, the end of a step, read()'s end positions) is this
// one expression, so read() gives exactly what the next step's start computes.
inline double on_line(double x, double v, double t, double t_own) { return x + v * (t - t_own); }

// How long until an approaching pair (separation d, relative velocity w, b = d.w < 0,
// c = |d|^2 - (r_i + r_j)^2 > 0) touches: the smaller root of |d + w t| = r_i + r_j, in the
// cancellation-free form; infinity if it passes by.
inline double approach_root(double b, double c, double wx, double wy) {
  const double a = wx * wx + wy * wy;
  const double disc = b * b - a * c;
  return disc < 0 ? kNever : c / (-b + std::sqrt(disc));
}

// Can a ball with these gaps to the four walls (min x, max x, min y, max y) reach the one it moves
// towards within k = dt (1 + 1e-9)? Bitwise, no ternaries: the direction of motion is a coin toss
// per ball, and the compiler turned the selects into branches once nothing else needed both gaps.
inline bool reaches_wall(double gx0, double gx1, double gy0, double gy1, double vx, double vy, double k) {
  const double kx = std::abs(vx) * k, ky = std::abs(vy) * k;
  const bool left = vx < 0, down = vy < 0;
  return (left & (gx0 <= kx)) | (!left & (gx1 <= kx)) | (down & (gy0 <= ky)) | (!down & (gy1 <= ky));
}

}  // namespace ballbench

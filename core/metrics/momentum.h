#pragma once
// Momentum of a state.
// Linear: P = sum_i m_i v_i (kg m/s). Conserved in open space without gravity; walls and gravity
// change it, so its drift is reported always but judged only in open space.
// Angular, about a fixed point c: L = sum_i m_i (x_i - c) x v_i + I_i w_i (kg m^2/s; z component,
// counter-clockwise), orbital plus spin, with I_i = k m_i r_i^2. Friction exchanges the two parts
// and conserves their sum in open space without gravity. c is the container's centre, or in open
// space the initial centre of mass; since P is conserved there, L's drift does not depend on c.
#include <Eigen/Core>

#include "scene.h"
#include "state.h"

namespace ballbench {

inline Eigen::Vector2d total_momentum(const State& s, const Eigen::VectorXd& mass) {
  return s.vel.transpose() * mass;
}

// The point angular momentum is taken about (m).
Eigen::Vector2d angular_momentum_centre(const Scene& scene);

double angular_momentum(const State& s, const Scene& scene, const Eigen::Vector2d& centre);

}  // namespace ballbench

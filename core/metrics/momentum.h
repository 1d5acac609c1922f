#pragma once
// Total linear momentum P = sum_i m_i v_i (kg m/s). Conserved in open space without gravity;
// walls and gravity change it, so its drift is reported always but judged only in open space.
#include <Eigen/Core>

#include "state.h"

namespace ballbench {

inline Eigen::Vector2d total_momentum(const State& s, const Eigen::VectorXd& mass) {
  return s.vel.transpose() * mass;
}

}  // namespace ballbench

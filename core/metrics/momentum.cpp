#include "metrics/momentum.h"

namespace ballbench {

Eigen::Vector2d angular_momentum_centre(const Scene& scene) {
  if (scene.container.kind == ContainerKind::Box) return 0.5 * (scene.container.min + scene.container.max);
  return scene.initial.pos.transpose() * scene.mass / scene.mass.sum();
}

double angular_momentum(const State& s, const Scene& scene, const Eigen::Vector2d& centre) {
  const Eigen::ArrayXd dx = s.pos.col(0).array() - centre.x(), dy = s.pos.col(1).array() - centre.y();
  const double orbital = (scene.mass.array() * (dx * s.vel.col(1).array() - dy * s.vel.col(0).array())).sum();
  if (!s.rotates()) return orbital;
  const double k = inertia_factor(scene.inertia);
  return orbital + k * (scene.mass.array() * scene.radius.array().square() * s.w.array()).sum();
}

}  // namespace ballbench

#include "metrics/energy.h"

namespace ballbench {

double energy_reference(const Scene& scene) {
  const Eigen::Vector2d g = scene.gravity;
  if (scene.container.kind == ContainerKind::Box) {
    const Eigen::Vector2d lo = scene.container.min, hi = scene.container.max;
    // -g . x is linear, so its minimum over the box is at a corner.
    double m = -g.dot(lo);
    for (const Eigen::Vector2d& c : {Eigen::Vector2d(hi.x(), lo.y()), Eigen::Vector2d(lo.x(), hi.y()), hi})
      m = std::min(m, -g.dot(c));
    return m;
  }
  return (-(scene.initial.pos * g)).minCoeff();
}

double kinetic_energy(const State& s, const Scene& scene) {
  const double translation = 0.5 * scene.mass.dot(s.vel.rowwise().squaredNorm());
  if (!s.rotates()) return translation;
  const double k = inertia_factor(scene.inertia);
  return translation + 0.5 * k * (scene.mass.array() * scene.radius.array().square() * s.w.array().square()).sum();
}

double potential_energy(const State& s, const Eigen::VectorXd& mass, const Eigen::Vector2d& gravity, double reference) {
  return mass.dot(((-(s.pos * gravity)).array() - reference).matrix());
}

double total_energy(const State& s, const Scene& scene, double reference) {
  return kinetic_energy(s, scene) + potential_energy(s, scene.mass, scene.gravity, reference);
}

}  // namespace ballbench

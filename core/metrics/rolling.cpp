#include "metrics/rolling.h"

#include <cmath>

namespace ballbench {

RollingClosedForm rolling_closed_form(const Scene& scene, int i) {
  const double k = inertia_factor(scene.inertia), r = scene.radius(i), mu = scene.friction, g = -scene.gravity.y();
  const double v0 = scene.initial.vel(i, 0), vy0 = scene.initial.vel(i, 1), w0 = scene.spin(i);
  RollingClosedForm out;
  out.speed = (v0 - k * r * w0) / (1 + k);
  const double gap = scene.initial.pos(i, 1) - r - scene.container.min.y();  // above the floor (m)
  const double slowing = mu * g * (1 + 1 / k);                                // of the slip while sliding (m/s^2)
  double u = v0 + w0 * r, t = 0;
  if (gap > 0 || vy0 > 0) {
    if (scene.restitution > 0) return out;
    const double vi = std::sqrt(vy0 * vy0 + 2 * g * gap);  // speed into the floor
    t = (vy0 + vi) / g;
    u = mu * vi * (1 + 1 / k) >= std::abs(u) ? 0.0 : u - std::copysign(mu * vi * (1 + 1 / k), u);
  }
  out.time_to_roll = t + std::abs(u) / slowing;
  return out;
}

}  // namespace ballbench

#include "solver/exact_world.h"

namespace ballbench {

ExactModel::ExactModel(const Scene& scene, const ExactSettings& s)
    : settings(s),
      ball_count(scene.n()),
      restitution(scene.restitution),
      friction(scene.friction),
      inertia_factor(ballbench::inertia_factor(scene.inertia)),
      gravity{scene.gravity.x(), scene.gravity.y()},
      has_walls(scene.container.kind == ContainerKind::Box),
      contact_time(s.contact_time),
      rest_velocity(s.rest_velocity),
      wake_velocity(s.wake_velocity),
      support_gap(s.support_gap) {
  has_gravity = gravity[0] != 0 || gravity[1] != 0;
  rotation = scene.features().rotation;
  rough_walls = friction > 0 && has_gravity && has_walls;
  if (has_walls) {
    box_lo[0] = scene.container.min.x(), box_lo[1] = scene.container.min.y();
    box_hi[0] = scene.container.max.x(), box_hi[1] = scene.container.max.y();
  }
}

ExactBalls::ExactBalls(const Scene& scene, const ExactModel& model) {
  const int n = model.ball_count;
  radius.resize(n), inv_mass.resize(n);
  for (int k = 0; k < 2; ++k) pos[k].resize(n), vel[k].resize(n), acc[k].resize(n);
  for (int i = 0; i < n; ++i) {
    radius[i] = scene.radius(i);
    inv_mass[i] = 1.0 / scene.mass(i);
    for (int k = 0; k < 2; ++k) {
      pos[k][i] = scene.initial.pos(i, k);
      vel[k][i] = scene.initial.vel(i, k);
      acc[k][i] = model.gravity[k];
    }
  }
  if (model.rotation) {
    spin.resize(n), angle.resize(n);
    for (int i = 0; i < n; ++i) {
      spin[i] = scene.spin(i);
      angle[i] = scene.initial.angle.size() == n ? scene.initial.angle(i) : 0.0;
    }
    spin_rate.assign(n, 0.0);
    slip_sign.assign(n, 0);
    held_axes.assign(n, 0);
  }
  clock.assign(n, 0.0);
  jam_window_start.assign(n, -kNever);
  jam_events.assign(n, 0);
  course.assign(n, 0);
  asleep.assign(n, 0);
  step_events.assign(n, 0);
}

}  // namespace ballbench

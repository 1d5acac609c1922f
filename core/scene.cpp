#include "scene.h"

#include <cmath>

namespace ballbench {

long Scene::steps() const { return std::lround(duration / dt); }

SceneFeatures Scene::features() const {
  SceneFeatures f;
  f.gravity = gravity.squaredNorm() > 0.0;
  f.walls = container.kind == ContainerKind::Box;
  f.equal_radii = n() == 0 || (radius.array() == radius(0)).all();
  f.equal_masses = n() == 0 || (mass.array() == mass(0)).all();
  f.elastic = restitution == 1.0;
  f.frictionless = friction == 0.0;
  f.rotation = !f.frictionless || (initial.rotates() && (initial.w.array() != 0.0).any());
  return f;
}

double inertia_factor(Inertia inertia) { return inertia == Inertia::sphere ? 0.4 : 0.5; }

const char* inertia_name(Inertia inertia) { return inertia == Inertia::sphere ? "sphere" : "disk"; }

}  // namespace ballbench

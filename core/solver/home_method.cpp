#include "solver/home_method.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "accuracy_spec.h"
#include "scene.h"

namespace ballbench {
namespace {

// A random close packing of discs fills about 82% of the plane (hexagonal: 91%).
constexpr double kPackingFraction = 0.82;
// The soft step's substeps never fall below its default (soft_step.h), which settles piles and
// bounces as measured there.
constexpr int kMinSubsteps = 4;

}  // namespace

double settled_layers(const Scene& scene) {
  if (scene.n() == 0 || scene.container.kind != ContainerKind::Box) return 1;
  const double width = scene.container.max.x() - scene.container.min.x();
  const double height = scene.container.max.y() - scene.container.min.y();
  const double area = std::numbers::pi * scene.radius.squaredNorm();
  const double r = scene.radius.mean();
  const double layer = std::sqrt(3.0) * r;  // hexagonal rows
  const double settled = std::min(area / (kPackingFraction * width), height);
  return std::max(1.0, settled / layer);
}

HomeMethod choose_home_method(const Scene& scene, double dt, double overlap) {
  HomeMethod m;
  // One ball has nothing to pile on: the event-driven path follows its bounces exactly.
  if (scene_class(scene) != SceneClass::pile || scene.n() < 2) return m;
  m.soft = true;
  const double load = settled_layers(scene) * scene.gravity.norm();  // per unit mass (m/s^2)
  const double sag = overlap * scene.radius.minCoeff();               // (m)
  const double omega = std::max(std::sqrt(kSagSafety * load / sag), kLandingRate / overlap);
  m.contact_hertz = omega / (2 * std::numbers::pi);
  m.substeps = std::max(kMinSubsteps, int(std::ceil(4 * m.contact_hertz * dt - 1e-9)));
  return m;
}

}  // namespace ballbench

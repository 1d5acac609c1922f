#pragma once
// The standard benchmark scenes, scaled to any ball count at the seed scenes' density: a "gas"
// (seed-box: no gravity, balls everywhere) and a "bowl" (seed-bowl: g = 100 down, balls filling
// the lower part of the box), where radius and speeds stay the seed's and the box grows with the
// count; and the "fluid", the thesis's wish for "many more, smaller balls": the seed-bowl's own
// box, with smaller balls as the count grows.
#include <string>

#include "scene.h"

namespace ballbench::bench {

enum class SceneKind { Gas, Bowl, Fluid };

const char* scene_kind_name(SceneKind k);

// Gas and bowl: n balls of radius 0.25 in a box of area 5 n (seed-box: 20 balls in 10 x 10),
// restitution 1 for the gas (so the energy stays put while timing) and 0.99 for the bowl.
// Fluid: seed-bowl (10 x 10 box, g = 100, restitution 0.99, velocities uniform in [-2.5, 2.5]^2)
// with n balls at its packing fraction: radius 0.25 sqrt(72 / n), on its lattice scaled (spacing
// 0.6 sqrt(72 / n), sqrt(8 n / 9) columns from its first ball at (-4.6, -4.6)); the built-in scene
// fluid-10k is n = 10^4, with its spec (overlap <= 2%; not at rest).
Scene scaled_scene(SceneKind kind, int n);

// The same scene, built once per (kind, n) and kept for the process: benchmarks of one run share
// it (building 10^6 random balls takes a while).
const Scene& shared_scaled_scene(SceneKind kind, int n);

}  // namespace ballbench::bench

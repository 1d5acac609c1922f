#pragma once
// The standard benchmark scenes, scaled to any ball count at the seed scenes' density: a "gas"
// (seed-box: no gravity, balls everywhere) and a "bowl" (seed-bowl: g = 100 down, balls filling
// the lower part of the box). Radius and speeds stay the seed's; the box grows with the count.
#include <string>

#include "scene.h"

namespace ballbench::bench {

enum class SceneKind { Gas, Bowl };

const char* scene_kind_name(SceneKind k);

// n balls of radius 0.25 in a box of area 5 n (seed-box: 20 balls in 10 x 10), restitution 1 for
// the gas (so the energy stays put while timing) and 0.99 for the bowl.
Scene scaled_scene(SceneKind kind, int n);

// The same scene, built once per (kind, n) and kept for the process: benchmarks of one run share
// it (building 10^6 random balls takes a while).
const Scene& shared_scaled_scene(SceneKind kind, int n);

}  // namespace ballbench::bench

#pragma once
// The settled-pile benchmark scene: balls poured into a box under gravity and run until they are
// at rest, then saved, so a benchmark times a pile at rest from its first step (as MuJoCo's step
// benchmark resets to a saved state).
#include "scene.h"

namespace ballbench::bench {

// n balls of radius 0.25 (restitution 0.5, g 9.81, dt 0.01) dropped from a loose square lattice
// into a box about as wide as the pile is tall, settled by `home` (its default profile up to
// kSettledAtSpecBalls, at the pile's spec; its soft profile beyond) until the RMS speed is below
// kSettledSpeed or kSettleSteps have run. The scene's initial state is the settled one; its name
// says the count.
Scene settled_pile(int n);

// Built once per n and kept for the process (settling 10^5 balls takes a while).
const Scene& shared_settled_pile(int n);

// The pile counts as settled below this RMS speed (m/s), and settling stops after this many steps.
inline constexpr double kSettledSpeed = 1e-3;
inline constexpr int kSettleSteps = 5000;
// Piles up to this many balls are settled at the spec they are judged at (15 s for 10^4 balls).
inline constexpr int kSettledAtSpecBalls = 10'000;

}  // namespace ballbench::bench

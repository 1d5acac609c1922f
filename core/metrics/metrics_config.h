#pragma once
// The tolerances the metrics judge by, recorded in every result (JSON "metrics_config").

namespace ballbench {

struct MetricsConfig {
  /// Overlap deeper than this fraction of the radius sum (pairs) or of the radius (walls) counts as
  /// "in contact" for sticking, and a straight-line pass closer than (1 - this) of the radius sum
  /// counts as tunnelling. 2% sits above the rest penetration soft engines allow by design (Box2D's
  /// linear slop, 0.005 m, is 1% of the seed scenes' radius sum of 0.5 m). (dimensionless)
  double contact_tolerance = 0.02;
  /// Consecutive samples a contact may stay deeper than the tolerance before it counts as stuck. A
  /// bounce resolves within one or two steps; 10 steps of 0.01 s is already visibly stuck. (samples)
  int stuck_samples = 10;
  /// Energy above this multiple of the initial energy (plus the initial kinetic energy scale) means
  /// the run has blown up: it is stopped and marked diverged. (dimensionless)
  double divergence_energy_factor = 100.0;
  /// The sampled metrics (energy, momentum, overlaps, sticking, penetration, the error against the
  /// reference, checksums, figure series) see every k-th step and the last; tunnelling and the
  /// finiteness check see every step, since a pass-through lasts a step. 1 for the exact record;
  /// more where the harness would cost a large share of a fast engine's step (10^5 balls). (steps)
  int sample_every = 1;
  /// A ball touching a wall whose contact point slips slower than this rolls (metrics/slip.h).
  /// Far above the round-off of a float32 engine at the scenes' speeds (~1e-6 m/s), far below a
  /// visible slide. (m/s)
  double roll_tolerance = 1e-3;
};

}  // namespace ballbench

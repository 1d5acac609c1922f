#pragma once
// `home`: our ball solver. Design and the reasons for it: core/solver/README.md.
#include <nlohmann/json.hpp>

#include "engine.h"

namespace ballbench {

struct HomeSettings {
  /// Most Gauss-Seidel sweeps of the contact pass before the drift; it stops early once every
  /// contact is within the velocity tolerance. Too few leaves resting piles to the event loop
  /// (cluster solves); more costs time only where a pile needs it. (count)
  int contact_iterations = 50;
  /// Normal approach speed below which an impact is treated as resting contact (restitution 0).
  /// Negative means 2 |g| dt: slower than two steps of gravity is a ball settling, not a bounce.
  /// Zero gravity gives 0: every impact bounces with the scene's restitution. (m/s)
  double rest_velocity = -1;
  /// Gap below which two balls (or a ball and a wall) count as touching, as a fraction of the
  /// radius sum (or the radius). An approach that closes less than this over a step is round-off,
  /// not motion. (dimensionless)
  double contact_slop = 1e-6;
  /// Safety valve: more events than this per ball in one step is reported as a failure instead of
  /// running on (it would mean an inelastic collapse the contact pass did not resolve). (count)
  int max_events_per_ball = 1000;
};

EngineEntry home_engine();

}  // namespace ballbench

#pragma once
// `exact`: the event-driven reference solver. No time step inside: balls fly on exact parabolas
// between collisions found as polynomial roots; with friction, impacts are those of rough disks and
// a ball on a wall slides and rolls in closed form, and scenes without a closed form are refused.
// Algorithm and the reasons for its rules: core/solver/EXACT.md.
#include <nlohmann/json.hpp>

#include "engine.h"

namespace ballbench {

struct ExactSettings {
  /// Contact duration t_c (the TC model's, Luding & McNamara 1998): a ball held against a support
  /// by gravity leaves each collision with at least the normal speed g_n t_c / 2 (one flight of
  /// t_c) instead of the infinitely many vanishing bounces of hard-sphere dynamics; also the window
  /// of the jam rule. Too large: visible micro-bounces (height g t_c^2 / 8); too small: a resting
  /// ball that is not asleep costs 1 / t_c events per second. Negative: 1e-2 of the scene's time
  /// scale r_min / max(sqrt(|g| r_min), fastest initial speed). Must be > 0 under gravity. (s)
  double contact_time = -1;
  /// Normal impact speed below which a ball is settling, not bouncing: a wall stops its normal
  /// motion (it slides along a wall gravity presses it on), and a ball-ball impact is resolved
  /// with every contact around it as one perfectly inelastic multi-contact impact. Bounce heights
  /// below rest_velocity^2 / 2g are not simulated. Negative: 1e-2 of the scene's speed scale under
  /// gravity, 0 without (no rest rule: every impact honours the restitution). (m/s)
  double rest_velocity = -1;
  /// Put a ball to sleep (fixed, zero velocity) when it is slower than rest_velocity after a slow
  /// impact and the walls and sleeping balls it touches (or a group of slow balls resting on one
  /// another and on them) carry its weight. Without sleep, a settled pile keeps micro-bouncing.
  bool sleep = true;
  /// Normal impact speed at or above which a sleeping ball wakes (with every sleeping ball resting
  /// on it) and takes part as a free ball; a slower impact meets it as a fixed obstacle (the pile
  /// under it takes the impulse). Negative: 10 rest_velocity. (m/s)
  double wake_velocity = -1;
  /// Gap within which a wall or a sleeping ball counts as carrying a ball's weight. Negative:
  /// max(rest_velocity^2 / |g|, 1e-9 r_min), twice the highest bounce the rest rule ignores. (m)
  double support_gap = -1;
  /// Width of the cells of the neighbour grid; at least the largest diameter. Negative: the
  /// largest diameter, grown so that there are at most about 4 cells per ball. (m)
  double cell_size = -1;
  /// Safety valve: one ball taking part in more events than this within one step is reported as a
  /// failure (an inelastic collapse the rules above did not resolve) instead of running on. (count)
  int max_events_per_ball = 100000;
};

EngineEntry exact_engine();

}  // namespace ballbench

#pragma once
// `chipmunk`: Chipmunk2D 7.0.3 (Debian's libchipmunk, double precision, a debug build) driven
// through the Engine interface. The scene mapping, the two profiles and where each setting comes
// from: adapters/chipmunk/README.md.
#include <string>

#include "engine.h"
#include "scene.h"

namespace ballbench {

// Every run-time knob of a cpSpace that can change a ball's trajectory. Some of the profiles'
// values depend on the scene (the hash cell, the slop), so chipmunk_profile() takes it.
// ChipmunkSettings::spatial_index: "bbtree", "hash" in the settings.
enum class SpatialIndex { bbtree, hash };

struct ChipmunkSettings {
  /// Sequential-impulse sweeps over all contacts per step (cpSpaceSetIterations). (count)
  int iterations = 10;
  /// Overlap the solver leaves alone (cpSpaceSetCollisionSlop): only the depth beyond it is pushed
  /// apart. (m)
  double collision_slop = 0.1;
  /// Fraction of the overlap beyond the slop left unfixed after one second
  /// (cpSpaceSetCollisionBias); per step 1 - bias^dt of it is removed, by a separate bias velocity
  /// that moves positions but is never kept in the ball's velocity. (1)
  double collision_bias = 0.0017970074436457143;
  /// Steps a contact's cached impulse is kept after the shapes stop touching
  /// (cpSpaceSetCollisionPersistence). (count)
  int collision_persistence = 3;
  /// Radius of the four wall segments (m). Each is set back by it, so the surface a ball touches
  /// stays on the container's bound; 0 gives lines on the bounds. A ball whose centre crosses a
  /// segment's middle is pushed out on the far side, so a thin wall is a hole for a fast ball, not
  /// the solid side of the scene's box. Negative: max(1 m, half the container's larger side), as
  /// thick as the Box2D adapter's walls.
  double wall_radius = -1.0;
  /// Broad phase: "bbtree" (Chipmunk's default axis-aligned bounding box tree) or "hash"
  /// (cpSpaceUseSpatialHash with hash_cell and hash_count).
  SpatialIndex spatial_index = SpatialIndex::bbtree;
  /// Spatial hash cell edge (m); used only with spatial_index = "hash".
  double hash_cell = 0.5;
  /// Suggested minimum number of hash cells (Chipmunk rounds it up to a prime); used only with
  /// spatial_index = "hash". (count)
  int hash_count = 1000;
  /// Let groups of bodies that stay idle for sleep_time_threshold freeze until something hits them.
  /// Chipmunk's default is off (threshold INFINITY); a benchmark keeps it off.
  bool allow_sleep = false;
  /// Idle time before a group falls asleep (cpSpaceSetSleepTimeThreshold); used only with
  /// allow_sleep. (s)
  double sleep_time_threshold = 0.5;
  /// Speed below which a body counts as idle (cpSpaceSetIdleSpeedThreshold); 0 lets Chipmunk
  /// derive it from gravity (|g| dt). Used only with allow_sleep. (m/s)
  double idle_speed_threshold = 0.0;
};

// The settings of a named profile ("tuned" or "stock") for `scene`; InputError for any other name.
// Stock's values are read from a freshly created cpSpace, so they are Chipmunk's own defaults.
ChipmunkSettings chipmunk_profile(const std::string& profile, const Scene& scene);

EngineEntry chipmunk_engine();

}  // namespace ballbench

#pragma once
// `box2d`: Box2D 2.4.1 (Debian's libbox2d) driven through the Engine interface. The scene mapping,
// the two profiles and where each setting comes from: adapters/box2d/README.md.
#include <string>

#include "engine.h"

namespace ballbench {

// Box2dSettings::fixed_rotation: "auto", "always", "never" in the settings.
enum class FixedRotation { automatic, always, never };

// Every run-time knob of Box2D 2.4.1 that can change a ball's trajectory. The defaults are the
// "tuned" profile; box2d_profile() gives each profile's values.
struct Box2dSettings {
  /// Sequential-impulse sweeps over all contacts per step (b2World::Step's velocityIterations).
  /// Too few leaves piles of touching balls with unresolved approach speed; more costs time. (count)
  int velocity_iterations = 10;
  /// Non-linear Gauss-Seidel sweeps that push overlapping shapes apart per step
  /// (positionIterations). Only positions change; velocities are untouched. (count)
  int position_iterations = 8;
  /// Approach speed below which a contact gets no restitution (b2FixtureDef::restitutionThreshold,
  /// set on every fixture; a contact uses the smaller of its two). Box2D's default 1 m/s stops
  /// resting bodies jittering but makes slow impacts perfectly inelastic. (m/s)
  double restitution_threshold = 0.0;
  /// Treat the balls as bullets: continuous collision (time of impact) against other dynamic
  /// bodies too, not only against the static walls. Costs a TOI query per ball pair per step.
  bool bullet = true;
  /// Let bodies that stay slow for b2_timeToSleep (0.5 s) freeze until something hits them.
  /// Box2D's default is true; a benchmark keeps it off so a slow ball is never frozen.
  bool allow_sleep = false;
  /// "auto": fixed rotation exactly when the scene is frictionless (a frictionless ball never
  /// spins, so its rotation is noise); "always" or "never" force it.
  FixedRotation fixed_rotation = FixedRotation::automatic;
  /// Start each step's solve from the previous step's contact impulses (b2World::SetWarmStarting).
  bool warm_starting = true;
  /// Time-of-impact handling at all (b2World::SetContinuousPhysics); off, even walls can be
  /// tunnelled through.
  bool continuous_physics = true;
  /// The testbed's debugging aid (b2World::SetSubStepping): at most one time-of-impact event is
  /// resolved per Step call, the rest are left to later calls.
  bool sub_stepping = false;
};

// The settings of a named profile ("tuned" or "stock"); InputError for any other name.
Box2dSettings box2d_profile(const std::string& profile);

EngineEntry box2d_engine();

}  // namespace ballbench

#pragma once
// `bullet`: Bullet Physics 3.x (the single-precision build), its 3D rigid-body world held to the
// XY plane. Scene mapping, profiles and the limits that shape its results: adapters/bullet/README.md.
#include <string>

#include <nlohmann/json.hpp>

#include "engine.h"

namespace ballbench {

// Every knob the adapter sets in Bullet, with Bullet's own default (the "stock" profile). Lengths
// given in "radii" are multiples of each ball's radius, so one setting fits scenes of any scale.
struct BulletSettings {
  /// Sequential-impulse sweeps per step (btContactSolverInfo::m_numIterations). Too few leaves
  /// contacts in a pile unresolved; more costs time per step. (count)
  int solver_iterations = 10;
  /// Internal steps per harness step: stepSimulation(dt, substeps, dt / substeps), Bullet's own
  /// sub-stepping (fixed internal step, no interpolation since dt is a whole number of them). (count)
  int substeps = 1;
  /// Split impulse (m_splitImpulse): penetration is removed by a separate "push" velocity that is
  /// thrown away after the position update, so position correction adds no kinetic energy.
  bool split_impulse = true;
  /// Penetration (a negative distance) deeper than this uses split impulse; shallower contacts fold
  /// the Baumgarte correction into the velocity, which adds kinetic energy. Bullet's -0.04 means
  /// "only deeper than 4 cm"; 0 splits every penetrating contact. (m)
  double split_impulse_penetration_threshold = -0.04;
  /// Baumgarte factor for contacts solved without split impulse (m_erp). (fraction per step)
  double erp = 0.2;
  /// Baumgarte factor of the split-impulse push (m_erp2). (fraction per step)
  double erp2 = 0.2;
  /// Normal approach speed below which Bullet gives a contact zero restitution
  /// (m_restitutionVelocityThreshold). Non-zero means slow impacts do not bounce. (m/s)
  double restitution_velocity_threshold = 0.2;
  /// Fraction of last step's contact impulse applied before iterating (m_warmstartingFactor). (-)
  double warmstarting_factor = 0.85;
  /// Penetration the solver leaves uncorrected (m_linearSlop). (m)
  double linear_slop = 0.0;
  /// Contacts farther apart than this are not solved (btCollisionObject::
  /// setContactProcessingThreshold, on every body; the pair uses the smaller). Bullet's default is
  /// BT_LARGE_FLOAT: every contact point the narrow phase keeps (separation up to the contact
  /// breaking threshold) is solved, with restitution, before the bodies touch. (m)
  double contact_processing_threshold = 1e18;
  /// CCD motion clamping starts when a ball would move more than this in one step
  /// (setCcdMotionThreshold); 0 turns CCD off. (radii)
  double ccd_motion_threshold = 0.0;
  /// Radius of the sphere swept for CCD (setCcdSweptSphereRadius): a core inside the ball, so a
  /// clamped ball may still penetrate by (1 - this) radii. (radii)
  double ccd_swept_sphere_radius = 0.0;
  /// Apply restitution to CCD's predictive contacts after the step
  /// (btDiscreteDynamicsWorld::setApplySpeculativeContactRestitution); Bullet gives them zero
  /// restitution otherwise.
  bool speculative_contact_restitution = false;
};

// The settings of a named profile ("tuned", "stock"); throws InputError for an unknown name.
BulletSettings bullet_profile(const std::string& profile);

EngineEntry bullet_engine();

}  // namespace ballbench

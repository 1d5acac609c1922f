#pragma once
// The soft step: `home`'s contact solve for scenes with gravity, where balls rest on each other.
//
// Catto's soft step (E. Catto, "Solver2D", 2024; the solver of Box2D v3): the step is cut into
// substeps; each substep integrates the velocities, re-applies the accumulated impulses (warm
// start), solves every contact once with a soft constraint that pushes an overlap out at a bounded
// speed, integrates the positions, then relaxes (solves again without the push, so the push moves
// positions but leaves no velocity behind). Restitution is applied once after the last substep,
// from each contact's approach speed at the start of the step. Contact normals are fixed for the
// step and the separation is tracked from the balls' displacements, so a contact that is not yet
// touching is speculative (it may close its gap, not more: Catto, "Speculative Contacts", 2013).
// With friction each contact also solves a tangential impulse after its normal one, clamped to the
// friction cone |Jt| <= mu Jn (Coulomb's law as sequential impulses: Catto, GDC 2005), in the
// substeps and in the relax sweeps, warm started as the normal one is; the tangent is
// (-n_y, n_x) and the slip as in rough_impact.h.
//
// Plain data in, plain data out: the balls as arrays, the contacts as a vector; no grid, no state
// of its own. The caller finds the contacts (every pair and wall that can touch within the step).
#include <vector>

#include "solver/contact.h"

namespace ballbench {

// A contact (contact.h) whose normal is fixed for the step; its impulse is one substep's, and in:
// the warm start.
struct SoftContact : Contact {
  double gap;          // separation at the start of the step (m); negative when overlapping
  double vn0;          // relative normal velocity at the start of the step (m/s); < 0 approaching
  double max_impulse;  // the largest the impulse was during the step: restitution only where it pushed
  double tangent_impulse = 0;  // friction's, one substep's as the normal impulse is (N s)
  double tangent_mass = 0;     // effective mass along the tangent (rough_impact.h; kg); friction only
};

struct SoftStepSettings {
  int substeps = 4;            // (count)
  int substep_iterations = 1;  // sweeps over the contacts with the push, per substep
  int relax_iterations = 1;    // sweeps without the push, per substep
  double contact_hertz = 100;  // stiffness of the push-out (Hz); at most a quarter of the substep rate is used
  double damping_ratio = 10;   // of the push-out: heavily damped, so a push does not ring
  double push_speed = 3;       // fastest an overlap is pushed out (m/s)
};

// The scene's restitution and the approach speed below which a contact does not bounce (m/s).
struct Restitution {
  double e = 1;
  double threshold = 1;
};

// Arrays of n balls, structure of arrays; inv_mass may be null (then every ball has inv_mass0). A
// ball of inverse mass 0 is held still: no gravity, no impulse moves it.
struct SoftBodies {
  double* x;
  double* y;
  double* vx;
  double* vy;
  const double* inv_mass;
  double inv_mass0;
  // The balls that move, if not all: the others have inverse mass 0 (inv_mass given) and zero
  // velocity, and the step does not touch them.
  const int* moving = nullptr;
  int moving_count = 0;
  // Friction (mu > 0): angular velocities (rad/s) and angles (rad), counter-clockwise, the radii
  // (null: every ball has r0) and the inertia factor k (I = k m r^2). Angles alone (mu = 0, w
  // given): spins are kept and the angles turn.
  double* w = nullptr;
  double* angle = nullptr;
  const double* radius = nullptr;
  double r0 = 0, k = 0.5, mu = 0;
};

// Scratch the step reuses between calls (no allocation once warm).
struct SoftStepScratch {
  // A ball's velocity (m/s) and displacement since the start of the step (m), during the step.
  struct Motion {
    double vx, vy, dx, dy;
  };
  std::vector<Motion> motion;
};

// Advances the balls by dt under gravity (gx, gy), solving `contacts`; their impulses are left
// as the warm start for the next step.
void soft_step(const SoftBodies& b, int n, std::vector<SoftContact>& contacts, double gx, double gy, double dt,
               const SoftStepSettings& s, Restitution restitution, SoftStepScratch& scratch);

}  // namespace ballbench

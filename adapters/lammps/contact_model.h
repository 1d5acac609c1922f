#pragma once
// The soft-sphere contact parameters the LAMMPS adapter derives from a scene: the normal stiffness
// that keeps the largest expected overlap at a target, the damping that gives the scene's
// restitution, the contact time and the DEM step it sets. Formulas and sources:
// adapters/lammps/README.md ("Stiffness, damping and the DEM step").
#include <string>

#include "scene.h"

namespace ballbench::lammps {

enum class ContactLaw {
  hooke,  // pair gran/hooke: F = kn d - meff gn dd/dt (linear spring-dashpot)
  hertz,  // pair gran/hertz/history: F = sqrt(R d) (kn d - meff gn dd/dt)
};

// What the derivation needs besides the scene.
struct ContactInputs {
  ContactLaw law = ContactLaw::hooke;
  double overlap_target = 0.005;  // largest overlap, as a fraction of the smallest radius
  double impact_speed = -1;       // the largest ball speed expected (m/s); <= 0: from the scene
  double contact_steps = 50;      // DEM steps per contact time
};

// One kind of contact (ball-ball or ball-wall) as designed: the worst case of the scene.
struct ContactDesign {
  double meff = 0;         // reduced mass designed for (kg)
  double radius = 0;       // effective radius R (m): r/2 for two balls, r at a wall
  double approach = 0;     // approach speed designed for (m/s)
  double kn = 0;           // LAMMPS Kn: N/m (hooke), N/m^2 (hertz)
  double gamma_n = 0;      // LAMMPS gamma_n: 1/s (hooke), 1/(m s) (hertz)
  double contact_time = 0; // duration of that contact (s)
};

struct ContactModel {
  ContactLaw law = ContactLaw::hooke;
  double ball_speed = 0;   // the largest ball speed expected (m/s)
  double overlap = 0;      // the target overlap (m)
  ContactDesign pair, wall;
  double contact_time = 0; // the shortest contact of the scene, lightest balls included (s)
  double dem_dt_max = 0;   // contact_time / contact_steps (s)
  // The same springs met by the lightest balls (where the masses differ): shorter, and, as LAMMPS
  // damps per unit of reduced mass, with another restitution (e_light_pair, e_light_wall).
  ContactDesign light_pair, light_wall;
  double e_light_pair = 0, e_light_wall = 0;
  // Hertz only: the dimensionless damping g = gamma_n d*^(3/2) sqrt(R) / v the bisection found
  // (both contacts share it), and the restitution of one contact integrated with it.
  double hertz_damping = 0, hertz_restitution = 0;
};

// The largest ball speed a scene is expected to reach: sqrt(max |v0|^2 + 2 |g| h), h the largest
// drop inside the container along gravity (open space: |v0| + |g| T over the scene's duration T).
// At least 0.01 m/s, so that a scene at rest still gets a finite stiffness.
double expected_ball_speed(const Scene& scene);

// The contact parameters for `scene`. Throws SceneUnsupported where the law cannot give the
// scene's restitution (hertz with e = 0: no finite damping stops a viscoelastic contact).
ContactModel derive_contact_model(const Scene& scene, const ContactInputs& in);

// One head-on Hertz contact in the units of its undamped largest overlap d* and d*/v:
// x'' = -(5/4) x^(3/2) - g sqrt(x) x', x(0) = 0, x'(0) = 1, until x returns to 0. Returns the
// restitution -x'(end) and writes the contact's duration (in units of d*/v) to `duration`.
double hertz_restitution(double g, double* duration = nullptr);

const char* law_name(ContactLaw law);

}  // namespace ballbench::lammps

#pragma once
// `ode`: the Open Dynamics Engine (0.16, double precision) on a ballbench scene. Each ball is a
// dynamic body with a sphere geom held to the z = 0 plane by a Plane2D joint; a box container is
// four static half-spaces. Profiles and every setting are documented in adapters/ode/README.md.
#include <string>

#include "engine.h"

namespace ballbench {

// Every knob of the adapter. Defaults here are the "tuned" profile; see ode_settings_for_profile.
// OdeSettings::stepper and space: "step", "quickstep" and "sap", "hash" in the settings.
enum class OdeStepper { step, quickstep };
enum class OdeSpace { sap, hash };

struct OdeSettings {
  // "step": dWorldStep, the exact ("big matrix", Dantzig LCP) solver, O(m^3) in constraint rows m;
  // "quickstep": dWorldQuickStep, iterative SOR/PGS, O(m N), less accurate.
  OdeStepper stepper = OdeStepper::step;
  // Broad phase. "sap": dSweepAndPruneSpace, sorted along x, then y, z last (the plane's normal):
  // O(n log n). "hash": dHashSpace, whose cell hash (level*1000 + 100 x + 10 y + z, ODE 0.16's
  // collision_space.cpp) sends many cells of a plane larger than ~10 cells to one bucket and which
  // clears an n x n bit table every step, so its cost per ball grows with n (measured 49 us per
  // ball-step at 10^4 balls against 3.7 at 10^3).
  OdeSpace space = OdeSpace::sap;
  int quickstep_iterations = 20;  // dWorldSetQuickStepNumIterations (ODE default 20); quickstep only
  double quickstep_w = 1.3;       // SOR over-relaxation, dWorldSetQuickStepW (ODE default 1.3)
  // Error reduction parameter: fraction of the penetration removed per step (dimensionless). The
  // removal is a velocity erp * depth / dt pushed into the contact, i.e. energy put in.
  double erp = 0.2;
  // Constraint force mixing (m/N per s): softness. 0 = hard; larger lets contacts sink and absorb.
  double cfm = 1e-10;
  // Minimum approach speed (m/s) for dContactBounce to apply; slower contacts get restitution 0
  // (only the ERP push-out remains).
  double bounce_vel = 0.0;
  // Penetration (m) tolerated before ERP correction starts (dWorldSetContactSurfaceLayer).
  double contact_surface_layer = 0.001;
  // Cap on the ERP push-out speed (m/s), dWorldSetContactMaxCorrectingVel; -1 = no cap (ODE's
  // default dInfinity). It never caps the bounce itself.
  double max_correcting_vel = 1.0;
  // After each step, reset each body's rotation to one about z and its angular velocity to
  // (0, 0, wz), as the ODE wiki's "HOWTO constrain objects to 2d" recommends (Plane2D does not
  // correct rotational drift). Position z and velocity z are never touched: out_of_plane() reports
  // them as the engine leaves them.
  bool align_to_plane = true;
};

// The settings of a named profile ("tuned" or "stock"); InputError for any other name.
OdeSettings ode_settings_for_profile(const std::string& profile);

EngineEntry ode_engine();

}  // namespace ballbench

#pragma once
// The closed-form checks every engine is held to: free fall, bounces with restitution, head-on and
// oblique two-ball impacts, a ball sliding to roll and a spinning ball dropped (friction and
// inertia), no ball leaving a box of fast balls, an elastic gas's energy. `ballbench conform` runs
// them on any engine, built in or from an engines file, with one tolerance per case;
// tests/test_conformance.cpp holds every built-in engine to a table of its own measured figures.
#include <span>
#include <string>

#include "engine.h"

namespace ballbench {

enum class ConformCase {
  wall_bounce_elastic,
  wall_bounce_lossy,
  head_on,
  drop,
  seed_box_contained,
  gas_energy,
  slide_to_roll_disk,
  slide_to_roll_sphere,
  spin_drop_sliding,
  spin_drop_sticking,
  oblique_sticking,
  oblique_sliding,
};

struct ConformCaseDef {
  ConformCase c;
  const char* name;        // as the tests name it: "WallBounceElastic"
  const char* key;         // as the command prints it: "wall-bounce-elastic"
  const char* closed_form; // what the figure is measured against, in a line
  // The command's tolerance: any engine that computes the case right meets it, in float or double
  // (a count for seed-box, a relative error for the others).
  double tolerance;
  // The handshake's capability the case tests (Capabilities), or "": an engine that claims it and
  // misses the case by `refutes` or more has the claim refuted.
  const char* capability;
  double refutes;
};

// Every case, in the order they run.
std::span<const ConformCaseDef> conform_cases();
const ConformCaseDef& conform_case(ConformCase c);
bool is_friction_case(ConformCase c);

// The case's figure for `engine` in `profile`: its error against the closed form; infinite where
// a run of it fails. An engine without friction passes a friction case by refusing its scene
// (figure 0); one that refuses a case's scene otherwise throws SceneUnsupported with its reason.
double conform_figure(const EngineEntry& engine, const std::string& profile, ConformCase c);

// The friction coefficient and inertia factor an engine applies, measured on slide-to-roll (a ball
// of radius 0.25 sliding on the floor at v0 = 3 m/s, friction 0.5, g 9.81) run to its end on `e`
// (the scene's inertia set by the caller): while it slides, friction slows it at mu g (from the
// speeds after steps 3 and 13: 0.03 and 0.13 s, before it rolls at 0.17 or 0.20 s); rolling, it
// keeps v0 / (1 + k), so k = v0 / v_final - 1.
struct SlideMeasure {
  double mu, k;
};
SlideMeasure measure_slide(Engine& e, const Scene& s);

// Whether `caps` claims the capability `name` ("friction", "any_restitution", "gravity").
bool claims(const Capabilities& caps, const std::string& name);

}  // namespace ballbench

#pragma once
// How `home` runs a scene when its profile leaves the choice to it (the default profile): the
// event-driven path where nothing rests on anything (no gravity, no box to pile in, or a single
// ball), and the soft step where balls pile up, with its stiffness and substeps derived from the overlap the
// scene's accuracy spec allows (accuracy_spec.h).
#include <string>

namespace ballbench {

struct Scene;

struct HomeMethod {
  bool soft = false;        // the soft step; else the event-driven path
  int substeps = 0;         // the soft step's (soft only)
  double contact_hertz = 0;  // its contact stiffness (Hz; soft only)
};

// Two things press a pile's contacts in, and the stiffness is the larger of what each asks:
//
// - The weight of the balls above: a spring of frequency f under the weight of L balls sinks by
//   about L g / (2 pi f)^2 (per unit mass, both balls of a pair giving way). A settling pile squeezes
//   its rows sideways as well, and the factor kSagSafety covers that (measured on `pile-10k`, 100
//   balls deep: 0.64 - 0.75 of the overlap asked at 5%, 2% and 1%).
// - The landing of balls on the pile: the heavily damped push-out stops a landing ball within
//   about a period of the spring, so the overlap it leaves shrinks as 1 / f, not 1 / f^2: about
//   kLandingRate / (2 pi f) of the radius (measured on `pile`, `rough-pile`, `smooth-pile` and
//   `seed-bowl` at 68 - 950 Hz: 5 - 24 /s). On shallow piles and at tight overlaps this term binds.
//
// The substeps are then the fewest that carry the stiffness (the push-out uses at most a quarter of
// the substep rate). core/solver/PERFORMANCE.md, "Choosing the stiffness", has the figures.
inline constexpr double kSagSafety = 60.0;
inline constexpr double kLandingRate = 30.0;  // (1/s)

// The method for `scene` at step dt, for a largest overlap of `overlap` (fraction of the radius).
HomeMethod choose_home_method(const Scene& scene, double dt, double overlap);

// How many balls deep the scene's balls lie once settled in its box: their area, packed at the
// density of a random disc packing, over the box's width, in layers of hexagonal spacing (at least 1).
double settled_layers(const Scene& scene);

}  // namespace ballbench

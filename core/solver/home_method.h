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

// A settled pile's contacts carry the weight of the balls above them: a spring of frequency f under
// the weight of L balls sinks by about L g / (2 pi f)^2 (per unit mass, both balls of a pair
// giving way); the landing of the balls above, through the heavily damped push-out, adds to that,
// and the factor kSagSafety covers both (measured on `pile` and `deep-pile`: core/solver/PERFORMANCE.md,
// "Choosing the stiffness"). The stiffness is then the one that keeps the sag of the deepest
// contact to `overlap` of the radius, and the substeps are the fewest that carry it (the push-out
// uses at most a quarter of the substep rate).
inline constexpr double kSagSafety = 60.0;

// The method for `scene` at step dt, for a largest overlap of `overlap` (fraction of the radius).
HomeMethod choose_home_method(const Scene& scene, double dt, double overlap);

// How many balls deep the scene's balls lie once settled in its box: their area, packed at the
// density of a random disc packing, over the box's width, in layers of hexagonal spacing (at least 1).
double settled_layers(const Scene& scene);

}  // namespace ballbench

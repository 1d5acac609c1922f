#pragma once
// One look per run, the same in every figure, the viewer page and the GIFs: the engine picks the
// colour (colour-blind safe: Okabe-Ito's eight and Paul Tol's muted set), the profile the line
// style, so box2d is one colour everywhere and box2d/stock its dashed twin.
#include <string>

namespace ballbench {

struct RunStyle {
  std::string colour;  // "#rrggbb"
  int dash;            // gnuplot dashtype: 1 solid (the engine's first profile), 2 dashed, 3 dotted, 4 dash-dot, 5 dash-dot-dot
};

inline constexpr int kDashTypes = 5;  // the dashtypes above

// A fixed table for the registry's engines and their profiles; an engine or profile not in it gets
// a colour or dash from a hash of its name, stable across runs and machines.
RunStyle run_style(const std::string& engine, const std::string& profile);

// The colour of the tracks of balls 0, 1, 2, ... in pictures and the viewer: distinct from each other,
// drawn over balls of any engine's colour.
std::string track_colour(int ball);

}  // namespace ballbench

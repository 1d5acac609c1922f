#pragma once
// One look per run, the same in every figure, the viewer page and the GIFs: the engine picks the
// colour (colour-blind safe: Okabe-Ito's eight and Paul Tol's muted set), the profile the line
// style and the marker, so box2d is one colour everywhere and box2d/stock its dashed twin with
// squares, and home, home/events and home/soft three markers of one blue.
#include <string>

namespace ballbench {

struct RunStyle {
  std::string colour;  // "#rrggbb"
  int dash;            // gnuplot dashtype: 1 solid (the engine's first profile), 2 dashed, 3 dotted, 4 dash-dot, 5 dash-dot-dot
  int point = 7;       // gnuplot pointtype, filled: 7 circle, 5 square, 9 triangle, 13 diamond, 11 triangle down
  int open_point() const { return point - 1; }  // the same marker, open (gnuplot's filled types are the open + 1)
};

inline constexpr int kDashTypes = 5;  // the dashtypes above

// A fixed table for the registry's engines and their profiles; an engine or profile not in it gets
// a colour or dash from a hash of its name, stable across runs and machines.
RunStyle run_style(const std::string& engine, const std::string& profile);

// The colour of the tracks of balls 0, 1, 2, ... in pictures and the viewer: distinct from each other,
// drawn over balls of any engine's colour.
std::string track_colour(int ball);

}  // namespace ballbench

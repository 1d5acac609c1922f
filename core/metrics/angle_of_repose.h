#pragma once
// The angle of repose of a heap on the floor, from a state (the final one): the slope of the heap's
// flanks, measured as granular-physics DEM studies measure it, by a straight-line fit to the heap's
// free surface (Zhou, Xu, Yu and Zulli, "Numerical investigation of the angle of repose of
// monosized spheres", Phys. Rev. E 64, 021301, 2001; Lee and Herrmann, "Angle of repose and angle
// of marginal stability: molecular dynamics of granular particles", J. Phys. A 26, 373, 1993, for
// heaps of discs):
// - the surface profile: the floor cut into columns one mean diameter wide from the box's left
//   wall; a column's height is the top (y + r) of the highest ball whose centre lies in it, above
//   the floor (0 for an empty column);
// - the heap's height H is the highest column's; each flank is the run of columns walking outward
//   from that column up to the first column below kReposeBandLow H (or the wall);
// - on each flank, a least-squares line through the column centres whose height lies within
//   [kReposeBandLow H, kReposeBandHigh H] (at least kReposeMinColumns of them): its angle
//   atan |slope|. The band leaves out the rounded top and the toe, where balls rolled out;
// - the angle of repose is the mean over the flanks measured (degrees), none when neither is.
// A heap that spread flat over the floor measures near 0 (its flanks are the layer's ripples).
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "scene.h"
#include "state.h"

namespace ballbench {

inline constexpr double kReposeBandLow = 0.2;   // of H: above the toe, where lone balls rolled out
inline constexpr double kReposeBandHigh = 0.8;  // of H: below the top, rounded over a few balls
inline constexpr int kReposeMinColumns = 3;     // two points always fit a line; three can disagree with it

// How Result::skipped's note begins for a scene that asks for the angle but whose final heap had
// no flank to measure; the report finds such scenes by it.
inline constexpr const char* kReposeUnmeasuredNote = "angle of repose: not measured";

// The surface profile: column k spans [x0 + k width, x0 + (k + 1) width).
struct HeapProfile {
  double x0 = 0, width = 0;
  std::vector<double> height;  // above the floor (m)
};

HeapProfile heap_profile(const State& s, const Eigen::VectorXd& radius, const Container& box);

// Degrees; none when no flank has kReposeMinColumns columns within the band (or nothing is on the floor).
std::optional<double> angle_of_repose(const HeapProfile& profile);
std::optional<double> angle_of_repose(const State& s, const Scene& scene);

}  // namespace ballbench

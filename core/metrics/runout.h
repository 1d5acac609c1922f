#pragma once
// The runout of a heap on the floor, from a state (the final one): how far a collapsed column or
// a slumped block spread, the quantity granular-collapse studies scale with the column's aspect
// ratio (Lube, Huppert, Sparks and Freundt, "Collapses of two-dimensional granular columns", Phys.
// Rev. E 72, 041301, 2005; Staron and Hinch, J. Fluid Mech. 545, 1, 2005, for discs).
// - the balls are taken in order along the floor (by their left edges); a deposit is a run of
//   them in which each ball's left edge lies within kRunoutGap mean diameters of the farthest
//   right edge before it;
// - the heap's deposit is the run that holds the highest ball (its top, y + r);
// - the runout is that deposit's length, from its leftmost edge to its rightmost (m).
// Discs with sliding friction alone roll on (nothing resists rolling): a ball that rolled away
// from the heap, a gap of more than kRunoutGap diameters, is not part of the deposit.
#include <optional>

#include <Eigen/Core>

#include "state.h"

namespace ballbench {

inline constexpr double kRunoutGap = 1.0;  // mean diameters: a gap a ball could not bridge

// None when there are no balls.
std::optional<double> runout(const State& s, const Eigen::VectorXd& radius);

}  // namespace ballbench

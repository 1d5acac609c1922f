#pragma once
// What the stages of one step of home's event path (home_events.h) share: each ball's clock, the
// balls that may have an event, and the step's constants. The broad phase (home_broad_grid.h or
// home_broad_list.h) marks `active` in its screen and sets the clocks back to 0 at the step's end;
// the event loop moves each ball along its line, from event to event, in between.
#include <cstdint>
#include <vector>

#include "solver/home_world.h"

namespace ballbench {

// A ball's first pair event of the step as the broad phase's screen found it: partner j at time t
// (s); j = -1: none; j = kAsk: the screen cannot tell, next_event decides.
inline constexpr int kAsk = -2;
struct FirstPair {
  double t;
  int j;
};

struct EventStep {
  std::vector<double> clock;    // each ball's own time within the step (s): where its position is on its line
  std::vector<uint8_t> active;  // may have an event this step (the screen's marks): only these are predicted at the start
  double dt = 0;                // the step (s)
  double v_rest = 0;            // impacts slower than this are resting contact (m/s)
  double v_tol = 0;             // approach speeds below this are round-off, not motion (m/s)
  double slop = 0;              // contact_slop: touching is a gap below slop x the radius sum

  EventStep(int n, double slop) : clock(n), active(n, 0), slop(slop) {}

  // A gap below this counts as touching: the slop times the radius sum (of a pair, or of a ball
  // alone at a wall). The hot kernels keep the slop in a local and apply the same product.
  double touching_gap(double radius_sum) const { return slop * radius_sum; }

  // Ball i along its line from its clock to time t (s), its angle turned with it.
  void advance(HomeWorld& w, int i, double t) {
    w.p(i, 0) = on_line(w.p(i, 0), w.v(i, 0), t, clock[i]), w.p(i, 1) = on_line(w.p(i, 1), w.v(i, 1), t, clock[i]);
    if (w.rotation) w.angle(i) += w.w(i) * (t - clock[i]);
    clock[i] = t;
  }
};

}  // namespace ballbench

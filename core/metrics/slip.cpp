#include "metrics/slip.h"

#include <algorithm>
#include <cmath>

namespace ballbench {

SlipTracker::SlipTracker(const Scene& scene, double contact_tolerance, double roll_tolerance)
    : scene_(scene),
      contact_tolerance_(contact_tolerance),
      roll_tolerance_(roll_tolerance) {}

void SlipTracker::observe(const State& s) {
  if (!s.rotates()) return;
  const Container& box = scene_.container;
  bool touching = false;
  double worst = 0;
  for (int i = 0; i < s.n(); ++i) {
    const double r = scene_.radius(i), reach = r * (1 + contact_tolerance_);
    const double x = s.pos(i, 0), y = s.pos(i, 1), vx = s.vel(i, 0), vy = s.vel(i, 1), wr = s.w(i) * r;
    // Each wall: its gap, and v . t with t = z x n for its inward normal n.
    const double gap[4] = {x - box.min.x(), box.max.x() - x, y - box.min.y(), box.max.y() - y};
    const double vt[4] = {vy, -vy, -vx, vx};  // n = +x, -x, +y, -y
    for (int k = 0; k < 4; ++k)
      if (gap[k] <= reach) touching = true, worst = std::max(worst, std::abs(vt[k] - wr));
  }
  touched_ = touched_ || touching;
  final_max_ = worst;
  if (worst > roll_tolerance_) rolling_since_.reset();
  else if (!rolling_since_) rolling_since_ = s.t;
}

SlipSummary SlipTracker::summary() const {
  SlipSummary out;
  out.final_max = final_max_;
  if (touched_) out.time_to_roll = rolling_since_;
  return out;
}

}  // namespace ballbench

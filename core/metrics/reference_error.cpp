#include "metrics/reference_error.h"

#include <algorithm>
#include <cmath>

#include "metrics/energy.h"

namespace ballbench {

ReferenceErrorTracker::ReferenceErrorTracker(const Scene& scene)
    : scene_(scene), reference_height_(energy_reference(scene)) {
  m_.available = true;
  m_.horizon_tolerance = 0.1 * scene.radius.mean();
}

void ReferenceErrorTracker::observe(const State& s, const State& ref) {
  const double e_ref = total_energy(ref, scene_, reference_height_);
  if (first_) e0_ = e_ref, first_ = false;
  // Squares of differences beyond ~1e154 overflow: such a state (finite, or the run would have
  // stopped) is measured with Eigen's overflow-safe norm instead, so the error stays a number.
  const auto rms = [](const auto& d) {
    const double plain = std::sqrt(d.rowwise().squaredNorm().mean());
    if (std::isfinite(plain) || !d.allFinite() || d.rows() == 0) return plain;
    return d.stableNorm() / std::sqrt(static_cast<double>(d.rows()));
  };
  const double pos_rms = rms(s.pos - ref.pos);
  const double vel_rms = rms(s.vel - ref.vel);
  m_.pos_rms_final = pos_rms, m_.vel_rms_final = vel_rms;
  m_.pos_rms_max = std::max(m_.pos_rms_max, pos_rms);
  m_.vel_rms_max = std::max(m_.vel_rms_max, vel_rms);
  if (e0_ > 0)
    m_.energy_rel_max = std::max(m_.energy_rel_max, std::abs(total_energy(s, scene_, reference_height_) - e_ref) / e0_);
  if (!m_.horizon && pos_rms > m_.horizon_tolerance) m_.horizon = s.t;
}

void ReferenceErrorTracker::reference_failed(long step, const std::string& why) {
  m_.reference_failed_step = step;
  m_.reference_error = why;
}

HorizonStatus horizon_status(const ReferenceErrorSummary& e) {
  return e.horizon ? HorizonStatus::exceeded : HorizonStatus::within;
}

const char* horizon_status_text(HorizonStatus s) { return s == HorizonStatus::exceeded ? "exceeded" : "within"; }

}  // namespace ballbench

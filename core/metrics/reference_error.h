#pragma once
// Error against the reference: the same scene run by the event-driven `exact` engine in lockstep
// (or, for a scene exact refuses, a converged run: RunOptions::converged_reference), compared at
// every sample. Chaotic scenes diverge from any reference after a while, so besides the
// errors the horizon is reported: the first time the position error exceeds a tolerance.
#include <optional>

#include <Eigen/Core>

#include "scene.h"
#include "state.h"

namespace ballbench {

struct ReferenceErrorSummary {
  bool available = false;               // a reference ran alongside
  std::string reference;                // its engine name ("exact"), or "ENGINE/PROFILE at dt/K" for a converged run
  double reference_dt = 0;              // the reference's step (s)
  double pos_rms_final = 0;             // sqrt(mean_i |x_i - x_i^ref|^2) at the last sample (m)
  double pos_rms_max = 0;               // the largest of the same over samples (m)
  double vel_rms_final = 0, vel_rms_max = 0;  // the same for velocities (m/s)
  double energy_rel_max = 0;            // max |E - E_ref| / E_ref(0) over samples
  std::optional<double> horizon;        // first t with pos_rms > horizon_tolerance (s); none: never
  double horizon_tolerance = 0;         // (m), see ReferenceErrorTracker
  long reference_failed_step = -1;      // the reference itself failed here (compared up to it)
  std::string reference_error;
};

// What a null horizon means is told apart in the results' JSON by "horizon_status": `exceeded` (the
// horizon holds the time), `within` (the error stayed within the tolerance at every sample
// compared: the whole run, or up to reference_failed_step). A run without a reference has no
// "error_vs_reference" at all.
enum class HorizonStatus { exceeded, within };
HorizonStatus horizon_status(const ReferenceErrorSummary& e);
const char* horizon_status_text(HorizonStatus s);

class ReferenceErrorTracker {
 public:
  // The horizon tolerance is a tenth of the mean radius: a ball that far off is visibly elsewhere.
  explicit ReferenceErrorTracker(const Scene& scene);
  void observe(const State& s, const State& ref);
  void reference_failed(long step, const std::string& why);
  const ReferenceErrorSummary& summary() const { return m_; }

 private:
  const Scene& scene_;
  double reference_height_ = 0;
  double e0_ = 0;
  bool first_ = true;
  ReferenceErrorSummary m_;
};

}  // namespace ballbench

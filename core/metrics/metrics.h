#pragma once
// Streams state samples through every metric. Engine-agnostic: it sees states and the scene only.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "metrics/events.h"
#include "metrics/slip.h"
#include "metrics/sticking.h"
#include "metrics/tunnelling.h"
#include "overlap.h"
#include "scene.h"
#include "state.h"
#include "uniform_grid.h"

namespace ballbench {

struct MetricsConfig {
  /// Overlap deeper than this fraction of the radius sum (pairs) or of the radius (walls) counts as
  /// "in contact" for sticking, and a straight-line pass closer than (1 - this) of the radius sum
  /// counts as tunnelling. 2% sits above the rest penetration soft engines allow by design (Box2D's
  /// linear slop, 0.005 m, is 1% of the seed scenes' radius sum of 0.5 m). (dimensionless)
  double contact_tolerance = 0.02;
  /// Consecutive samples a contact may stay deeper than the tolerance before it counts as stuck. A
  /// bounce resolves within one or two steps; 10 steps of 0.01 s is already visibly stuck. (samples)
  int stuck_samples = 10;
  /// Energy above this multiple of the initial energy (plus the initial kinetic energy scale) means
  /// the run has blown up: it is stopped and marked diverged. (dimensionless)
  double divergence_energy_factor = 100.0;
  /// The sampled metrics (energy, momentum, overlaps, sticking, penetration, the error against the
  /// reference, checksums, figure series) see every k-th step and the last; tunnelling and the
  /// finiteness check see every step, since a pass-through lasts a step. 1 for the exact record;
  /// more where the harness would cost a large share of a fast engine's step (10^5 balls). (steps)
  int sample_every = 1;
  /// A ball touching a wall whose contact point slips slower than this rolls (metrics/slip.h).
  /// Far above the round-off of a float32 engine at the scenes' speeds (~1e-6 m/s), far below a
  /// visible slide. (m/s)
  double roll_tolerance = 1e-3;
};

struct EnergySummary {
  double initial = 0, final = 0;
  std::optional<double> max_rel_drift;  // max |E - E0| / E0 over samples; none when E0 = 0
  double max_abs_drift = 0;             // max |E - E0| (J)
  double reference = 0;                 // -g . x_ref (J/kg), see metrics/energy.h
};

struct MomentumSummary {
  Eigen::Vector2d initial{0, 0}, final{0, 0};
  double max_abs_drift = 0;  // max |P - P0| over samples (kg m/s)
};

// Angular momentum about a fixed point, orbital plus spin (metrics/momentum.h).
struct AngularMomentumSummary {
  Eigen::Vector2d centre{0, 0};  // the point it is taken about (m)
  double initial = 0, final = 0;
  double max_abs_drift = 0;      // max |L - L0| over samples (kg m^2/s)
};

struct MetricsSummary {
  EnergySummary energy;
  MomentumSummary momentum;
  AngularMomentumSummary angular_momentum;
  SlipSummary slip;
  int tunnelling_wall = 0, tunnelling_pair = 0;
  int sticking_wall = 0, sticking_pair = 0;
  double penetration_max = 0;   // max overlap depth / radius (pairs: the smaller radius)
  double penetration_mean = 0;  // mean of the same over every overlapping contact in every sample
  // The deepest overlap / radius in the first sample (a placement that starts overlapping), and in
  // every sample after it: what the engine's contacts let balls sink into each other.
  double penetration_initial = 0;
  double penetration_after_start = 0;
  long samples = 0;
};

class MetricsAccumulator {
 public:
  MetricsAccumulator(const Scene& scene, MetricsConfig config);

  // Feeds one sample; the first one is the initial state.
  void observe(const State& s);
  // Feeds one step of motion, from `prev` to `cur` (every step, sampled or not): tunnelling. False
  // when a position, velocity, angular velocity or angle of `cur` is not finite (positions and
  // velocities are checked in the same sweep over the states).
  bool observe_motion(const State& prev, const State& cur);
  // The last observe_motion found a centre beyond the box by more than the largest diameter: a
  // ball has left the container (it fell through a wall, or the scene blew it away).
  bool left_container() const { return left_container_; }
  // The energy of the last sample exceeded the divergence bound.
  bool energy_blew_up() const;
  const MetricsSummary& summary() const { return m_; }
  // The first kEventsKept tunnelling and sticking events, in the order counted (step by step; in a
  // step, wall escapes, pass-throughs, then the sample's stuck balls and pairs). A step is the
  // number of observe_motion() calls so far.
  const std::vector<Event>& events() const { return events_; }

 private:
  const Scene& scene_;
  MetricsConfig cfg_;
  MetricsSummary m_;
  bool left_container_ = false;
  long motion_steps_ = 0;
  std::vector<Event> events_;
  void keep(const Event& e);
  StickingTracker sticking_;
  SlipTracker slip_;
  OverlapScratch overlap_scratch_;
  TunnellingCheck tunnelling_;
  std::vector<Overlap> overlaps_, deep_;
  std::vector<char> deep_in_wall_, wall_leaving_, deep_leaving_;
  double penetration_sum_ = 0;
  long penetration_count_ = 0;
  double ke0_ = 0;
};

}  // namespace ballbench

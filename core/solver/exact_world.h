#pragma once
// exact's world as plain data: the scene's constants and settings in force (ExactModel), the balls
// as structure-of-arrays (ExactBalls: each ball's state is exact at its own clock, brought to any
// later time along its parabola by `advance`), and the list of balls whose course an event changed
// (Repredictions). Every stage of the solver (events, cluster settling, sleeping, friction) reads
// and writes these; none keeps state of its own beyond scratch space.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "scene.h"
#include "solver/contact.h"
#include "solver/exact.h"

namespace ballbench {

// Relative size of round-off in a normal velocity: touching bodies that approach more slowly than
// this fraction of their speeds are not approaching (a collision there would be one of noise).
inline constexpr double kVelocityNoise = 1e-12;
// Under gravity, approach speeds below this fraction of rest_velocity are not an approach now
// either: a cluster of balls settling at restitution 0 would otherwise refine its relative
// velocities towards round-off through thousands of zero-time collisions (the Gauss-Seidel
// iteration of a multi-contact impact, done one binary collision at a time).
inline constexpr double kRestSlop = 1e-2;
// A pair (or ball and wall) closing slower than the noise above may creep into overlap by at most
// this fraction of the radius sum (radius), then collides: the cascade is spread over time.
inline constexpr double kOverlapCap = 1e-9;
// A relative acceleration presses a contact only if its normal part is above this fraction of its
// size: side-by-side balls differ in height by round-off, which must not count as pressing.
inline constexpr double kPressedFraction = 1e-9;
// Gap within which balls (or a ball and a wall) count as touching when a slow impact is settled,
// as a fraction of the radius sum (radius).
inline constexpr double kTouch = 1e-9;
// A slow ball in more collisions than this within contact_time is jammed (is_jammed).
inline constexpr int kJamEvents = 100;

// |(x, y)|: plain sqrt, as every quantity here is far from overflow (std::hypot is several times
// slower for its care about it).
inline double norm2(double x, double y) { return std::sqrt(x * x + y * y); }

// What does not change during a run: the scene's material and container, and the settings in force.
struct ExactModel {
  ExactSettings settings;
  int ball_count = 0;
  double restitution = 0;
  double friction = 0;        // Coulomb coefficient, ball-ball and ball-wall
  double inertia_factor = 0;  // k: I = k m r^2
  double gravity[2] = {0, 0};
  bool has_gravity = false;
  bool has_walls = false;
  double box_lo[2] = {0, 0}, box_hi[2] = {0, 0};
  bool rotation = false;     // the scene's balls turn
  bool rough_walls = false;  // friction under gravity in a box: a ball on a wall slides, then rolls
  double contact_time = 0, rest_velocity = 0, wake_velocity = 0, support_gap = 0;

  ExactModel(const Scene& scene, const ExactSettings& s);
};

// The balls, structure of arrays. Position, velocity, acceleration, angle, angular velocity and its
// rate are exact at the ball's own clock.
struct ExactBalls {
  std::vector<double> radius, inv_mass;     // (m), 1 / mass (1/kg)
  std::vector<double> pos[2], vel[2], acc[2];  // (m), (m/s), (m/s^2) at clock
  std::vector<double> clock;                // the time each ball was last brought to (s)
  std::vector<uint32_t> course;             // trajectory changes so far, to recognise stale predictions
  std::vector<uint8_t> asleep;
  std::vector<int> step_events;             // events this step, against max_events_per_ball
  std::vector<double> jam_window_start;     // start of each ball's current window of contact_time (s)
  std::vector<int> jam_events;              // its events in that window
  // Rotation, only for a scene that rotates; sliding and rolling, only with rough walls.
  std::vector<double> spin, angle, spin_rate;  // (rad/s), (rad), (rad/s^2) at clock
  std::vector<int8_t> slip_sign;            // sliding on a wall: the sign of the slip; 0: rolling (or not on a wall)
  std::vector<uint8_t> held_axes;           // bit k: held on the wall of axis k that gravity presses it against

  ExactBalls(const Scene& scene, const ExactModel& model);
  int size() const { return static_cast<int>(radius.size()); }
  double speed(int i) const { return norm2(vel[0][i], vel[1][i]); }

  // Brings ball i along its parabola to time t (lazily: each ball keeps its own clock), and its
  // angle with it: the spin changes at the constant spin_rate (friction while sliding on a wall,
  // the rolling constraint while rolling), 0 in flight.
  void advance(int i, double t, bool rotation) {
    const double h = t - clock[i];
    if (h != 0) {
      for (int k = 0; k < 2; ++k) {
        pos[k][i] += (vel[k][i] + 0.5 * acc[k][i] * h) * h;
        vel[k][i] += acc[k][i] * h;
      }
      if (rotation) {
        angle[i] += (spin[i] + 0.5 * spin_rate[i] * h) * h;
        spin[i] += spin_rate[i] * h;
      }
    }
    clock[i] = t;
  }

  // Jammed: a ball in more than kJamEvents collisions within t_c. Contacts that resolve this
  // badly are a wedge, an arch or a column clamped between supports (nearly opposite contact
  // normals, where the impulses that hold a ball are many times its momentum, and a micro-bounce
  // has no room): the ball is held there, and is put to sleep.
  bool is_jammed(int i) const { return jam_events[i] > kJamEvents; }
};

// The balls an event changed: each predicts its next event once the event is processed.
struct Repredictions {
  std::vector<int> pending;
  std::vector<uint32_t> listed_in;  // the round each ball was last listed in
  uint32_t round = 1;

  explicit Repredictions(int n) : listed_in(n, 0) {}
  // Ball k's event was used up: list it (once).
  void add(int k) {
    if (listed_in[k] != round) {
      listed_in[k] = round;
      pending.push_back(k);
    }
  }
  // Ball k's trajectory changed: every prediction made against it is stale, and it predicts anew.
  void changed_course(ExactBalls& balls, int k) {
    ++balls.course[k];
    add(k);
  }
};

// Normal speeds up to this count as zero for bodies moving at `speeds` (the sum of their speeds).
inline double velocity_noise(const ExactModel& m, double speeds) {
  return std::max(kVelocityNoise * speeds, kRestSlop * m.rest_velocity);
}

// Does relative acceleration (Ax, Ay), with normal part `press` into the contact (m/s^2), hold a
// touching pair together? Then a collision cannot leave them separating at restitution 0, only
// at the TC micro-bounce speed press t_c / 2 (one flight of t_c: Luding & McNamara's contact
// duration) instead of the infinitely many vanishing bounces of a body held against a support.
// Pressing too weak for that speed to stand out of round-off (`fine`), or a tilt of side-by-side
// balls, does not count.
inline bool pressed(const ExactModel& m, double press, double Ax, double Ay, double fine) {
  return press > kPressedFraction * norm2(Ax, Ay) && 0.5 * press * m.contact_time > 4 * fine;
}

// A ball sliding on a wall (axis k held: a_k = 0 though g_k != 0) was struck. Struck away from
// the wall it flies again; struck into it faster than rest_velocity it is freed, and the wall
// event due now bounces it; otherwise the wall absorbs the normal part (the rest rule, applied
// here rather than by a zero-time wall event) and it keeps sliding.
inline void after_impulse(const ExactModel& m, ExactBalls& balls, int i) {
  const double noise = velocity_noise(m, balls.speed(i));
  for (int k = 0; k < 2; ++k) {
    if (balls.acc[k][i] != 0 || m.gravity[k] == 0) continue;
    const double away = m.gravity[k] < 0 ? balls.vel[k][i] : -balls.vel[k][i];  // normal velocity off the wall
    if (away > noise || away < -m.rest_velocity) balls.acc[k][i] = m.gravity[k];
    else balls.vel[k][i] = 0;
  }
}

}  // namespace ballbench

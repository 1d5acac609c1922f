#include "lammps/contact_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "engine.h"

namespace ballbench::lammps {
namespace {

constexpr double kPi = std::numbers::pi;

// Linear spring-dashpot, m x'' = -kn x - m gn x' (LAMMPS gran/hooke; its force is not cut off when
// it turns attractive, so the contact ends where the overlap returns to 0, after half a damped
// period). With b = -ln e: zeta = b / sqrt(pi^2 + b^2), gn = 2 zeta w0, w0 = sqrt(kn / m), and
// e = exp(-zeta pi / sqrt(1 - zeta^2)) (Schwager and Poeschel 2007; LAMMPS pair gran docs; Silbert
// et al. 2001). The undamped overlap peak v / w0 is the target, so kn = m v^2 / d^2.
ContactDesign hooke_contact(double meff, double radius, double approach, double overlap, double e) {
  ContactDesign c{meff, radius, approach};
  c.kn = meff * approach * approach / (overlap * overlap);
  const double w0 = approach / overlap;  // sqrt(kn / meff)
  const double b = e >= 1 ? 0.0 : e <= 0 ? HUGE_VAL : -std::log(e);
  const double zeta = std::isinf(b) ? 1.0 : b / std::sqrt(kPi * kPi + b * b);
  c.gamma_n = 2 * zeta * w0;
  // Critically damped (e = 0) has no end: the undamped half period sets the step instead.
  c.contact_time = zeta < 1 ? kPi / (w0 * std::sqrt(1 - zeta * zeta)) : kPi / w0;
  return c;
}

// Hertz with LAMMPS's damping, m x'' = -sqrt(R x) (kn x + m gn x'): the undamped overlap peak d*
// satisfies m v^2 / 2 = (2/5) kn sqrt(R) d*^(5/2), so kn = 5 m v^2 / (4 sqrt(R) d*^(5/2)); in units
// of d* and d*/v the contact depends on g = gn d*^(3/2) sqrt(R) / v alone (hertz_restitution).
ContactDesign hertz_contact(double meff, double radius, double approach, double overlap, double g) {
  ContactDesign c{meff, radius, approach};
  c.kn = 5 * meff * approach * approach / (4 * std::sqrt(radius) * std::pow(overlap, 2.5));
  c.gamma_n = g * approach / (std::pow(overlap, 1.5) * std::sqrt(radius));
  double duration = 0;
  hertz_restitution(g, &duration);
  c.contact_time = duration * overlap / approach;
  return c;
}

// The contact `designed` makes (its kn and gamma_n, radius and approach speed) for a ball of
// another reduced mass `meff`: its duration, and its restitution in `e`. Hooke: w0 = sqrt(kn / m),
// zeta = gn / (2 w0). Hertz: d* from m v^2 / 2 = (2/5) kn sqrt(R) d*^(5/2), then g as above.
ContactDesign same_springs(const ContactDesign& designed, ContactLaw law, double meff, double* e) {
  ContactDesign c = designed;
  c.meff = meff;
  if (law == ContactLaw::hooke) {
    const double w0 = std::sqrt(c.kn / meff), zeta = c.gamma_n / (2 * w0);
    c.contact_time = zeta < 1 ? kPi / (w0 * std::sqrt(1 - zeta * zeta)) : kPi / w0;
    *e = zeta < 1 ? std::exp(-zeta * kPi / std::sqrt(1 - zeta * zeta)) : 0.0;
  } else {
    const double peak =
        std::pow(5 * meff * c.approach * c.approach / (4 * c.kn * std::sqrt(c.radius)), 0.4);  // d*
    const double g = c.gamma_n * std::pow(peak, 1.5) * std::sqrt(c.radius) / c.approach;
    double duration = 0;
    *e = hertz_restitution(g, &duration);
    c.contact_time = duration * peak / c.approach;
  }
  return c;
}

// The g that gives restitution e, by bisection: e falls monotonically from 1 at g = 0.
double hertz_damping_for(double e) {
  if (e >= 1) return 0;
  double lo = 0, hi = 1;
  while (hertz_restitution(hi) > e) {
    lo = hi, hi *= 2;
    if (hi > 1e6)
      throw SceneUnsupported(fmt::format(
          "lammps (hertz): restitution {} needs a damping past any the contact can end with (the viscoelastic "
          "contact's restitution only tends to 0); use the hooke profile",
          e));
  }
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

const char* law_name(ContactLaw law) { return law == ContactLaw::hooke ? "hooke" : "hertz"; }

double expected_ball_speed(const Scene& scene) {
  double v0sq = 0;
  for (int i = 0; i < scene.n(); ++i) v0sq = std::max(v0sq, scene.initial.vel.row(i).squaredNorm());
  const double g = scene.gravity.norm();
  double v = std::sqrt(v0sq);
  if (g > 0 && scene.container.kind == ContainerKind::Box) {
    const Eigen::Vector2d extent = scene.container.max - scene.container.min, down = scene.gravity / g;
    const double drop = std::abs(extent.x() * down.x()) + std::abs(extent.y() * down.y());
    v = std::sqrt(v0sq + 2 * g * drop);
  } else if (g > 0) {
    v += g * scene.duration;
  }
  return std::max(v, 0.01);
}

// Classic fourth-order Runge-Kutta at a step of 1e-4 d*/v (about 30 000 steps for an undamped
// contact), the overlap's return to 0 found by linear interpolation within the last step. sqrt(x)
// is taken of max(x, 0), as the intermediate stages of the last step may overshoot below 0.
double hertz_restitution(double g, double* duration) {
  constexpr double ds = 1e-4, s_max = 200;  // past s_max an overdamped contact is taken as ended at rest
  auto accel = [g](double x, double v) {
    const double r = std::sqrt(std::max(x, 0.0));
    return -1.25 * x * r - g * r * v;
  };
  double x = 0, v = 1, s = 0;
  while (s < s_max) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * ds * k1v, k2v = accel(x + 0.5 * ds * k1x, v + 0.5 * ds * k1v);
    const double k3x = v + 0.5 * ds * k2v, k3v = accel(x + 0.5 * ds * k2x, v + 0.5 * ds * k2v);
    const double k4x = v + ds * k3v, k4v = accel(x + ds * k3x, v + ds * k3v);
    const double xn = x + ds / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + ds / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xn <= 0 && s > 0) {
      const double f = x / (x - xn);
      if (duration) *duration = s + f * ds;
      return -(v + f * (vn - v));
    }
    x = xn, v = vn, s += ds;
  }
  if (duration) *duration = s_max;
  return std::max(0.0, -v);
}

ContactModel derive_contact_model(const Scene& scene, const ContactInputs& in) {
  ContactModel m;
  m.law = in.law;
  m.ball_speed = in.impact_speed > 0 ? in.impact_speed : expected_ball_speed(scene);
  const double r_min = scene.radius.minCoeff(), m_max = scene.mass.maxCoeff(), m_min = scene.mass.minCoeff();
  m.overlap = in.overlap_target * r_min;
  const double e = scene.restitution;
  // The worst cases: two of the heaviest balls head-on, each at the largest speed (reduced mass
  // m/2, approach 2v), and the heaviest ball square on a wall (m, v); the smallest radius, whose
  // overlap target is the smallest and whose Hertz contact is the stiffest per metre of overlap.
  if (in.law == ContactLaw::hooke) {
    m.pair = hooke_contact(m_max / 2, r_min / 2, 2 * m.ball_speed, m.overlap, e);
    m.wall = hooke_contact(m_max, r_min, m.ball_speed, m.overlap, e);
  } else {
    m.hertz_damping = hertz_damping_for(e);
    m.hertz_restitution = hertz_restitution(m.hertz_damping);
    m.pair = hertz_contact(m_max / 2, r_min / 2, 2 * m.ball_speed, m.overlap, m.hertz_damping);
    m.wall = hertz_contact(m_max, r_min, m.ball_speed, m.overlap, m.hertz_damping);
  }
  // The springs are set for the heaviest balls; the lightest meet them in a shorter contact, which
  // the DEM step must resolve too (two light balls: m_min / 2; a light ball on a wall: m_min).
  m.light_pair = same_springs(m.pair, in.law, m_min / 2, &m.e_light_pair);
  m.light_wall = same_springs(m.wall, in.law, m_min, &m.e_light_wall);
  m.contact_time = std::min({m.pair.contact_time, m.wall.contact_time, m.light_pair.contact_time,
                             m.light_wall.contact_time});
  m.dem_dt_max = m.contact_time / in.contact_steps;
  return m;
}

}  // namespace ballbench::lammps

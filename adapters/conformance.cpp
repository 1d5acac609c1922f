#include "conformance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>

#include "engine_settings.h"
#include "runner.h"
#include "project_scene.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

constexpr double kRelative = 1e-4;  // float round-off over a few thousand steps; double meets it with room
constexpr double kFriction = 5e-3;  // the closed form within 0.5%

constexpr std::array<ConformCaseDef, 12> kCases{{
    {ConformCase::wall_bounce_elastic, "WallBounceElastic", "wall-bounce-elastic",
     "a ball between two walls at e = 1 keeps its speed (3 m/s)", kRelative, "", 0},
    {ConformCase::wall_bounce_lossy, "WallBounceLossy", "wall-bounce-lossy",
     "at e = 0.8 its speed is 0.8^k 3 m/s after k bounces", kRelative, "any_restitution", 0.1},
    {ConformCase::head_on, "HeadOn", "head-on",
     "masses 1 and 3 head on at e = 1 leave at -1 and 1 m/s (m/s)", kRelative, "", 0},
    {ConformCase::drop, "Drop", "drop",
     "a ball in free fall follows s0 + v0 t + g t^2 / 2 (error over the 9 m drop)", kRelative, "gravity", 0.01},
    {ConformCase::seed_box_contained, "SeedBoxContained", "seed-box-contained",
     "no ball leaves seed-box's box (20 balls at up to 35 m/s, 30 s): balls that left", 0, "", 0},
    {ConformCase::gas_energy, "GasEnergy", "gas-energy",
     "an elastic gas (e = 1, 20 balls in a box, 10 s) keeps its kinetic energy", 1e-2, "", 0},
    {ConformCase::slide_to_roll_disk, "SlideToRollDisk", "slide-to-roll-disk",
     "a disk sliding at 3 m/s, mu 0.5, decelerates at mu g and rolls at 2 m/s", kFriction, "friction", 0.1},
    {ConformCase::slide_to_roll_sphere, "SlideToRollSphere", "slide-to-roll-sphere",
     "a sphere sliding at 3 m/s decelerates at mu g and rolls at 15/7 m/s", kFriction, "friction", 0.1},
    {ConformCase::spin_drop_sliding, "SpinDropSliding", "spin-drop-sliding",
     "a backspinning ball dropped at mu 0.2 rolls at -1 m/s", kFriction, "friction", 0.1},
    {ConformCase::spin_drop_sticking, "SpinDropSticking", "spin-drop-sticking",
     "the same at mu 0.8 rolls at -1 m/s from the impact on", kFriction, "friction", 0.1},
    {ConformCase::oblique_sticking, "ObliqueSticking", "oblique-sticking",
     "an oblique impact of two rough spinning disks conserves momentum, each angular momentum about "
     "the contact, e, and sticks (mu 0.9)",
     kFriction, "friction", 0.1},
    {ConformCase::oblique_sliding, "ObliqueSliding", "oblique-sliding",
     "the same at mu 0.1 slides: its tangential impulse is mu times the normal one", kFriction, "friction", 0.1},
}};

Scene scene_from(const std::string& text) { return parse_scene(text, "conformance.toml"); }

std::unique_ptr<Engine> build(const EngineEntry& engine, const std::string& profile, const Scene& s) {
  return engine.create(s, profile, merged_settings(s, engine.info.name, {}));
}


// One ball between two walls 2 apart, speed 3, 10 s: it bounces 16 times (7 at e = 0.8). Figure: the relative
// error of the final speed against e^k v0, k counted from the sign changes of vx.
double wall_bounce(const EngineEntry& engine, const std::string& profile, double e) {
  const Scene s = scene_from(fmt::format(R"(
dt = 0.01
duration = 10.0
restitution = {}
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[[ball]]
pos = [0.0, 0.0]
vel = [3.0, 0.0]
radius = 0.1
)", e));
  auto eng = build(engine, profile, s);
  State st;
  double vx = 3.0;
  int bounces = 0;
  for (long k = 0; k < s.steps(); ++k) {
    eng->step(s.dt);
    eng->read(st);
    if ((st.vel(0, 0) > 0) != (vx > 0)) ++bounces;
    vx = st.vel(0, 0);
  }
  const double want = std::pow(e, bounces) * 3.0;
  if (bounces == 0) return HUGE_VAL;
  return std::abs(std::hypot(st.vel(0, 0), st.vel(0, 1)) - want) / want;
}

// Masses 1 and 3, v1 = 2, v2 = 0, e = 1, in open space (scenarios/two-ball-3.toml): thesis
// eq. 11-12 give v1' = -1, v2' = 1.
double head_on(const EngineEntry& engine, const std::string& profile) {
  const Scene s = load_project_scene("two-ball-3");
  auto eng = build(engine, profile, s);
  for (long k = 0; k < s.steps(); ++k) eng->step(s.dt);
  State st;
  eng->read(st);
  return std::max({std::abs(st.vel(0, 0) + 1.0), std::abs(st.vel(1, 0) - 1.0), std::abs(st.vel(0, 1)),
                   std::abs(st.vel(1, 1))});
}

// A ball dropped from y = 4 (floor at -5, radius 0.25) with v0 = (1, 0), g = -9.81, before it
// lands (~1.34 s): the largest position error against s0 + v0 t + g t^2 / 2, relative to the drop
// height 9. A time-stepped engine's first-order integrator is off the parabola by a known
// lead * g dt t / 2, linear in t: symplectic Euler velocity first leads by it (lead 1), position
// first (Chipmunk) lags by it (-1), k substeps of dt / k lead by a k-th of it (Rapier, Box2D v3,
// home's soft step), velocity Verlet and closed forms not at all (0). The figure is the smallest
// error over those leads: the offset of the engine's integrator is taken off, and an error of
// gravity (quadratic in t) cannot hide behind it, so the figure measures the engine, not the
// integrator's order.
double drop(const EngineEntry& engine, const std::string& profile) {
  const Scene s = scene_from(R"(
dt = 0.01
duration = 1.2
gravity = [0.0, -9.81]
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [0.0, 4.0]
vel = [1.0, 0.0]
radius = 0.25
)");
  auto eng = build(engine, profile, s);
  std::vector<double> leads{0.0, -1.0};
  for (int k = 1; k <= 64; ++k) leads.push_back(1.0 / k);
  std::vector<double> worst(leads.size(), 0.0);
  State st;
  for (long k = 1; k <= s.steps(); ++k) {
    eng->step(s.dt);
    eng->read(st);
    const double t = k * s.dt, x = std::abs(st.pos(0, 0) - t) / 9.0;
    for (size_t j = 0; j < leads.size(); ++j) {
      const double y = 4.0 - 9.81 * t * t / 2 - leads[j] * 9.81 * s.dt * t / 2;
      worst[j] = std::max({worst[j], std::abs(st.pos(0, 1) - y) / 9.0, x});
    }
  }
  return *std::min_element(worst.begin(), worst.end());
}

// seed-box, 3000 steps: balls that left the box (wall escapes, plus balls outside at the end).
double seed_box_escapes(const EngineEntry& engine, const std::string& profile) {
  RunOptions o;
  o.profile = profile;
  const Scene s = load_project_scene("seed-box");
  const Result r = run_engine(s, engine, o);
  if (r.status != RunStatus::ok) return HUGE_VAL;
  return r.metrics.count(Metric::tunnelling_wall);
}

// A friction case's engine, built for its scene; or, when there is none to run, the case's figure:
// an engine without friction must refuse the scene (0 if the runner does, infinite if it runs
// it), and one that cannot build it (a limit of its own) fails the case (infinite).
struct RoughCase {
  std::unique_ptr<Engine> engine;
  double figure = 0;
};

RoughCase build_rough(const EngineEntry& engine, const std::string& profile, const Scene& s) {
  const EngineEntry& entry = engine;
  if (!entry.info.caps.friction) {
    RunOptions o;
    o.profile = profile;
    return {nullptr, run_engine(s, entry, o).status == RunStatus::unsupported ? 0.0 : HUGE_VAL};
  }
  return {build(engine, profile, s), 0.0};
}

// A ball (radius 0.25, mass 1) sliding on the floor at v0 = 3 m/s, friction mu = 0.5, g = 9.81,
// I = k m r^2. Friction decelerates it at mu g until it rolls, at v0 / (1 + k) (2/3 v0 for a disk,
// 5/7 v0 for a sphere), from t = v0 k / ((1 + k) mu g) (0.20 s, 0.17 s) on (Goldstein, Classical
// Mechanics, the rolling constraint v = -w r with the impulse of friction on both). Figure: the
// larger relative error of the final speed (the inertia in force) and of the friction coefficient
// measured from the deceleration between t = 0.03 and 0.13 s, while it slides (the friction in
// force).
double slide_to_roll(const EngineEntry& engine, const std::string& profile, const char* inertia) {
  Scene s = load_project_scene("slide-to-roll");  // v0 3 m/s, friction 0.5, g 9.81, r 0.25, m 1
  s.inertia = inertia == std::string("sphere") ? Inertia::sphere : Inertia::disk;
  RoughCase rough = build_rough(engine, profile, s);
  if (!rough.engine) return rough.figure;
  const SlideMeasure m = measure_slide(*rough.engine, s);
  const double k = inertia_factor(s.inertia);
  // The final speed 3 / (1 + m.k) against 3 / (1 + k), relative: |k - m.k| / (1 + m.k).
  return std::max(std::abs(m.k - k) / (1 + m.k), std::abs(m.mu - 0.5) / 0.5);
}

// A ball (radius 0.25, mass 1, a disk) dropped from 1 m above the floor with v0 = 1 m/s and backspin
// w0 = 20 rad/s (counter-clockwise), restitution 0: it lands at 4.43 m/s with its contact point
// slipping forward at v0 + w0 r = 6 m/s. Friction at the floor and along it acts at the contact,
// so the angular momentum about the floor point under the centre, m r v + I w (gravity and the
// normal force pass through that point too), is the same when it rolls (v = -w r):
// v_final = (v0 - k r w0) / (1 + k) = -1 m/s. The impact's Coulomb impulse law sets how it gets
// there: sticking needs a tangential impulse m k / (1 + k) 6 = 2 N s, within mu m 4.43 for mu
// above 0.45. mu = 0.2: the ball slides off the impact (v 0.114, w 12.9) and rolls 0.57 s later (slip 3.34 m/s
// closing at mu g (1 + 1/k));
// mu = 0.8: it rolls from the impact on. Figure: the relative error of the final speed.
double spin_drop(const EngineEntry& engine, const std::string& profile, double mu) {
  Scene s = load_project_scene("spin-drop");  // v0 (1, 0), w0 20 rad/s, r 0.25, m 1, dropped from 1 m, e 0
  s.friction = mu;
  RoughCase rough = build_rough(engine, profile, s);
  if (!rough.engine) return rough.figure;
  Engine* eng = rough.engine.get();
  for (long k = 0; k < s.steps(); ++k) eng->step(s.dt);
  State st;
  eng->read(st);
  const double want = (1.0 - 0.5 * 0.25 * 20.0) / 1.5;
  return std::abs(st.vel(0, 0) - want) / std::abs(want);
}

// An oblique impact of two rough disks (unequal masses and radii, both spinning, restitution 0.7)
// in a box far from its walls, without gravity. Ball 1 (at rest, spinning) sits at the origin;
// ball 0 comes along x at height b, so it touches at the normal n = (sqrt(R^2 - b^2), b) / R,
// known before the run. It starts 20 steps of travel from touching, so a time-stepped engine meets
// the contact at a step's end, touching: the case is about the impact law, not about how deep a
// contact is found (a step's travel, 6 cm, would tilt the normal by a degree). Six conditions fix
// the six velocities after the impact:
// - linear momentum (2);
// - each ball's angular momentum about the contact point (2): the impulse passes through it;
// - the normal relative velocity is -e times what it was (1);
// - sticking: the contact points move together; sliding: the tangential impulse is mu times the
//   normal one (1).
// The sticking impulse is 0.18 of the normal one here: mu 0.9 sticks, mu 0.1 slides. Figure: the
// largest of the six residuals, each relative to its scale (the incoming momentum m0 |v0|, its
// moment m0 |v0| r0, the incoming normal speed, the incoming slip, the normal impulse). Computed
// from the run's velocities without solving for them, so it is independent of any engine's law.
double oblique_impact(const EngineEntry& engine, const std::string& profile, double mu, bool sticks) {
  const double r0 = 0.3, r1 = 0.5, m0 = 1.0, m1 = 2.5, e = 0.7, R = r0 + r1, b = 0.35, w0 = 4.0, w1 = -7.0;
  const double x_start = std::sqrt(R * R - b * b) + 6.0 * 20 * 0.01;
  const Scene s = scene_from(fmt::format(R"(
dt = 0.01
duration = 0.5
restitution = {e}
friction = {mu}
[container]
min = [-10.0, -10.0]
max = [10.0, 10.0]
[[ball]]
pos = [{x:.17g}, {b}]
vel = [-6.0, 0.0]
spin = {w0}
radius = {r0}
mass = {m0}
[[ball]]
pos = [0.0, 0.0]
vel = [0.0, 0.0]
spin = {w1}
radius = {r1}
mass = {m1}
)", fmt::arg("e", e), fmt::arg("mu", mu), fmt::arg("x", x_start), fmt::arg("b", b), fmt::arg("w0", w0), fmt::arg("r0", r0),
                                         fmt::arg("m0", m0), fmt::arg("w1", w1), fmt::arg("r1", r1), fmt::arg("m1", m1)));
  RoughCase rough = build_rough(engine, profile, s);
  if (!rough.engine) return rough.figure;
  Engine* eng = rough.engine.get();
  for (long k = 0; k < s.steps(); ++k) eng->step(s.dt);
  State st;
  eng->read(st);
  const Eigen::Vector2d n{std::sqrt(R * R - b * b) / R, b / R}, t{-n.y(), n.x()}, v0{-6.0, 0.0}, v1{0.0, 0.0};
  const double I0 = 0.5 * m0 * r0 * r0, I1 = 0.5 * m1 * r1 * r1;
  const Eigen::Vector2d u0 = st.vel.row(0), u1 = st.vel.row(1);
  const double x0 = st.w(0), x1 = st.w(1);
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& c) { return a.x() * c.y() - a.y() * c.x(); };
  // The velocity of ball 0's contact point relative to ball 1's along t: ball 0's point sits at
  // -r0 n from its centre, ball 1's at +r1 n from its own.
  const auto slip = [&](const Eigen::Vector2d& a, double wa, const Eigen::Vector2d& c, double wc) {
    return (a - c).dot(t) - (wa * r0 + wc * r1);
  };
  const double p_in = m0 * v0.norm(), slip_in = slip(v0, w0, v1, w1), vn_in = (v0 - v1).dot(n);
  const double pn = m0 * (u0 - v0).dot(n), pt = m0 * (u0 - v0).dot(t);
  if (!(pn > 0)) return HUGE_VAL;  // no impact
  // Angular momentum about the contact point: centres at +r0 n (ball 0) and -r1 n (ball 1) from it.
  const double residuals[] = {
      (m0 * u0 + m1 * u1 - m0 * v0 - m1 * v1).norm() / p_in,
      std::abs(m0 * cross(r0 * n, u0 - v0) + I0 * (x0 - w0)) / (p_in * r0),
      std::abs(m1 * cross(-r1 * n, u1 - v1) + I1 * (x1 - w1)) / (p_in * r0),
      std::abs((u0 - u1).dot(n) + e * vn_in) / std::abs(vn_in),
      sticks ? std::abs(slip(u0, x0, u1, x1)) / std::abs(slip_in) : std::abs(std::abs(pt) - mu * pn) / pn,
  };
  return *std::max_element(std::begin(residuals), std::end(residuals));
}
// seed-box's 20 balls at up to 35 m/s in a 7 m box without gravity or friction, every impact
// elastic (e = 1), 10 s: the kinetic energy at the end against the start's, relative.
double gas_energy(const EngineEntry& engine, const std::string& profile) {
  Scene s = load_project_scene("seed-box");
  s.restitution = 1.0;
  s.duration = 10.0;
  auto eng = build(engine, profile, s);
  for (long k = 0; k < s.steps(); ++k) eng->step(s.dt);
  State st;
  eng->read(st);
  double e0 = 0, e1 = 0;
  for (int i = 0; i < s.n(); ++i) {
    e0 += 0.5 * s.mass(i) * s.initial.vel.row(i).squaredNorm();
    e1 += 0.5 * s.mass(i) * st.vel.row(i).squaredNorm();
  }
  return std::isfinite(e1) ? std::abs(e1 / e0 - 1) : HUGE_VAL;
}

}  // namespace

SlideMeasure measure_slide(Engine& e, const Scene& s) {
  constexpr long kEarly = 3, kLate = 13;
  State st;
  double v_early = 0, v_late = 0;
  for (long k = 1; k <= s.steps(); ++k) {
    e.step(s.dt);
    e.read(st);
    if (k == kEarly) v_early = st.vel(0, 0);
    if (k == kLate) v_late = st.vel(0, 0);
  }
  const double g = s.gravity.norm(), v0 = s.initial.vel(0, 0);
  return {(v_early - v_late) / ((kLate - kEarly) * s.dt * g), v0 / st.vel(0, 0) - 1.0};
}

std::span<const ConformCaseDef> conform_cases() { return kCases; }

const ConformCaseDef& conform_case(ConformCase c) {
  return *std::find_if(kCases.begin(), kCases.end(), [&](const ConformCaseDef& d) { return d.c == c; });
}

bool is_friction_case(ConformCase c) { return std::string_view(conform_case(c).capability) == "friction"; }

bool claims(const Capabilities& caps, const std::string& name) {
  if (name == "friction") return caps.friction;
  if (name == "any_restitution") return caps.any_restitution;
  if (name == "gravity") return caps.gravity;
  return false;
}

double conform_figure(const EngineEntry& engine, const std::string& profile, ConformCase c) {
  switch (c) {
    case ConformCase::wall_bounce_elastic: return wall_bounce(engine, profile, 1.0);
    case ConformCase::wall_bounce_lossy: return wall_bounce(engine, profile, 0.8);
    case ConformCase::head_on: return head_on(engine, profile);
    case ConformCase::drop: return drop(engine, profile);
    case ConformCase::seed_box_contained: return seed_box_escapes(engine, profile);
    case ConformCase::gas_energy: return gas_energy(engine, profile);
    case ConformCase::slide_to_roll_disk: return slide_to_roll(engine, profile, "disk");
    case ConformCase::slide_to_roll_sphere: return slide_to_roll(engine, profile, "sphere");
    case ConformCase::spin_drop_sliding: return spin_drop(engine, profile, 0.2);
    case ConformCase::spin_drop_sticking: return spin_drop(engine, profile, 0.8);
    case ConformCase::oblique_sticking: return oblique_impact(engine, profile, 0.9, true);
    case ConformCase::oblique_sliding: return oblique_impact(engine, profile, 0.1, false);
  }
  return HUGE_VAL;
}

}  // namespace ballbench

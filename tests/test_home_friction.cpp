// `home` with friction: each case against a closed form derived here, independently of the
// solver's impulse law (core/solver/rough_impact.h): from conservation laws about the contact
// point and the Coulomb conditions, not from the law's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "registry.h"
#include "rough_gas.h"
#include "runner.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

// One impulse's round-off is ~1e-16 relative; a run of a few hundred steps adds a friction impulse
// per step, so 1e-9 leaves a wide margin and still fails any law that is off by a physical amount.
constexpr double kClosedForm = 1e-9;

std::unique_ptr<Engine> build_home(const Scene& s) { return find_engine("home").create(s, "default", merged_settings(s, "home", {})); }

// A ball sliding at v0 on the floor (scenarios/slide-to-roll.toml: v0 3, mu 0.5, g 9.81, r 0.25):
// each step's friction impulse is mu times the step's normal impulse m g dt, so the ball slows by
// exactly mu g dt a step until the impulse that makes it roll is within the cone; from then on it
// rolls. Friction at the floor point leaves the angular momentum about it, m r v - I w (w
// counter-clockwise), unchanged: rolling (v = -w r) then gives v = v0 / (1 + k).
class HomeSlideToRoll : public ::testing::TestWithParam<Inertia> {};

TEST_P(HomeSlideToRoll, DeceleratesAtMuGAndRollsAtTheClosedFormSpeed) {
  Scene s = load_scene("slide-to-roll");
  s.inertia = GetParam();
  const double k = inertia_factor(s.inertia), mu = 0.5, g = 9.81, v0 = 3.0, r = 0.25;
  auto home = build_home(s);
  State st;
  double v_last = v0;
  long rolling_from = -1;
  for (long n = 1; n <= s.steps(); ++n) {
    home->step(s.dt);
    home->read(st);
    const double v = st.vel(0, 0);
    if (rolling_from < 0 && std::abs(v + st.w(0) * r) < kClosedForm) rolling_from = n;
    if (rolling_from < 0) {
      EXPECT_NEAR(v_last - v, mu * g * s.dt, kClosedForm) << "step " << n;
    }
    v_last = v;
  }
  EXPECT_NEAR(st.vel(0, 0), v0 / (1 + k), kClosedForm);
  EXPECT_NEAR(st.w(0), -v0 / (1 + k) / r, kClosedForm / r);
  EXPECT_NEAR(st.vel(0, 1), 0.0, kClosedForm);
  // It starts rolling in the step that contains the closed-form time v0 k / ((1 + k) mu g).
  const double t_roll = v0 * k / ((1 + k) * mu * g);
  EXPECT_EQ(rolling_from, static_cast<long>(std::ceil(t_roll / s.dt - 1e-9)));
}

INSTANTIATE_TEST_SUITE_P(Inertia, HomeSlideToRoll, ::testing::Values(Inertia::disk, Inertia::sphere),
                         [](const auto& info) { return std::string(inertia_name(info.param)); });

// The spin drop of tests/test_conformance.cpp: a disk (r 0.25, m 1) dropped with v0 = 1 m/s and
// backspin w0 = 20 rad/s onto the floor, restitution 0. The landing is an impact: the test takes
// the state of the step before and derives the state after, on the floor:
// - normal: restitution 0 stops the fall, P_n = m |v_y|;
// - sticking: the contact point stops (v = -w r) and the angular momentum about it,
//   m r v - I w, is unchanged: v = (v - k r w) / (1 + k), needing the tangential impulse
//   m (v_before - v_after), allowed if within mu P_n;
// - otherwise sliding: the tangential impulse is mu P_n against the slip, which gives v and, by
//   the same angular momentum, w.
// Then the slide (a step's friction mu g dt) ends in rolling at (v0 - k r w0) / (1 + k) = -1 m/s.
class HomeSpinDrop : public ::testing::TestWithParam<double> {};

TEST_P(HomeSpinDrop, LandsByTheCoulombImpulseLawAndRollsAtTheClosedFormSpeed) {
  const double mu = GetParam(), r = 0.25, k = 0.5, m = 1.0;
  Scene s = load_scene("spin-drop");  // v0 (1, 0), w0 20 rad/s, r 0.25, m 1, dropped from 1 m, e 0
  s.friction = mu;
  auto home = build_home(s);
  State before, st;
  home->read(before);
  bool landed = false;
  for (long n = 1; n <= s.steps(); ++n) {
    home->step(s.dt);
    home->read(st);
    if (!landed && st.vel(0, 1) > -1e-12) {  // the step of the impact
      landed = true;
      const double vy = before.vel(0, 1) - 9.81 * s.dt;  // this step's kick, then the fall to the floor
      const double vx = before.vel(0, 0), w = before.w(0), pn = m * std::abs(vy);
      const double l = vx - k * r * w;  // angular momentum about the floor point / (m r)
      const double v_stick = l / (1 + k);
      double v_after = v_stick;
      if (m * std::abs(vx - v_stick) > mu * pn) v_after = vx - std::copysign(mu * pn / m, vx + w * r);
      const double w_after = (v_after - l) / (k * r);
      const bool sticks = mu == 0.8;  // needs 2 N s of tangential impulse, within 0.8 x 4.4 but not 0.2 x 4.4
      EXPECT_EQ(v_after == v_stick, sticks);
      EXPECT_NEAR(st.vel(0, 0), v_after, kClosedForm);
      EXPECT_NEAR(st.w(0), w_after, kClosedForm);
      EXPECT_NEAR(st.vel(0, 1), 0.0, kClosedForm);
      EXPECT_NEAR(st.pos(0, 1), r, kClosedForm);
    }
    before = st;
  }
  ASSERT_TRUE(landed);
  const double want = (1.0 - k * r * 20.0) / (1 + k);
  EXPECT_NEAR(st.vel(0, 0), want, kClosedForm);
  EXPECT_NEAR(st.w(0), -want / r, kClosedForm);
}

INSTANTIATE_TEST_SUITE_P(Friction, HomeSpinDrop, ::testing::Values(0.2, 0.8),
                         [](const auto& info) { return info.param == 0.2 ? std::string("Sliding") : std::string("Sticking"); });

// A rough gas in open space without gravity: every impulse acts at a contact point, equal and
// opposite, so the total angular momentum about any fixed point (orbital plus spin) is conserved;
// friction and restitution only take energy. Restitution 1 runs the elastic path (its neighbour
// list), 0.9 the grid's.
class HomeRoughGas : public ::testing::TestWithParam<double> {};

TEST_P(HomeRoughGas, KeepsAngularMomentumAndNeverGainsEnergy) {
  const Scene s = rough_gas::scene(GetParam());
  auto home = build_home(s);
  State st;
  home->read(st);
  const double l0 = rough_gas::angular_momentum(s, st), e0 = rough_gas::kinetic_energy(s, st);
  double worst_l = 0, e_last = e0;
  for (long n = 0; n < s.steps(); ++n) {
    home->step(s.dt);
    home->read(st);
    worst_l = std::max(worst_l, std::abs(rough_gas::angular_momentum(s, st) - l0));
    const double e = rough_gas::kinetic_energy(s, st);
    EXPECT_LE(e, e_last * (1 + 1e-14)) << "step " << n;  // round-off of the sum only
    e_last = e;
  }
  // Round-off: ~1e-16 relative per impulse over a few hundred impacts, on terms of size |x| m v.
  EXPECT_LT(worst_l, 1e-11 * std::max(1.0, std::abs(l0)));
  EXPECT_LT(e_last, 0.99 * e0);  // friction took energy: the gas is rough
}

INSTANTIATE_TEST_SUITE_P(Restitution, HomeRoughGas, ::testing::Values(1.0, 0.9),
                         [](const auto& info) { return info.param == 1.0 ? std::string("Elastic") : std::string("Lossy"); });

// A frictionless scene whose balls start spinning: impacts never touch the spins, and each angle
// turns at its ball's spin.
TEST(HomeSpin, WithoutFrictionSpinsAreKeptAndAnglesTurnAtThem) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 3.0
gravity = [0.0, -9.81]
restitution = 0.8
[container]
min = [-2.0, -2.0]
max = [2.0, 2.0]
[random]
count = 30
radius = 0.15
mass = 1.0
vel_min = [-3.0, -3.0]
vel_max = [3.0, 3.0]
spin_min = -5.0
spin_max = 5.0
seed = 3
)", "spin.toml");
  auto home = build_home(s);
  for (long n = 0; n < s.steps(); ++n) home->step(s.dt);
  State st;
  home->read(st);
  ASSERT_TRUE(st.rotates());
  for (int i = 0; i < s.n(); ++i) {
    EXPECT_EQ(st.w(i), s.spin(i));
    EXPECT_NEAR(st.angle(i), s.spin(i) * st.t, 1e-12 * std::abs(s.spin(i)) * st.t + 1e-15);
  }
}

// The soft path (resting = soft) solves friction in its soft step: slide to roll and the spin
// drop end rolling at the closed-form speed, which friction at the floor point cannot change.
TEST(HomeSoftPath, RollsAtTheClosedFormSpeed) {
  for (const double mu : {0.2, 0.8}) {
    Scene s = load_scene("slide-to-roll");
    s.friction = mu;
    s.initial.w(0) = 20.0;  // backspin: v0 - k r w0 = 3 - 2.5
    auto home = find_engine("home").create(s, "default", {{"resting", "soft"}});
    for (long n = 0; n < s.steps(); ++n) home->step(s.dt);
    State st;
    home->read(st);
    const double want = (3.0 - 0.5 * 0.25 * 20.0) / 1.5;
    EXPECT_NEAR(st.vel(0, 0), want, 1e-9) << "mu " << mu;
    EXPECT_NEAR(st.w(0), -want / 0.25, 1e-9 / 0.25) << "mu " << mu;
  }
}

// A rough pile (rough-box's 40 balls, friction 0.3): nothing passes through anything, no energy
// appears, and the rotation metrics are there.
TEST(HomeRoughBox, NeitherTunnelsNorGainsEnergy) {
  const Result r = run_engine(load_scene("rough-box"), find_engine("home"), {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  EXPECT_EQ(r.metrics.count(Metric::tunnelling_wall) + r.metrics.count(Metric::tunnelling_pair), 0);
  EXPECT_EQ(r.metrics.count(Metric::sticking_wall) + r.metrics.count(Metric::sticking_pair), 0);
  EXPECT_LE(r.metrics.value(Metric::energy_final), r.metrics.value(Metric::energy_initial));
  EXPECT_LT(r.metrics.value(Metric::penetration_max), 0.01);
}

}  // namespace
}  // namespace ballbench

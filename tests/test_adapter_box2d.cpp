// The Box2D adapter: effective restitution measured from read-back states, the limits Box2D 2.4.1
// imposes (restitution threshold, speed clamp), settings and their errors, exact set-up.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include <fmt/format.h>

#include "box2d/box2d_engine.h"
#include "input_error.h"
#include "adapter_calibration.h"
#include "registry.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

// One isolated contact is solved exactly by Box2D's sequential impulses (a single row: the first
// iteration sets the normal speed to e times the approach speed, later ones change nothing), so
// what separates the measured ratio from e is float32 round-off: the scene values are rounded to
// float (relative 6e-8 each) and the impulse takes about ten float operations. 1e-5 is about 80
// float ulps at 1.0, well above that and far below any solver effect worth seeing.
constexpr double kBox2dRestitutionTol = 1e-5;

using calibration::Calibration;
using calibration::calibration_name;
using calibration::head_on_scene;
using calibration::wall_scene;

State run_box2d(const Scene& s, const std::string& profile, int steps, const nlohmann::json& overrides = {}) {
  return calibration::run_steps("box2d", s, profile, steps, overrides);
}

class Box2dCalibration : public ::testing::TestWithParam<Calibration> {};

TEST_P(Box2dCalibration, BallWallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = wall_scene(e, 5.0);
  // Wall at t = 0.18 s; back at the far wall not before t = 0.18 + 1.8 / 5 = 0.54 s.
  const State st = run_box2d(s, profile, 40);
  const double measured = -st.vel(0, 0) / s.initial.vel(0, 0);  // post / pre normal speed
  RecordProperty("effective_restitution", fmt::format("{:.9g}", measured));
  EXPECT_NEAR(measured, e, kBox2dRestitutionTol);
  EXPECT_EQ(st.vel(0, 1), 0.0);  // a frictionless wall gives no tangential push
}

TEST_P(Box2dCalibration, BallBallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = head_on_scene(e);
  const State st = run_box2d(s, profile, 40);
  const double pre = s.initial.vel(0, 0) - s.initial.vel(1, 0);  // approach speed along the line of centres
  const double post = st.vel(1, 0) - st.vel(0, 0);               // separation speed
  const double measured = post / pre;
  RecordProperty("effective_restitution", fmt::format("{:.9g}", measured));
  EXPECT_NEAR(measured, e, kBox2dRestitutionTol);
  // Momentum 1 * 3 + 2 * (-2) = -1 kg m/s is kept by an equal and opposite impulse; float
  // velocities of a few m/s carry about 1e-6 of round-off.
  EXPECT_NEAR(s.mass(0) * st.vel(0, 0) + s.mass(1) * st.vel(1, 0), -1.0, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Profiles, Box2dCalibration,
                         ::testing::Values(Calibration{"tuned", 0.8}, Calibration{"tuned", 1.0},
                                           Calibration{"stock", 0.8}, Calibration{"stock", 1.0}),
                         calibration_name);

// Box2D's documented default: an impact slower than restitutionThreshold (1 m/s) gets no bounce.
// Stock keeps it, so a 0.5 m/s ball stops dead at the wall; tuned sets it to 0 and bounces.
TEST(Box2dLimits, StockIgnoresRestitutionBelowOneMeterPerSecond) {
  const Scene s = wall_scene(0.8, 0.5);
  // Wall at t = 1.8 s; 2.5 s leaves time to come back 0.28 m (tuned) but not to reach x = -0.9.
  const State stock = run_box2d(s, "stock", 250);
  const State tuned = run_box2d(s, "tuned", 250);
  EXPECT_NEAR(stock.vel(0, 0), 0.0, 1e-6);  // perfectly inelastic
  EXPECT_NEAR(-tuned.vel(0, 0) / 0.5, 0.8, kBox2dRestitutionTol);
}

// b2_maxTranslation (2 m per step, compile-time) caps the speed at 2 / dt = 200 m/s at dt = 0.01:
// Box2D scales the velocity itself down, so the energy is lost, not just the step shortened.
TEST(Box2dLimits, SpeedIsClampedByMaxTranslation) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 1.0
[[ball]]
pos = [0.0, 0.0]
vel = [300.0, 0.0]
radius = 0.1
)",
                              "fast.toml");
  const State st = run_box2d(s, "tuned", 1);
  EXPECT_NEAR(st.vel(0, 0), 200.0, 200.0 * 1e-6);  // float rounding of 2 / 0.01f
  EXPECT_NEAR(st.pos(0, 0), 2.0, 2.0 * 1e-6);
}

TEST(Box2dAdapter, InitialStateReadsBackAsTheScenesToFloatPrecision) {
  const Scene s = load_scene("seed-bowl");
  auto engine = find_engine("box2d").create(s, "tuned", {});
  State st;
  engine->read(st);
  ASSERT_EQ(st.n(), s.n());
  EXPECT_EQ(st.t, 0.0);
  for (int i = 0; i < s.n(); ++i)
    for (int a = 0; a < 2; ++a) {
      // Box2D stores float: the scene's value rounded to float, exactly, and nothing else.
      EXPECT_EQ(st.pos(i, a), static_cast<double>(static_cast<float>(s.initial.pos(i, a)))) << i;
      EXPECT_EQ(st.vel(i, a), static_cast<double>(static_cast<float>(s.initial.vel(i, a)))) << i;
    }
}

TEST(Box2dAdapter, SettingsListEveryKnobOfBothProfiles) {
  const Scene s = load_scene("seed-box");
  const auto tuned = find_engine("box2d").create(s, "tuned", {})->settings();
  const auto stock = find_engine("box2d").create(s, "stock", {})->settings();
  for (const char* key : {"velocity_iterations", "position_iterations", "restitution_threshold", "bullet",
                          "allow_sleep", "fixed_rotation", "warm_starting", "continuous_physics", "sub_stepping"}) {
    EXPECT_TRUE(tuned.contains(key)) << key;
    EXPECT_TRUE(stock.contains(key)) << key;
  }
  for (const char* key : {"max_translation", "linear_slop", "polygon_radius", "max_sub_steps", "real"})
    EXPECT_TRUE(tuned["compile_time"].contains(key)) << key;
  EXPECT_EQ(tuned["compile_time"]["max_translation"], 2.0);

  EXPECT_EQ(tuned["velocity_iterations"], 10);
  EXPECT_EQ(tuned["position_iterations"], 8);
  EXPECT_EQ(tuned["restitution_threshold"], 0.0);
  EXPECT_EQ(tuned["bullet"], true);
  EXPECT_EQ(stock["velocity_iterations"], 8);
  EXPECT_EQ(stock["position_iterations"], 3);
  EXPECT_EQ(stock["restitution_threshold"], 1.0);
  EXPECT_EQ(stock["bullet"], false);
  for (const auto* j : {&tuned, &stock}) {
    EXPECT_EQ((*j)["allow_sleep"], false);
    EXPECT_EQ((*j)["derived"]["fixed_rotation"], true);  // seed-box is frictionless
    EXPECT_DOUBLE_EQ((*j)["derived"]["max_speed"].get<double>(), 200.0);
  }
}

TEST(Box2dAdapter, OverridesApplyOnTopOfTheProfile) {
  const Scene s = load_scene("seed-box");
  const auto j = find_engine("box2d")
                     .create(s, "stock", {{"velocity_iterations", 20}, {"restitution_threshold", 0.25}})
                     ->settings();
  EXPECT_EQ(j["velocity_iterations"], 20);
  EXPECT_EQ(j["restitution_threshold"], 0.25);
  EXPECT_EQ(j["position_iterations"], 3);  // untouched: still stock
}

TEST(Box2dAdapter, BadSettingsAreInputErrors) {
  const Scene s = load_scene("seed-box");
  const auto& box2d = find_engine("box2d");
  EXPECT_THROW(box2d.create(s, "tuned", {{"velocity_iteration", 4}}), InputError);  // unknown key
  EXPECT_THROW(box2d.create(s, "tuned", {{"bullet", 1}}), InputError);              // wrong type
  EXPECT_THROW(box2d.create(s, "tuned", {{"velocity_iterations", 0}}), InputError);
  EXPECT_THROW(box2d.create(s, "tuned", {{"restitution_threshold", -1.0}}), InputError);
  try {
    box2d.create(s, "tuned", {{"max_translation", 4.0}});
    ADD_FAILURE() << "a compile-time constant was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compile-time"), std::string::npos) << e.what();
  }
  try {
    box2d.create(s, "x", {});
    ADD_FAILURE() << "an unknown profile was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "box2d: unknown profile 'x' (known: tuned, stock)");
  }
}

TEST(Box2dAdapter, IsDeterministic) {
  const Scene s = load_scene("seed-box");
  for (const char* profile : {"tuned", "stock"}) {
    const State a = run_box2d(s, profile, 300), b = run_box2d(s, profile, 300);
    EXPECT_EQ(a.pos, b.pos) << profile;
    EXPECT_EQ(a.vel, b.vel) << profile;
  }
}

// The scene's friction coefficient and inertia, as the adapter maps them (its README), measured.
TEST(Box2dCalibration, FrictionAndInertiaAreTheScenes) { calibration::expect_friction_and_inertia_are_the_scenes("box2d"); }

}  // namespace
}  // namespace ballbench

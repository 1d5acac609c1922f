// The Bullet adapter: effective restitution measured from read-back states, the plane constraint,
// the settings it reports and the errors it gives. Why Bullet's numbers are what they are:
// adapters/bullet/README.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "adapter_calibration.h"
#include "bullet/bullet_engine.h"
#include "input_error.h"
#include "registry.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

constexpr double kDt = 0.01;      // every calibration scene's step (s)
constexpr double kRadius = 0.25;  // every calibration ball's radius (m)

State run(const Scene& scene, const std::string& profile, long steps) {
  auto engine = find_engine("bullet").create(scene, profile, nlohmann::json::object());
  for (long k = 0; k < steps; ++k) engine->step(scene.dt);
  State s;
  engine->read(s);
  return s;
}

// One ball moving at `speed` towards the wall x = 1, its surface 0.75 m plus `phase` of a step's
// travel away, so that the step of first contact finds it at a different depth for each phase.
// The box reaches far to the left: nothing else is hit. Returns post / pre normal speed, read after
// the ball has bounced and left the wall.
double wall_restitution(const std::string& profile, double e, double speed, double phase) {
  const Scene s = parse_scene(fmt::format(R"(
dt = {}
duration = 1.0
restitution = {}
[container]
min = [-100.0, -5.0]
max = [1.0, 5.0]
[[ball]]
pos = [{}, 0.0]
vel = [{}, 0.0]
radius = {}
)",
                                          kDt, e, -phase * speed * kDt, speed, kRadius),
                              "wall.toml");
  const long steps = std::lround(2 * 0.75 / (speed * kDt)) + 12;
  return -run(s, profile, steps).vel(0, 0) / speed;
}

// Two equal balls head-on in open space, the left one at `speed` and 0.5 m plus `phase` of a step
// from contact, the right one at rest. Returns separation speed / approach speed after the impact.
double pair_restitution(const std::string& profile, double e, double speed, double phase) {
  const Scene s = parse_scene(fmt::format(R"(
dt = {}
duration = 1.0
restitution = {}
[container]
kind = "none"
[[ball]]
pos = [{}, 0.0]
vel = [{}, 0.0]
radius = {}
[[ball]]
pos = [0.0, 0.0]
radius = {}
)",
                                          kDt, e, -1.0 - phase * speed * kDt, speed, kRadius, kRadius),
                              "pair.toml");
  const long steps = std::lround(2 * 0.5 / (speed * kDt)) + 12;
  const State st = run(s, profile, steps);
  return (st.vel(1, 0) - st.vel(0, 0)) / speed;
}

const std::vector<double> kPhases = {0.0, 0.13, 0.37, 0.5, 0.71, 0.93};
// 2 m/s moves 0.08 radii per step; 30 m/s moves 1.2 radii, above tuned's CCD motion threshold.
const std::vector<double> kSpeeds = {2.0, 30.0};

TEST(BulletCalibration, TunedRestitutionIsTheScenes) {
  double worst = 0;
  for (double e : {0.8, 1.0})
    for (double v : {0.1, 2.0, 30.0})  // 0.1 m/s: below stock's restitution threshold
      for (double ph : kPhases) {
        const double wall = wall_restitution("tuned", e, v, ph);
        const double pair = pair_restitution("tuned", e, v, ph);
        // Float round-off only: sqrt(e) rounded to float and multiplied back (Bullet's combined
        // restitution) is within 2 ulp of e (~2.4e-7), and the impulse, the velocities and the
        // read-back are float: a few 1e-7 relative. 1e-5 is that with a wide margin; any physics
        // error (a threshold, a Baumgarte push, a speculative contact) is 1e-2 or more.
        EXPECT_NEAR(wall, e, 1e-5) << "ball-wall e=" << e << " v=" << v << " phase=" << ph;
        EXPECT_NEAR(pair, e, 1e-5) << "ball-ball e=" << e << " v=" << v << " phase=" << ph;
        worst = std::max({worst, std::abs(wall - e), std::abs(pair - e)});
      }
  RecordProperty("worst_abs_error", fmt::format("{:.3g}", worst));
}

TEST(BulletCalibration, StockRestitutionDependsOnTheContactDepth) {
  // Bullet's defaults do not give the requested e; they give e shifted by where the ball happens to
  // be at the step the contact is solved. The bands below are derived from Bullet's contact setup
  // (btSequentialImpulseConstraintSolver::setupContactConstraint), not fitted:
  // - up: a penetration p shallower than split_impulse_penetration_threshold (4 cm) is corrected by
  //   Baumgarte inside the velocity, adding erp p / dt; p < v dt, so e rises by at most
  //   erp min(v dt, 0.04) / (v dt) (0.2 at 2 m/s, 0.027 at 30 m/s);
  // - down (walls only): the sphere-box test keeps contacts up to the contact breaking threshold
  //   apart, 0.02 x the sphere's angular motion disc (sqrt(3) r) = 8.66 mm; solved at distance d
  //   the bounce loses d / dt, so e falls by at most 8.66 mm / (v dt). Sphere-sphere contacts
  //   exist only once touching, so ball-ball never falls below e.
  // 1e-4 absorbs float round-off at the band edges.
  const double erp = 0.2, split_depth = 0.04, breaking = 0.02 * std::sqrt(3.0) * kRadius, slack = 1e-4;
  for (double e : {0.8, 1.0})
    for (double v : kSpeeds) {
      const double step = v * kDt;
      const double up = erp * std::min(step, split_depth) / step, down = breaking / step;
      double lo_w = 9, hi_w = -9, lo_p = 9, hi_p = -9;
      for (double ph : kPhases) {
        const double wall = wall_restitution("stock", e, v, ph);
        const double pair = pair_restitution("stock", e, v, ph);
        EXPECT_GE(wall, e - down - slack) << "ball-wall e=" << e << " v=" << v << " phase=" << ph;
        EXPECT_LE(wall, e + up + slack) << "ball-wall e=" << e << " v=" << v << " phase=" << ph;
        EXPECT_GE(pair, e - slack) << "ball-ball e=" << e << " v=" << v << " phase=" << ph;
        EXPECT_LE(pair, e + up + slack) << "ball-ball e=" << e << " v=" << v << " phase=" << ph;
        lo_w = std::min(lo_w, wall), hi_w = std::max(hi_w, wall), lo_p = std::min(lo_p, pair), hi_p = std::max(hi_p, pair);
      }
      RecordProperty(fmt::format("e{}_v{}", e, v),
                     fmt::format("wall {:.3f}..{:.3f}, pair {:.3f}..{:.3f}", lo_w, hi_w, lo_p, hi_p));
    }
}

TEST(BulletPlane, NoOutOfPlaneDriftOnSeedBox) {
  const Scene scene = load_scene("seed-box");
  for (const char* profile : {"tuned", "stock"}) {
    auto engine = find_engine("bullet").create(scene, profile, nlohmann::json::object());
    double worst = 0;
    for (int k = 0; k < 1000; ++k) {
      engine->step(scene.dt);
      worst = std::max(worst, engine->out_of_plane());
    }
    // setLinearFactor(1, 1, 0) zeroes every z impulse and force in Bullet, so z stays exactly 0;
    // float epsilon is the bound the brief allows.
    EXPECT_LE(worst, std::numeric_limits<float>::epsilon()) << profile;
  }
}

TEST(BulletEngine, SameInputSameTrajectory) {
  const Scene scene = load_scene("seed-box");
  const State a = run(scene, "tuned", 300), b = run(scene, "tuned", 300);
  EXPECT_EQ(a.pos, b.pos);
  EXPECT_EQ(a.vel, b.vel);
}

TEST(BulletSettings, ListsEveryKnobWithItsProfileValue) {
  const Scene scene = load_scene("seed-box");
  const std::vector<std::string> knobs = {"solver_iterations",
                                          "substeps",
                                          "split_impulse",
                                          "split_impulse_penetration_threshold",
                                          "erp",
                                          "erp2",
                                          "restitution_velocity_threshold",
                                          "warmstarting_factor",
                                          "linear_slop",
                                          "contact_processing_threshold",
                                          "ccd_motion_threshold",
                                          "ccd_swept_sphere_radius",
                                          "speculative_contact_restitution"};
  const auto& entry = find_engine("bullet");
  const nlohmann::json tuned = entry.create(scene, "tuned", nlohmann::json::object())->settings();
  const nlohmann::json stock = entry.create(scene, "stock", nlohmann::json::object())->settings();
  EXPECT_EQ(tuned.size(), knobs.size() + 1);  // and what they mean for the scene:
  EXPECT_EQ(tuned["derived"]["moment_of_inertia"], "0.5 m r^2 (disk)");
  for (const auto& k : knobs) {
    EXPECT_TRUE(tuned.contains(k)) << k;
    EXPECT_TRUE(stock.contains(k)) << k;
  }
  // Bullet 3.24's own defaults (btContactSolverInfo, btCollisionObject).
  EXPECT_EQ(stock["solver_iterations"], 10);
  EXPECT_EQ(stock["substeps"], 1);
  EXPECT_EQ(stock["split_impulse"], true);
  EXPECT_DOUBLE_EQ(stock["restitution_velocity_threshold"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(stock["ccd_motion_threshold"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(tuned["restitution_velocity_threshold"].get<double>(), 0.0);
  EXPECT_GT(tuned["ccd_motion_threshold"].get<double>(), 0.0);

  const nlohmann::json set = entry.create(scene, "stock", {{"solver_iterations", 7}, {"erp", 0.5}})->settings();
  EXPECT_EQ(set["solver_iterations"], 7);
  EXPECT_DOUBLE_EQ(set["erp"].get<double>(), 0.5);
}

TEST(BulletSettings, BadInputIsAnInputError) {
  const Scene scene = load_scene("seed-box");
  const auto& entry = find_engine("bullet");
  EXPECT_THROW(entry.create(scene, "tuned", {{"solver_iteration", 5}}), InputError);  // unknown key
  EXPECT_THROW(entry.create(scene, "tuned", {{"split_impulse", 1}}), InputError);     // wrong type
  EXPECT_THROW(entry.create(scene, "tuned", {{"ccd_swept_sphere_radius", 2.0}}), InputError);
  try {
    entry.create(scene, "x", nlohmann::json::object());
    ADD_FAILURE() << "unknown profile accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "bullet: unknown profile 'x' (known: tuned, stock)");
  }
}

TEST(BulletEngine, InfoNamesTheLibrary) {
  const EngineInfo& info = find_engine("bullet").info;
  // btGetVersion()'s 324 as "3.24" (Debian's libbullet-dev at the time of writing).
  EXPECT_TRUE(std::regex_match(info.version, std::regex(R"(\d+\.\d\d)"))) << info.version;
  EXPECT_EQ(info.profiles, (std::vector<std::string>{"tuned", "stock"}));
}

// The scene's friction coefficient and inertia, as the adapter maps them (its README), measured.
TEST(BulletCalibration, FrictionAndInertiaAreTheScenes) { calibration::expect_friction_and_inertia_are_the_scenes("bullet"); }

}  // namespace
}  // namespace ballbench

// The Chipmunk2D adapter: effective restitution measured from read-back states, the mapping of
// mass, moment and friction, settings and their errors, the debug build's banner kept off stdout,
// and a failed Chipmunk assertion reported as a crashed run.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <ostream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "chipmunk/chipmunk_engine.h"
#include "input_error.h"
#include "isolated_run.h"
#include "adapter_calibration.h"
#include "registry.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

// One isolated contact is solved exactly by Chipmunk's sequential impulses: the first iteration
// sets the normal speed to e times the approach speed and later ones change nothing, and when the
// shapes still overlap the step after, the cached impulse it re-applies is taken back whole by the
// first iteration. What separates the measured ratio from e is double round-off: sqrt(e)^2 is e to
// an ulp and the impulse takes about ten operations, so ~1e-15. 1e-12 is well above that and far
// below any solver effect worth seeing.
constexpr double kChipmunkRestitutionTol = 1e-12;

using calibration::Calibration;
using calibration::calibration_name;
using calibration::head_on_scene;
using calibration::wall_scene;

State run_chipmunk(const Scene& s, const std::string& profile, int steps, const nlohmann::json& overrides = {}) {
  return calibration::run_steps("chipmunk", s, profile, steps, overrides);
}

class ChipmunkCalibration : public ::testing::TestWithParam<Calibration> {};

TEST_P(ChipmunkCalibration, BallWallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = wall_scene(e, 5.0);
  // Wall at t = 0.18 s; back at the far wall not before t = 0.18 + 1.8 / 5 = 0.54 s.
  const State st = run_chipmunk(s, profile, 40);
  const double measured = -st.vel(0, 0) / s.initial.vel(0, 0);  // post / pre normal speed
  RecordProperty("effective_restitution", fmt::format("{:.17g}", measured));
  std::printf("chipmunk/%s ball-wall e = %g: measured %.17g\n", profile.c_str(), e, measured);
  EXPECT_NEAR(measured, e, kChipmunkRestitutionTol);
  EXPECT_EQ(st.vel(0, 1), 0.0);  // a frictionless wall gives no tangential push
}

TEST_P(ChipmunkCalibration, BallBallRestitutionIsTheScenes) {
  const auto [profile, e] = GetParam();
  const Scene s = head_on_scene(e);
  const State st = run_chipmunk(s, profile, 40);
  const double pre = s.initial.vel(0, 0) - s.initial.vel(1, 0);  // approach speed along the line of centres
  const double post = st.vel(1, 0) - st.vel(0, 0);               // separation speed
  const double measured = post / pre;
  RecordProperty("effective_restitution", fmt::format("{:.17g}", measured));
  std::printf("chipmunk/%s ball-ball e = %g: measured %.17g\n", profile.c_str(), e, measured);
  EXPECT_NEAR(measured, e, kChipmunkRestitutionTol);
  // The masses are the scene's: momentum 1 * 3 + 2 * (-2) = -1 kg m/s is kept, and each ball gets
  // its own share of the impulse m1 m2 / (m1 + m2) (1 + e) 5 = (10 / 3) (1 + e).
  EXPECT_NEAR(s.mass(0) * st.vel(0, 0) + s.mass(1) * st.vel(1, 0), -1.0, 1e-12);
  EXPECT_NEAR(st.vel(0, 0), 3.0 - (10.0 / 3.0) * (1 + e), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Profiles, ChipmunkCalibration,
                         ::testing::Values(Calibration{"tuned", 0.8}, Calibration{"tuned", 1.0},
                                           Calibration{"stock", 0.8}, Calibration{"stock", 1.0}),
                         calibration_name);

// The moment is a solid disc's, m r^2 / 2, and the friction each contact sees is the scene's. A
// ball meeting the floor at (1, -3) m/s with enough friction to stop its contact point from
// sliding (the impulse needed, m vx / 3, is under mu (1 + e) m vy) leaves with vx' = vx (1 - 1 / (1
// + m r^2 / I)) = 2/3 vx for a disc (5/7 for a sphere, 1/2 for a ring), and vy' = e vy.
TEST(ChipmunkAdapter, MomentIsADiscsAndFrictionIsTheScenes) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 1.0
restitution = 0.5
friction = 0.5
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[[ball]]
pos = [0.0, 0.0]
vel = [1.0, -3.0]
radius = 0.1
mass = 2.0
)",
                              "glancing.toml");
  for (const char* profile : {"tuned", "stock"}) {
    // Floor at t = 0.3 s; the next wall (x = 0.9) not before t = 0.3 + 0.3 / (2/3) = 0.75 s.
    const State st = run_chipmunk(s, profile, 40);
    EXPECT_NEAR(st.vel(0, 0), 2.0 / 3.0, 1e-12) << profile;
    EXPECT_NEAR(st.vel(0, 1), 1.5, 1e-12) << profile;
  }
  // Frictionless, the same bounce keeps vx: the disc is never spun.
  Scene smooth = s;
  smooth.friction = 0.0;
  EXPECT_NEAR(run_chipmunk(smooth, "tuned", 40).vel(0, 0), 1.0, 1e-12);
}

TEST(ChipmunkAdapter, InitialStateReadsBackAsTheScenes) {
  const Scene s = load_scene("seed-bowl");
  for (const char* profile : {"tuned", "stock"}) {
    auto engine = find_engine("chipmunk").create(s, profile, {});
    State st;
    engine->read(st);
    ASSERT_EQ(st.n(), s.n());
    EXPECT_EQ(st.t, 0.0);
    EXPECT_EQ(st.pos, s.initial.pos) << profile;  // cpFloat is double: nothing is rounded
    EXPECT_EQ(st.vel, s.initial.vel) << profile;
  }
}

TEST(ChipmunkAdapter, SettingsListEveryKnobOfBothProfiles) {
  const Scene s = load_scene("seed-box");  // 20 balls of radius 0.25, frictionless
  const auto tuned = find_engine("chipmunk").create(s, "tuned", {})->settings();
  const auto stock = find_engine("chipmunk").create(s, "stock", {})->settings();
  for (const char* key : {"iterations", "collision_slop", "collision_bias", "collision_persistence", "wall_radius",
                          "spatial_index", "hash_cell", "hash_count", "allow_sleep", "sleep_time_threshold", "idle_speed_threshold"}) {
    EXPECT_TRUE(tuned.contains(key)) << key;
    EXPECT_TRUE(stock.contains(key)) << key;
  }
  // Stock is what cpSpaceInit sets: 10 iterations, slop 0.1f, bias cpfpow(1.0f - 0.1f, 60.0f),
  // persistence 3, the bounding box tree, no sleeping (threshold INFINITY).
  EXPECT_EQ(stock["iterations"], 10);
  EXPECT_EQ(stock["collision_slop"].get<double>(), static_cast<double>(0.1f));
  EXPECT_DOUBLE_EQ(stock["collision_bias"].get<double>(), std::pow(static_cast<double>(1.0f - 0.1f), 60.0));
  EXPECT_EQ(stock["collision_persistence"], 3);
  EXPECT_EQ(stock["spatial_index"], "bbtree");
  EXPECT_EQ(stock["idle_speed_threshold"], 0.0);
  // Both: solid walls as thick as Box2D's, half the 10 m box's side.
  EXPECT_EQ(stock["wall_radius"], 5.0);
  EXPECT_EQ(tuned["wall_radius"], 5.0);
  EXPECT_EQ(find_engine("chipmunk").create(s, "tuned", {{"wall_radius", 0.0}})->settings()["wall_radius"], 0.0);

  EXPECT_EQ(tuned["iterations"], 30);
  EXPECT_DOUBLE_EQ(tuned["collision_slop"].get<double>(), 0.0025);  // 1% of the radius
  EXPECT_EQ(tuned["collision_bias"], stock["collision_bias"]);
  EXPECT_EQ(tuned["spatial_index"], "hash");
  EXPECT_EQ(tuned["hash_cell"], 0.5);  // the diameter
  EXPECT_EQ(tuned["hash_count"], 200);  // 10 per ball
  for (const auto* j : {&tuned, &stock}) {
    EXPECT_EQ((*j)["allow_sleep"], false);
    EXPECT_EQ((*j)["derived"]["sleeping"], false);
    EXPECT_EQ((*j)["derived"]["damping"], 1.0);
    EXPECT_DOUBLE_EQ((*j)["derived"]["shape_elasticity"].get<double>(), std::sqrt(s.restitution));
    EXPECT_EQ((*j)["compile_time"]["real"], "float64");
    // Debian's build announces itself as a debug build (assertions compiled in).
    EXPECT_EQ((*j)["compile_time"]["debug_build"], true);
  }
  // At dt 0.01, 1 - bias^dt of the overlap beyond the slop goes per step: about 6%.
  EXPECT_NEAR(stock["derived"]["overlap_removed_per_step"].get<double>(), 0.0613, 1e-4);
}

TEST(ChipmunkAdapter, OverridesApplyOnTopOfTheProfile) {
  const Scene s = load_scene("seed-box");
  const auto j = find_engine("chipmunk")
                     .create(s, "stock", {{"iterations", 20}, {"spatial_index", "hash"}, {"hash_cell", 1.5},
                                          {"collision_bias", 0.5}})
                     ->settings();
  EXPECT_EQ(j["iterations"], 20);
  EXPECT_EQ(j["spatial_index"], "hash");
  EXPECT_EQ(j["hash_cell"], 1.5);
  EXPECT_EQ(j["collision_bias"], 0.5);
  EXPECT_EQ(j["collision_slop"].get<double>(), static_cast<double>(0.1f));  // untouched: still stock
  EXPECT_EQ(j["hash_count"], 200);
}

TEST(ChipmunkAdapter, BadSettingsAreInputErrors) {
  const Scene s = load_scene("seed-box");
  const auto& chipmunk = find_engine("chipmunk");
  const auto message = [&](const nlohmann::json& overrides) -> std::string {
    try {
      chipmunk.create(s, "tuned", overrides);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_NE(message({{"iteration", 4}}).find("settings.chipmunk.iteration: unknown setting"), std::string::npos);
  EXPECT_NE(message({{"allow_sleep", 1}}).find("expected true or false"), std::string::npos);
  EXPECT_EQ(message({{"iterations", 0}}), "settings.chipmunk.iterations: must be >= 1");
  EXPECT_EQ(message({{"collision_slop", -0.1}}), "settings.chipmunk.collision_slop: must be >= 0 (m)");
  EXPECT_NE(message({{"collision_bias", 1.5}}).find("must be from 0 to 1"), std::string::npos);
  EXPECT_NE(message({{"collision_persistence", 0}}).find("must be >= 1"), std::string::npos);
  EXPECT_NE(message({{"spatial_index", "quadtree"}}).find("'quadtree' is not one of: bbtree, hash"), std::string::npos);
  EXPECT_EQ(message({{"hash_cell", 0.0}}), "settings.chipmunk.hash_cell: must be > 0 (m)");
  EXPECT_EQ(message({{"hash_count", 0}}), "settings.chipmunk.hash_count: must be >= 1");
  EXPECT_NE(message({{"sleep_time_threshold", 0.0}}).find("must be > 0"), std::string::npos);
  EXPECT_NE(message({{"idle_speed_threshold", -1.0}}).find("must be >= 0"), std::string::npos);
  try {
    chipmunk.create(s, "x", {});
    ADD_FAILURE() << "an unknown profile was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "chipmunk: unknown profile 'x' (known: tuned, stock)");
  }
}

TEST(ChipmunkAdapter, IsDeterministic) {
  const Scene s = load_scene("seed-box");
  for (const char* profile : {"tuned", "stock"}) {
    const State a = run_chipmunk(s, profile, 300), b = run_chipmunk(s, profile, 300);
    EXPECT_EQ(a.pos, b.pos) << profile;
    EXPECT_EQ(a.vel, b.vel) << profile;
  }
}

// Debian's libchipmunk prints its debug banner with printf when the first space of a process is
// made; the adapter catches it, so stdout carries only ballbench's own output. In this process:
TEST(ChipmunkAdapter, DebugBannerDoesNotReachStdout) {
  ::testing::internal::CaptureStdout();
  const auto settings = find_engine("chipmunk").create(load_scene("seed-box"), "stock", {})->settings();
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(out, "");
  EXPECT_EQ(settings["compile_time"]["debug_build"], true);  // the banner was there, and caught
}

// ... and from the command line, isolated (the run in a forked child) and not. stdout is a pipe,
// as when the JSON is piped on: the JSON array (written straight to /dev/stdout) and the table
// (stdio's buffer, flushed at exit), and nothing of Chipmunk's.
std::string cli_stdout_through_pipe(const std::string& args, int& status) {
  std::string out;
  FILE* p = ::popen((std::string(BALLBENCH_CLI) + " " + args + " 2>/dev/null").c_str(), "r");
  if (!p) return out;
  char buf[4096];
  for (size_t got; (got = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, got);
  const int rc = ::pclose(p);
  status = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
  return out;
}

TEST(ChipmunkAdapter, JsonOnStdoutIsClean) {
  for (const char* isolation : {"", " --no-isolation"}) {
    int status = -1;
    const std::string out = cli_stdout_through_pipe(
        std::string("run --scene seed-box --engine chipmunk --steps 50 --quiet --json /dev/stdout") + isolation, status);
    ASSERT_EQ(status, 0) << isolation << ": " << out;
    EXPECT_EQ(out.find("Initializing cpSpace"), std::string::npos) << out;
    EXPECT_EQ(out.find("Debug Enabled"), std::string::npos) << out;
    // The JSON value, read up to its end, then the table and nothing else.
    ASSERT_EQ(out.rfind("[", 0), 0u) << isolation << ": " << out;
    std::istringstream in(out);
    nlohmann::json parsed;
    ASSERT_NO_THROW(in >> parsed) << isolation << ": " << out;
    ASSERT_EQ(parsed.size(), 1u);  // the default profile, tuned
    EXPECT_EQ(parsed[0]["engine"], "chipmunk");
    EXPECT_EQ(parsed[0]["status"], "ok");
    std::string rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(rest.find("\nengine "), 0u) << rest;
    EXPECT_NE(rest.find("chipmunk/tuned     ok"), std::string::npos) << rest;
  }
}

// A failed Chipmunk assertion aborts the process: isolated, that is the run's "crashed" row. A
// ball whose mass is the smallest double has a moment (m r^2 / 2) that rounds to 0, and
// cpBodyUpdateVelocity asserts "Body's mass and moment must be positive to simulate".
TEST(ChipmunkAdapter, AFailedAssertionIsACrashedRun) {
  const Scene s = parse_scene(R"(
dt = 0.01
duration = 0.1
[[ball]]
pos = [0.0, 0.0]
vel = [1.0, 0.0]
radius = 0.25
mass = 5e-324
)",
                              "denormal-mass.toml");
  RunOptions o;
  o.profile = "stock";
  const Result r = run_engine_isolated(s, find_engine("chipmunk"), o, IsolationOptions{60, ""});
  EXPECT_EQ(r.status, RunStatus::crashed) << r.error;
  EXPECT_NE(r.error.find("SIGABRT"), std::string::npos) << r.error;
}

// The scene's friction coefficient and inertia, as the adapter maps them (its README), measured.
TEST(ChipmunkCalibration, FrictionAndInertiaAreTheScenes) { calibration::expect_friction_and_inertia_are_the_scenes("chipmunk"); }

}  // namespace
}  // namespace ballbench

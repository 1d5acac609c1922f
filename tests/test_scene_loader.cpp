// Scene files -> Scene: the schema, derived features, and one clear line for bad input.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>

#include "input_error.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

const char* kMinimal = R"(
name = "one"
dt = 0.01
duration = 1.0
[container]
kind = "box"
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [0.0, 0.0]
vel = [1.0, 0.0]
radius = 0.25
mass = 1.0
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  return s.replace(s.find(from), from.size(), to);
}

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneLoader, ReadsTheIssueSchema) {
  const Scene s = parse_scene(kMinimal, "s.toml");
  EXPECT_EQ(s.name, "one");
  EXPECT_EQ(s.n(), 1);
  EXPECT_EQ(s.steps(), 100);
  EXPECT_TRUE(s.features().walls);
  EXPECT_FALSE(s.features().gravity);
  EXPECT_TRUE(s.features().elastic);  // restitution defaults to 1
}

TEST(SceneLoader, RandomBallsAreReproducibleFromTheSeed) {
  const std::string text = std::string(kMinimal) + "[random]\ncount = 50\nradius = 0.1\nvel_max = [3.0, 3.0]\nseed = 7\n";
  const Scene a = parse_scene(text, "a.toml"), b = parse_scene(text, "b.toml");
  ASSERT_EQ(a.n(), 51);
  EXPECT_EQ(a.initial.pos, b.initial.pos);
  EXPECT_EQ(a.initial.vel, b.initial.vel);
  EXPECT_NE(a.initial.pos, parse_scene(text.substr(0, text.size() - 9) + "seed = 8\n", "c.toml").initial.pos);
}

TEST(SceneLoader, BuiltInSeedScenesMatchTheThesis) {
  const Scene box = load_scene("seed-box");
  EXPECT_EQ(box.n(), 20);
  EXPECT_DOUBLE_EQ(box.restitution, 0.99);
  EXPECT_TRUE((box.initial.vel.array() >= 0).all() && (box.initial.vel.array() < 25).all());
  const Scene bowl = load_scene("seed-bowl");
  EXPECT_EQ(bowl.n(), 72);
  EXPECT_DOUBLE_EQ(bowl.gravity.y(), -100.0);
  EXPECT_DOUBLE_EQ(bowl.initial.pos.col(0).minCoeff(), -4.6);
  EXPECT_NEAR(bowl.initial.pos.col(1).maxCoeff(), 0.2, 1e-12);
}

// The fuzzer's seeds (tests/fuzz/corpus/) are valid scenes: it starts from inputs that reach deep
// into the parser, and they stay in step with the format.
TEST(SceneLoader, FuzzSeedsAreValidScenes) {
  int seeds = 0;
  for (const auto& e : std::filesystem::directory_iterator(BALLBENCH_FUZZ_CORPUS)) {
    EXPECT_NO_THROW(load_scene_file(e.path().string())) << e.path();
    ++seeds;
  }
  EXPECT_GE(seeds, 3);
}

struct BadCase {
  const char* what;
  std::string text;
  const char* expected;  // a piece of the one-line message
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.what; }

TEST(SceneLoader, ReadsInertiaAndSpin) {
  const Scene plain = parse_scene(kMinimal, "s.toml");
  EXPECT_EQ(plain.inertia, Inertia::disk);
  EXPECT_FALSE(plain.features().rotation);
  EXPECT_FALSE(plain.initial.rotates());  // nothing about rotation is built for it

  const Scene spun = parse_scene(replace(replace(kMinimal, "mass = 1.0", "mass = 2.0\nspin = -3.5"), "duration = 1.0",
                                         "duration = 1.0\ninertia = \"sphere\""),
                                 "s.toml");
  EXPECT_EQ(spun.inertia, Inertia::sphere);
  EXPECT_TRUE(spun.features().rotation);
  ASSERT_TRUE(spun.initial.rotates());
  EXPECT_EQ(spun.spin(0), -3.5);
  EXPECT_EQ(spun.initial.angle(0), 0.0);
  EXPECT_DOUBLE_EQ(spun.moment_of_inertia(0), 0.4 * 2.0 * 0.25 * 0.25);

  // Friction alone makes a scene rotate, from rest.
  const Scene rough = parse_scene(replace(kMinimal, "duration = 1.0", "duration = 1.0\nfriction = 0.2"), "s.toml");
  EXPECT_TRUE(rough.features().rotation);
  ASSERT_TRUE(rough.initial.rotates());
  EXPECT_EQ(rough.spin(0), 0.0);
  EXPECT_DOUBLE_EQ(rough.moment_of_inertia(0), 0.5 * 0.25 * 0.25);
}

TEST(SceneLoader, RandomSpinsAreDrawnInTheirRangeWithoutMovingThePlacements) {
  const std::string base = std::string(kMinimal) + "[random]\ncount = 50\nradius = 0.1\nvel_min = [-1.0, -1.0]\nvel_max = [1.0, 1.0]\n";
  const Scene without = parse_scene(base, "s.toml");
  const Scene with = parse_scene(base + "spin_min = -2.0\nspin_max = 3.0\n", "s.toml");
  ASSERT_TRUE(with.initial.rotates());
  EXPECT_GE(with.initial.w.minCoeff(), -2.0);
  EXPECT_LT(with.initial.w.maxCoeff(), 3.0);
  EXPECT_LT(with.initial.w.minCoeff(), 0.0);  // the range is used, not one end of it
  EXPECT_GT(with.initial.w.maxCoeff(), 1.0);
  EXPECT_EQ(with.spin(0), 0.0);  // the explicit ball has none
  // The first drawn ball's position and velocity are drawn before its spin: the same.
  EXPECT_EQ(with.initial.pos.row(1), without.initial.pos.row(1));
  EXPECT_EQ(with.initial.vel.row(1), without.initial.vel.row(1));
}

class SceneLoaderRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneLoaderRejects, WithOneClearLine) {
  const std::string msg = error_of(GetParam().text);
  EXPECT_NE(msg.find(GetParam().expected), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_EQ(msg.rfind("s.toml:", 0), 0u) << msg;  // names the file first
}


INSTANTIATE_TEST_SUITE_P(
    BadInput, SceneLoaderRejects,
    ::testing::Values(
        BadCase{"syntax", replace(kMinimal, "dt = 0.01", "dt = = 0.01"), "TOML syntax error"},
        BadCase{"negative radius", replace(kMinimal, "radius = 0.25", "radius = -0.25"), "ball[0].radius: must be positive"},
        BadCase{"unknown key", replace(kMinimal, "duration", "duraton"), "did you mean 'duration'"},
        BadCase{"wrong type", replace(kMinimal, "dt = 0.01", "dt = \"fast\""), "dt: expected a number"},
        BadCase{"nan", replace(kMinimal, "dt = 0.01", "dt = nan"), "dt: must be finite"},
        BadCase{"zero dt", replace(kMinimal, "dt = 0.01", "dt = 0.0"), "dt: must be positive"},
        BadCase{"outside", replace(kMinimal, "pos = [0.0, 0.0]", "pos = [4.9, 0.0]"), "not inside the container"},
        BadCase{"overlap", std::string(kMinimal) + "[[ball]]\npos = [0.3, 0.0]\nradius = 0.25\n", "overlap at the start"},
        BadCase{"no balls", "dt = 0.1\nduration = 1.0\n", "no balls"},
        BadCase{"too full", std::string(kMinimal) + "[random]\ncount = 1000\nradius = 0.4\n", "fit without overlap"},
        // The audit's additions (issue 7): every kind of bad input has its case.
        BadCase{"empty file", "", "s.toml:1: scene: the file is empty"},
        BadCase{"only comments", "# a scene, one day\n\n", "the file is empty"},
        BadCase{"not UTF-8", "dt = \xff\xfe\n", "TOML syntax error"},
        BadCase{"duplicate key", replace(kMinimal, "dt = 0.01", "dt = 0.01\ndt = 0.02"), ":4: TOML syntax error"},
        BadCase{"ball is a number", "dt = 0.01\nduration = 1.0\nball = 3\n", ":3: ball: expected [[ball]] tables, got an integer"},
        BadCase{"ball is a single table", replace(kMinimal, "[[ball]]", "[ball]"), "got a single [ball] table"},
        BadCase{"ball array holds a number", "dt = 0.01\nduration = 1.0\nball = [{pos = [0.0, 0.0], radius = 0.1}, 3]\n",
                ":3: ball[1]: expected a table of pos, vel, radius, mass, got an integer"},
        BadCase{"ball array is empty", "dt = 0.01\nduration = 1.0\nball = []\n", ":3: ball: expected [[ball]] tables, got an empty array"},
        BadCase{"count overflows 64 bits", std::string(kMinimal) + "[random]\ncount = 99999999999999999999\nradius = 0.1\n",
                ":15: TOML syntax error"},
        BadCase{"count too large", std::string(kMinimal) + "[random]\ncount = 9223372036854775807\nradius = 0.1\n",
                "random.count: at most 50000000 balls"},
        BadCase{"count negative", std::string(kMinimal) + "[random]\ncount = -1\nradius = 0.1\n", "random.count: missing or negative"},
        BadCase{"count fractional", std::string(kMinimal) + "[random]\ncount = 2.5\nradius = 0.1\n",
                "random.count: expected an integer, got a number"},
        BadCase{"wrong type in vector", replace(kMinimal, "pos = [0.0, 0.0]", "pos = [0.0, \"up\"]"), "ball[0].pos[1]: expected a number, got a string"},
        BadCase{"vector of three", replace(kMinimal, "pos = [0.0, 0.0]", "pos = [0.0, 0.0, 0.0]"), "ball[0].pos: expected an array of two numbers"},
        BadCase{"wrong type bool", replace(kMinimal, "mass = 1.0", "mass = true"), "ball[0].mass: expected a number, got a boolean"},
        BadCase{"inf", replace(kMinimal, "duration = 1.0", "duration = inf"), "duration: must be finite"},
        BadCase{"nan in a vector", replace(kMinimal, "vel = [1.0, 0.0]", "vel = [nan, 0.0]"), "ball[0].vel[0]: must be finite"},
        BadCase{"negative inf gravity", replace(kMinimal, "duration = 1.0", "duration = 1.0\ngravity = [0.0, -inf]"), "gravity[1]: must be finite"},
        BadCase{"zero mass", replace(kMinimal, "mass = 1.0", "mass = 0.0"), "ball[0].mass: must be positive"},
        BadCase{"unknown inertia", replace(kMinimal, "dt = 0.01", "dt = 0.01\ninertia = \"sphear\""),
                "inertia: unknown inertia 'sphear' (use \"disk\", I = m r^2 / 2, or \"sphere\", I = 2/5 m r^2), did you mean 'sphere'?"},
        BadCase{"inertia a number", replace(kMinimal, "dt = 0.01", "dt = 0.01\ninertia = 0.5"), "inertia: expected a string"},
        BadCase{"huge spin", replace(kMinimal, "mass = 1.0", "mass = 1.0\nspin = 1e300"), "ball[0].spin: must be a finite angular velocity"},
        BadCase{"spin range reversed", std::string(kMinimal) + "[random]\ncount = 3\nradius = 0.1\nspin_min = 2.0\nspin_max = 1.0\n",
                "random.spin_min: must not exceed spin_max"},
        BadCase{"lattice spin nan", std::string(kMinimal) + "[lattice]\ncount = 3\nradius = 0.1\nspacing = 0.3\nspin_max = nan\n",
                "lattice.spin_max: must be finite"},
        BadCase{"negative dt", replace(kMinimal, "dt = 0.01", "dt = -0.01"), "dt: must be positive"},
        BadCase{"random zero radius", std::string(kMinimal) + "[random]\ncount = 3\nradius = 0.0\n", "random.radius: must be positive"},
        BadCase{"random negative mass", std::string(kMinimal) + "[random]\ncount = 3\nradius = 0.1\nmass = -2.0\n",
                "random.mass: must be positive"},
        BadCase{"huge coordinates", replace(replace(kMinimal, "min = [-5.0, -5.0]", "min = [-1e308, -5.0]"), "max = [5.0, 5.0]", "max = [1e308, 5.0]"),
                "container.min[0]: must be within +-1e+12"},
        BadCase{"huge radius", replace(kMinimal, "radius = 0.25", "radius = 1e300"), "ball[0].radius: must be at most 1e+12"},
        BadCase{"tiny radius far out", replace(replace(kMinimal, "radius = 0.25", "radius = 1e-9"), "pos = [0.0, 0.0]", "pos = [2.0, 0.0]"),
                "ball[0].pos: (2, 0) is more than 1e+09 radii"},
        BadCase{"radius too small for a contact", replace(kMinimal, "radius = 0.25", "radius = 1e-300"),
                "ball[0].radius: must be at least 1e-09 m, got 1e-300"},
        BadCase{"random radius too small", std::string(kMinimal) + "[random]\ncount = 1\nradius = 1e-10\n",
                "random.radius: must be at least 1e-09 m"},
        BadCase{"random radius larger than the box", std::string(kMinimal) + "[random]\ncount = 1\nradius = 6.0\n",
                "random.radius: balls of radius 6 do not fit in the 10 x 10 container"},
        BadCase{"ball outside below", replace(kMinimal, "pos = [0.0, 0.0]", "pos = [0.0, -4.8]"), "ball[0].pos: ball at (0, -4.8) with radius 0.25 is not inside"},
        BadCase{"unknown key in a ball", replace(kMinimal, "radius = 0.25", "raduis = 0.25"), "ball[0].raduis: unknown key, did you mean 'radius'?"},
        BadCase{"unknown key in random", std::string(kMinimal) + "[random]\ncount = 1\nradius = 0.1\nsede = 3\n", "random.sede: unknown key, did you mean 'seed'?"},
        BadCase{"unknown key in container", replace(kMinimal, "kind = \"box\"", "knd = \"box\""), "container.knd: unknown key, did you mean 'kind'?"},
        BadCase{"unknown container kind", replace(kMinimal, "kind = \"box\"", "kind = \"bx\""), "did you mean 'box'?"},
        BadCase{"container not a table", "dt = 0.01\nduration = 1.0\ncontainer = 3\n", "container: expected a table [container]"},
        BadCase{"random not a table", "dt = 0.01\nduration = 1.0\nrandom = [1]\n", "random: expected a table [random] or tables [[random]]"},
        BadCase{"settings not a table", std::string(kMinimal) + "[settings]\nhome = 3\n", "settings.home: expected a table of settings"},
        BadCase{"setting of a wrong type", std::string(kMinimal) + "[settings.home]\ncontact_iterations = [1]\n",
                "settings.home.contact_iterations: expected a number, string or boolean"},
        BadCase{"too many steps", replace(kMinimal, "dt = 0.01", "dt = 1e-12"), "duration: duration / dt is more than"},
        BadCase{"restitution above 1", replace(kMinimal, "duration = 1.0", "duration = 1.0\nrestitution = 1.5"), "restitution: must be in [0, 1]"},
        BadCase{"newline in a key", replace(kMinimal, "duration", "\"dura\\ntion\""), "dura\\ntion: unknown key"},
        BadCase{"name not a string", replace(kMinimal, "name = \"one\"", "name = 1"), "name: expected a string, got an integer"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      std::string name = info.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

}  // namespace
}  // namespace ballbench

// Scene files -> Scene: the schema, derived features, and one clear line for bad input.
#include <gtest/gtest.h>

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

struct BadCase {
  const char* what;
  std::string text;
  const char* expected;  // a piece of the one-line message
};

class SceneLoaderRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneLoaderRejects, WithOneClearLine) {
  const std::string msg = error_of(GetParam().text);
  EXPECT_NE(msg.find(GetParam().expected), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_EQ(msg.rfind("s.toml:", 0), 0u) << msg;  // names the file first
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  return s.replace(s.find(from), from.size(), to);
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
        BadCase{"too full", std::string(kMinimal) + "[random]\ncount = 1000\nradius = 0.4\n", "fit without overlap"}));

}  // namespace
}  // namespace ballbench

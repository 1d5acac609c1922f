// The `ballbench` command as a user meets it: bad input gets one clear line on stderr and a
// non-zero exit, never a crash; the scene schema from the README runs unchanged.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct Outcome {
  int status;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Outcome cli(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string out = (dir / "ballbench_cli_out.txt").string(), err = (dir / "ballbench_cli_err.txt").string();
  const int rc = std::system((std::string(BALLBENCH_CLI) + " " + args + " >" + out + " 2>" + err).c_str());
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc), slurp(out), slurp(err)};
}

std::string write_scene(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

// The schema example from the README and scenarios/README.md, verbatim.
const char* kSchemaExample = R"(name = "seed-box"
dt = 0.01            # step size, seconds
duration = 30.0      # simulated seconds
gravity = [0.0, 0.0]
restitution = 0.99   # ball-ball and ball-wall
friction = 0.0
[container]          # kind = "box" (axis-aligned, min/max) or "none" (open space)
kind = "box"
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]             # explicit balls: pos, vel, radius, mass
pos = [0.0, 0.0]
vel = [1.0, 0.0]
radius = 0.25
mass = 1.0
[random]             # generated balls, reproducible from seed
count = 20
radius = 0.25
mass = 1.0
pos_min = [-3.5, -3.5]
pos_max = [3.5, 3.5]
vel_min = [0.0, 0.0]
vel_max = [25.0, 25.0]
seed = 1
)";

void expect_one_line_error(const Outcome& o, const std::string& fragment) {
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find(fragment), std::string::npos) << o.err;
  ASSERT_FALSE(o.err.empty());
  EXPECT_EQ(o.err.find('\n'), o.err.size() - 1) << "more than one line: " << o.err;
}

TEST(Cli, MissingSceneFile) {
  expect_one_line_error(cli("run --scene /nonexistent/x.toml --engine home"), "/nonexistent/x.toml: scene file not found");
}

TEST(Cli, TomlSyntaxErrorNamesFileAndLine) {
  const std::string p = write_scene("bb_syntax.toml", "dt = 0.01\nduration = [1.0\n");
  expect_one_line_error(cli("run --scene " + p + " --engine home"), p + ":2: TOML syntax error");
}

TEST(Cli, NegativeRadiusNamesTheField) {
  std::string text = kSchemaExample;
  text.replace(text.find("radius = 0.25"), 13, "radius = -0.25");
  const std::string p = write_scene("bb_radius.toml", text);
  expect_one_line_error(cli("run --scene " + p + " --engine home"), p + ":14: ball[0].radius: must be positive");
}

TEST(Cli, UnknownEngineSuggestsTheClosest) {
  expect_one_line_error(cli("run --scene seed-box --engine hom"), "unknown engine 'hom', did you mean 'home'?");
}

TEST(Cli, UnknownSceneListsTheBuiltIns) {
  expect_one_line_error(cli("run --scene seed-boxx --engine home"), "did you mean 'seed-box'?");
}

TEST(Cli, ContradictoryFlags) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 5 --duration 1"), "excludes");
}

TEST(Cli, UnknownSetting) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 1 --set home.iterations=3"),
                        "settings.home.iterations: unknown setting");
}

TEST(Cli, TheSchemaExampleRunsUnchanged) {
  const std::string p = write_scene("bb_schema.toml", kSchemaExample);
  const Outcome o = cli("run --scene " + p + " --engine home-seed,home --steps 200 --quiet");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("home-seed"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\nhome "), std::string::npos) << o.out;
}

TEST(Cli, ListShowsScenesAndEnginesWithVersions) {
  const Outcome o = cli("list");
  EXPECT_EQ(o.status, 0);
  EXPECT_NE(o.out.find("seed-bowl"), std::string::npos);
  EXPECT_NE(o.out.find("home-seed    thesis-2017"), std::string::npos) << o.out;
}

}  // namespace

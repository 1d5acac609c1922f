// The `ballbench` command as a user meets it: bad input gets one clear line on stderr and a
// non-zero exit, never a crash; the scene schema from the README runs unchanged.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace {

using Outcome = ballbench::testing::CliOutcome;
using ballbench::testing::expect_one_line_error;
using ballbench::testing::Scratch;
using ballbench::testing::slurp;
const auto cli = ballbench::testing::run_cli;

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

// Every command takes --quiet: none refuses it as an unknown option (the bad input after it is what
// each one reports).
TEST(Cli, EveryCommandTakesQuiet) {
  EXPECT_EQ(cli("list --quiet").status, 0);
  for (const char* command : {"run --scene no-such-scene --engine home", "report --engine no-such-engine",
                              "sweep --scene no-such-scene --engine home", "stress --scene no-such-scene --engine home",
                              "match --scene no-such-scene --engine home", "merge --out x no-such-shard.json",
                              "view no-such-run.json", "regress --baseline no-such-baseline.json",
                              "settle --scene no-such-scene --out x.toml", "conform --engine no-such-engine"}) {
    const Outcome o = cli(std::string(command) + " --quiet");
    EXPECT_EQ(o.status, 2) << command << ": " << o.err;
    EXPECT_EQ(o.err.find("--quiet"), std::string::npos) << command << ": " << o.err;
  }
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

// A run says whether each row meets the spec its scene asks for (here with --spec over it), as
// `match` judges a try: the line match prints for a configuration it found shows it met.
TEST(Cli, ARunSaysWhetherEachRowMeetsTheScenesSpec) {
  const Outcome o = cli("run --scene pile --engine home-seed,home --steps 100 --no-reference --spec overlap=0.01,rest_speed=none --quiet");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("spec: overlap <= 0.01, tunnelling <= 0\n"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\n  home: met (overlap "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\n  home-seed: not met: overlap "), std::string::npos) << o.out;
}

// The audit's additions (issue 7): files that cannot be read as scenes, names that do not exist,
// flags that contradict each other.

TEST(Cli, UnreadableSceneFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads files without read permission";
  const std::string p = write_scene("bb_unreadable.toml", kSchemaExample);
  std::filesystem::permissions(p, std::filesystem::perms::none);
  const Outcome o = cli("run --scene " + p + " --engine home");
  std::filesystem::permissions(p, std::filesystem::perms::owner_all);
  expect_one_line_error(o, p + ": cannot read the scene file: Permission denied");
}

TEST(Cli, DirectoryAsSceneFile) {
  const auto dir = std::filesystem::temp_directory_path() / "bb_dir.toml";
  std::filesystem::create_directories(dir);
  expect_one_line_error(cli("run --scene " + dir.string() + " --engine home"), "is a directory, not a scene file");
}

TEST(Cli, EmptySceneFile) {
  const std::string p = write_scene("bb_empty.toml", "");
  expect_one_line_error(cli("run --scene " + p + " --engine home"), p + ":1: scene: the file is empty");
}

TEST(Cli, UnknownEngineInTheScenesSettings) {
  std::string text = kSchemaExample;
  text += "[settings.hom]\ncontact_iterations = 4\n";
  const std::string p = write_scene("bb_settings_engine.toml", text);
  expect_one_line_error(cli("run --scene " + p + " --engine home --steps 1"),
                        p + ": settings.hom: unknown engine 'hom', did you mean 'home'?");
}

TEST(Cli, UnknownEngineInSet) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 1 --set hme.contact_iterations=3"),
                        "unknown engine 'hme', did you mean 'home'?");
}

TEST(Cli, EngineNamedTwice) { expect_one_line_error(cli("run --scene seed-box --engine home,home"), "named twice"); }

// A setting or a stress knob given twice is one line, not the last one silently winning or a
// frontier run twice.
TEST(Cli, SettingOrKnobGivenTwice) {
  expect_one_line_error(cli("run --scene seed-box --engine home --set home.resting=soft --set home.resting=events"),
                        "--set home.resting: set twice");
  expect_one_line_error(cli("stress --scene seed-box --engine home --knobs dt,dt"), "--knobs: 'dt' is named twice");
}

TEST(Cli, UnknownProfile) {
  expect_one_line_error(cli("run --scene seed-box --engine home --profile tunde"), "no selected engine has a profile 'tunde'");
}

TEST(Cli, NoIsolationContradictsATimeout) {
  expect_one_line_error(cli("run --scene seed-box --engine home --no-isolation --timeout 5"), "excludes");
}

TEST(Cli, TimeoutMustBePositive) {
  expect_one_line_error(cli("run --scene seed-box --engine home --timeout 0"), "--timeout");
  expect_one_line_error(cli("run --scene seed-box --engine home --timeout soon"), "--timeout");
}

TEST(Cli, NegativeStepsAndDt) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps -3"), "--steps");
  expect_one_line_error(cli("run --scene seed-box --engine home --dt -0.1"), "--dt");
}

// Numbers that parse but mean nothing: NaN, infinity, zero where a positive size is needed, no
// step at all, and whole numbers out of an int's range. Each is one line naming the flag and the
// value, across the commands that take such flags.
TEST(Cli, NonFiniteAndZeroNumbersAreRefused) {
  for (const char* args : {"run --scene seed-box --engine home --dt nan", "run --scene seed-box --engine home --dt inf",
                           "run --scene seed-box --engine home --duration nan",
                           "run --scene seed-box --engine home --duration -inf",
                           "run --scene seed-box --engine home --timeout nan",
                           "sweep --scene seed-box --engine home --horizon nan",
                           "stress --scene seed-box --engine home --energy-tolerance nan"})
    expect_one_line_error(cli(args), "must be a finite number");
  const Outcome zero = cli("run --scene seed-box --engine home --dt 0");
  expect_one_line_error(zero, "must be > 0, got '0'");
  EXPECT_LT(zero.err.size(), 200u) << zero.err;  // no range printed with DBL_MAX's digits
}

TEST(Cli, RunsOfNoStepAreRefused) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 0"), "--steps: must be >= 1");
  expect_one_line_error(cli("run --scene seed-box --engine home --duration 0.001"), "no step to run");
  expect_one_line_error(cli("run --scene seed-box --engine home --sample-every 0"), "--sample-every");
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 5e3"), "expected a whole number");
}

TEST(Cli, IntegerSettingsDoNotWrap) {
  // 2^32 + 1 would become 1 in a 32-bit int.
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set home.contact_iterations=4294967297"),
                        "out of range");
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set home.substeps=-4294967295"),
                        "out of range");
  // A whole number written as a float is that number: its range is what is wrong, not its form.
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set home.substeps=1e12"), "out of range");
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set home.substeps=2.5"),
                        "expected a whole number");
  EXPECT_EQ(cli("run --scene seed-box --engine home --no-reference --steps 2 --set home.substeps=8.0").status, 0);
}

TEST(Cli, FrictionIsRefusedByEnginesWithoutRotation) {
  // home-seed (the thesis's algorithm) has no rotation: friction would be ignored with status ok.
  // It is reported unsupported, with the reason; the engines with friction run.
  const std::string scene = write_scene("ballbench_friction.toml", R"(dt = 0.01
duration = 0.1
gravity = [0.0, -9.81]
friction = 0.5
[container]
min = [-5.0, 0.0]
max = [5.0, 5.0]
[[ball]]
pos = [0.0, 0.25]
vel = [3.0, 0.0]
radius = 0.25
)");
  const Outcome o = cli("run --quiet --no-reference --scene " + scene + " --engine home,exact,home-seed,box2d");
  EXPECT_EQ(o.status, 0) << o.err;
  // Each engine's own row of the table.
  const auto row = [&](const std::string& engine) {
    const size_t at = o.out.find("\n" + engine + " ");
    if (at == std::string::npos) return std::string();
    return o.out.substr(at + 1, o.out.find('\n', at + 1) - at - 1);
  };
  EXPECT_NE(row("home-seed").find("unsupported"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("it needs friction"), std::string::npos) << o.out;
  for (const char* engine : {"home", "exact", "box2d/tuned"}) EXPECT_NE(row(engine).find(" ok "), std::string::npos) << o.out;
}

// A count that is not a whole number says so, with the range it must be in (CLI11's own check
// said "not in range" of 1.5, which is in range).
TEST(Cli, ACountThatIsNotWholeSaysSo) {
  for (const char* value : {"1.5", "0x3", "21"})
    expect_one_line_error(cli(std::string("match --scene seed-box --engine home --max-halvings ") + value),
                          std::string("--max-halvings: expected a whole number from 0 to 20, got '") + value + "'");
}

TEST(Cli, SettingsOfEnginesNotRunAreCheckedToo) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set box2d.bogus=1"), "settings.box2d.bogus");
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set xyz.a=1"), "--set xyz.KEY: unknown engine");
  // A spec term the scene cannot measure: refused before any run, naming the fix.
  expect_one_line_error(cli("run --scene pile --engine home --steps 2 --spec rolling=0.01"),
                        "--spec rolling: pile has no rolling closed form");
  // A setting valid for an engine the run does not run would change nothing: refused, not ignored.
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set box2d.velocity_iterations=4"),
                        "--set box2d.velocity_iterations: box2d is not among --engine (home)");
  // A misspelling in the scene file is named by FILE:LINE (the schema example has 24 lines).
  const std::string scene = write_scene("ballbench_bad_setting.toml", std::string(kSchemaExample) + "[settings.ode]\nbogus = 1\n");
  expect_one_line_error(cli("run --scene " + scene + " --engine home --steps 2"), scene + ":26: settings.ode.bogus");
  const std::string value = write_scene("ballbench_bad_value.toml", std::string(kSchemaExample) + "[settings.home]\nsubsteps = 0\n");
  expect_one_line_error(cli("run --scene " + value + " --engine home --steps 2"), value + ":26: settings.home.substeps");
}

// Outputs are checked before the first run, and a FIFO or a device is written into, not replaced.
TEST(Cli, OutputsAreCheckedBeforeRunningAndNeverClobberWhatTheyShouldNot) {
  const std::string scene = write_scene("ballbench_outputs.toml", kSchemaExample);
  const std::string before = slurp(scene);
  expect_one_line_error(cli("run --quiet --scene " + scene + " --engine home --steps 2 --json " + scene),
                        "--json " + scene + ": same file as --scene " + scene);
  EXPECT_EQ(slurp(scene), before);
  const auto dir = std::filesystem::temp_directory_path();
  const std::string same = (dir / "ballbench_same.out").string();
  expect_one_line_error(cli("run --quiet --scene seed-box --engine home --steps 2 --json " + same + " --trajectory " + same),
                        "--trajectory " + same + ": same file as --json " + same);
  expect_one_line_error(cli("run --quiet --scene seed-box --engine home --steps 2 --json /proc/no/such/x.json"),
                        "cannot write the results there");
  expect_one_line_error(cli("run --quiet --scene seed-box --engine home --steps 2 --json " + dir.string()), "is a folder");
  const Outcome null_out = cli("run --quiet --scene seed-box --engine home --steps 2 --json /dev/null --trajectory /dev/null");
  EXPECT_EQ(null_out.status, 0) << null_out.err;
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  const std::string fifo = (dir / ("ballbench_fifo." + std::to_string(::getpid()))).string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string read_back;
  std::thread reader([&] { read_back = slurp(fifo); });
  const Outcome o = cli("run --quiet --scene seed-box --engine home --steps 2 --json " + fifo);
  reader.join();
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_NE(read_back.find("\"checksum\""), std::string::npos) << read_back;
  std::filesystem::remove(fifo);
  // A link (as /dev/stdout is) is written through: the link stays, its target gets the results.
  const std::string target = (dir / ("ballbench_link_target." + std::to_string(::getpid()))).string();
  const std::string link = target + ".link";
  std::ofstream(target) << "old";
  std::filesystem::create_symlink(target, link);
  const Outcome linked = cli("run --quiet --scene seed-box --engine home --steps 2 --json " + link);
  EXPECT_EQ(linked.status, 0) << linked.err;
  EXPECT_TRUE(std::filesystem::is_symlink(link)) << "the link was replaced by a file";
  EXPECT_NE(slurp(target).find("\"checksum\""), std::string::npos);
  std::filesystem::remove(link), std::filesystem::remove(target);
}

TEST(Cli, SceneNamesCannotLeaveTheWorkingFolder) {
  const std::string scene = write_scene("ballbench_dotdot.toml", std::string("name = \"../escape\"\n") + (kSchemaExample + 18));
  expect_one_line_error(cli("run --scene " + scene + " --engine home --steps 2"), "name: '../escape' cannot name a file");
}

TEST(Cli, LatticeColumnsMustBePositive) {
  const std::string scene = write_scene("ballbench_columns.toml", R"(dt = 0.01
duration = 0.1
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[lattice]
count = 4
radius = 0.25
spacing = 0.6
columns = 0
)");
  expect_one_line_error(cli("run --scene " + scene + " --engine home --steps 2"), "columns: must be at least 1");
}

TEST(Cli, ABallThatLeavesTheBoxEndsTheRun) {
  // Under 1e9 m/s^2 the thesis's algorithm drops every ball through the floor in one step; the
  // energy check alone (100 x the start) did not see it, and the run said ok.
  const std::string scene = write_scene("ballbench_g1e9.toml", R"(dt = 0.01
duration = 0.5
gravity = [0.0, -1e9]
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [0.0, 0.0]
radius = 0.25
)");
  const Outcome o = cli("run --quiet --no-reference --scene " + scene + " --engine home-seed,home");
  EXPECT_NE(o.out.find("home-seed          diverged"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("a ball left the container (beyond a wall by more than its diameter) at step 1"), std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("home               ok"), std::string::npos) << o.out;
  EXPECT_EQ(o.status, 1);  // a row that did not run to a result
  const Outcome ok = cli("run --quiet --no-reference --scene " + scene + " --engine home");
  EXPECT_EQ(ok.status, 0) << ok.out;
}

// SIGINT (the terminal's Ctrl-C, to the whole process group) or SIGTERM (to ballbench alone) during
// a run: the rows done so far and the interrupted one are printed and written, marked, no
// temporary file is left, one line says so, and the exit status is 128 + the signal.
TEST(Cli, AnInterruptKeepsTheRowsDoneAndLeavesNothingBehind) {
  const auto dir = std::filesystem::temp_directory_path() / ("ballbench_interrupt." + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const auto& [signal, status] : {std::pair{"INT", 130}, {"TERM", 143}, {"HUP", 129}}) {
    const std::string json = (dir / "r.json").string(), csv = (dir / "t.csv").string();
    const std::string out = (dir / "out").string(), err = (dir / "err").string();
    // home-seed's row is short; home's event path on the pile takes minutes: the signal lands in it
    // (or, on a slow machine, in home-seed's; either way in a run).
    const std::string cmd = std::string("timeout --preserve-status -s ") + signal + " 5 " + BALLBENCH_CLI +
                            " run --quiet --scene pile --engine home-seed,home --json " + json + " --trajectory " + csv +
                            " >" + out + " 2>" + err;
    const int rc = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(rc));
    EXPECT_EQ(WEXITSTATUS(rc), status) << slurp(err);
    EXPECT_NE(slurp(out).find("interrupted"), std::string::npos) << slurp(out);
    const std::string e = slurp(err);
    EXPECT_NE(e.find(std::string("interrupted by SIG") + signal), std::string::npos) << e;
    EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 1) << e;
    const std::string results = slurp(json);
    EXPECT_NE(results.find("\"status\": \"interrupted\""), std::string::npos) << results.substr(0, 300);
    // The row names the signal that came, not another.
    EXPECT_NE(results.find(std::string("interrupted by SIG") + signal), std::string::npos) << results.substr(0, 2000);
    EXPECT_EQ(slurp(csv).rfind("engine,profile,step,t,id,x,y,vx,vy\n", 0), 0u);
    for (const auto& f : std::filesystem::directory_iterator(dir)) {
      const std::string name = f.path().filename().string();
      EXPECT_TRUE(name == "r.json" || name == "t.csv" || name == "out" || name == "err") << "left behind: " << name;
    }
  }
  std::filesystem::remove_all(dir);
}

// The same for the commands that make many runs: sweep, stress and report write what they finished
// and the run in progress, marked, say so in one line, exit 128 + the signal, and a report does not
// render REPORT.md from a part that was cut short.
TEST(Cli, SweepStressAndReportKeepWhatTheyFinishedWhenInterrupted) {
  const auto dir = std::filesystem::temp_directory_path() / ("ballbench_interrupt_many." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string d = dir.string();
  struct Case {
    std::string args, written;
    int after_s;  // the signal's
  };
  // home's event path on the pile takes minutes a run, so the signal lands in a run; the report's
  // first table takes 5 s idle, so its signal lands in that table.
  const std::vector<Case> cases = {
      {"sweep --quiet --scene pile --engine home --no-knobs --horizon 4 --repeats 1 --json " + d + "/s.json", d + "/s.json", 6},
      {"stress --quiet --scene pile --engine home --knobs dt --json " + d + "/f.json", d + "/f.json", 6},
      {"report --no-bench --out " + d + "/report", d + "/report/results", 2},
  };
  for (const Case& c : cases) {
    const std::string err = d + "/err";
    const std::string cmd = fmt::format("timeout --preserve-status -s INT {} ", c.after_s) + BALLBENCH_CLI + " " +
                            c.args + " >/dev/null 2>" + err;
    const int rc = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(rc)) << c.args;
    EXPECT_EQ(WEXITSTATUS(rc), 130) << c.args << ": " << slurp(err);
    const std::string e = slurp(err);
    EXPECT_NE(e.find("ballbench: interrupted by SIGINT: "), std::string::npos) << c.args << ": " << e;
    std::string written;
    if (std::filesystem::is_directory(c.written)) {
      for (const auto& f : std::filesystem::directory_iterator(c.written)) written += slurp(f.path().string());
      EXPECT_FALSE(std::filesystem::exists(d + "/report/REPORT.md"));
    } else {
      written = slurp(c.written);
    }
    EXPECT_NE(written.find("interrupted"), std::string::npos) << c.args << ": " << written.substr(0, 300);
  }
  std::filesystem::remove_all(dir);
}

TEST(Cli, AnOversizedTrajectoryIsRefusedWithItsEstimate) {
  // 9 runs x 3 000 001 states x 20 balls, ~59 GB at 110 bytes a row: refused under a 1 GB limit.
  const std::string csv = (std::filesystem::temp_directory_path() / "ballbench_big.csv").string();
  expect_one_line_error(cli("run --scene seed-box --engine all --profile all --steps 3000000 --trajectory " + csv +
                            " --trajectory-limit-gb 1"),
                        "above --trajectory-limit-gb 1");
  EXPECT_FALSE(std::filesystem::exists(csv));
}

TEST(Cli, AReportFolderThatCannotBeWrittenIsOneLineBeforeAnyRun) {
  // A regular file where the folder should be (root writes into read-only folders, so this is the
  // case a test can make fail for every user).
  const std::string file = write_scene("ballbench_not_a_folder", "x");
  const Outcome o = cli("report --out " + file + "/out --no-bench");
  expect_one_line_error(o, "cannot write the report's files there");
  EXPECT_EQ(o.err.find("ran "), std::string::npos) << o.err;
}

// Rendering a folder that holds no report's results (none yet, or a run record that is not one) is
// one line, not a crash.
TEST(Cli, RenderingWithoutAReportsResultsIsOneLine) {
  const auto dir = std::filesystem::temp_directory_path() / ("bb_render_empty." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  expect_one_line_error(cli("report --out " + dir.string() + " --render-only"), "no run.json");
  std::ofstream(dir / "results" / "run.json") << "[1, 2]";
  expect_one_line_error(cli("report --out " + dir.string() + " --render-only"), "not a report's run record");
  std::filesystem::remove_all(dir);
}

// A benchmark process that fails leaves its part out, says so, and the parts that ran stand: a
// stand-in step benchmark whose gas filter writes one row and whose other filters fail.
TEST(Cli, AFailedBenchmarkPartLeavesTheOthersStanding) {
  const auto dir = std::filesystem::temp_directory_path() / ("bb_bench_parts." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "bin");
  const auto bin = dir / "bin" / "ballbench_step_benchmark";
  std::ofstream(bin) << R"(#!/bin/sh
for a in "$@"; do
  case "$a" in
    --benchmark_filter=*) filter="${a#--benchmark_filter=}" ;;
    --benchmark_out=*) out="${a#--benchmark_out=}" ;;
  esac
done
case "$filter" in
  *gas*) printf '{"context": {}, "benchmarks": [{"name": "step/home/default/gas/1000", "run_type": "iteration", "ns_per_ball_step": 24.0}]}' > "$out" ;;
  *none*) ;;
  *) exit 3 ;;
esac
)";
  std::filesystem::permissions(bin, std::filesystem::perms::owner_all);
  // One small table and the benchmark parts: what the test is about, in seconds.
  const auto suites = dir / "suites.toml";
  std::ofstream(suites) << "[quick]\nscenes = [\"two-ball-1\"]\nmatch_scenes = []\nsweep_scenes = []\n"
                           "stress_scenes = []\nbench_filters = [\"^step/home/default/gas/1000$\", \"^pipe/\", \"^none/\"]\n";
  const Outcome o = cli("report --out " + (dir / "out").string() + " --engine home --suites " + suites.string() +
                        " --bench-binary " + bin.string());
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find("scaling: part skipped: " + bin.string() + " --benchmark_filter='^pipe/': it failed (exit status 3)"),
            std::string::npos)
      << o.err;
  // A filter that matches nothing: Google Benchmark writes nothing and exits 0.
  EXPECT_NE(o.err.find("--benchmark_filter='^none/': no benchmark matched it"), std::string::npos) << o.err;
  const std::string bench = slurp((dir / "out" / "results" / "bench.json").string());
  EXPECT_NE(bench.find("step/home/default/gas/1000"), std::string::npos) << bench;
  EXPECT_NE(slurp((dir / "out" / "pages" / "scaling.md").string()).find("## Scaling"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Cli, FreshContradictsRenderOnly) {
  expect_one_line_error(cli("report --out /tmp/bb_never --fresh --render-only"), "excludes");
  expect_one_line_error(cli("report --out /tmp/bb_never --quick --full"), "excludes");
  expect_one_line_error(cli("report --out /tmp/bb_never --bench-binary /nonexistent"),
                        "--bench-binary /nonexistent: not an executable file");
  expect_one_line_error(cli("report --out /tmp/bb_never --bench-binary /bin/true --no-bench"), "excludes");
  expect_one_line_error(cli("run --scene seed-box --engine home --sample-every 0"), "sample-every");
}

TEST(Cli, UnwritableTrajectory) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 1 --trajectory /nonexistent/dir/t.csv"),
                        "--trajectory /nonexistent/dir/t.csv: cannot write the trajectory there");
}

// With isolation (the default) and without, `run` prints the same numbers and the JSON carries
// the same checksums; the trajectory CSV has one header and every run's rows.
TEST(Cli, IsolatedAndInProcessRunsAgree) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string j1 = (dir / "bb_iso1.json").string(), j2 = (dir / "bb_iso2.json").string();
  const std::string c1 = (dir / "bb_iso1.csv").string(), c2 = (dir / "bb_iso2.csv").string();
  const std::string args = "run --scene seed-box --engine home-seed,home --steps 50 --quiet ";
  const Outcome a = cli(args + "--json " + j1 + " --trajectory " + c1);
  const Outcome b = cli(args + "--no-isolation --json " + j2 + " --trajectory " + c2);
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  const std::string ja = slurp(j1), jb = slurp(j2);
  for (const std::string& j : {ja, jb}) EXPECT_NE(j.find("\"checksum\""), std::string::npos);
  auto checksums = [](const std::string& json) {
    std::string out;
    for (size_t at = json.find("\"trajectory\": \""); at != std::string::npos; at = json.find("\"trajectory\": \"", at + 1))
      out += json.substr(at, 32) + ";";
    return out;
  };
  EXPECT_EQ(checksums(ja), checksums(jb));
  EXPECT_EQ(slurp(c1), slurp(c2));
  const std::string csv = slurp(c1);
  EXPECT_EQ(csv.rfind("engine,profile,step,t,id,x,y,vx,vy\n", 0), 0u);
  EXPECT_EQ(csv.find("engine,", 1), std::string::npos);  // one header
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 51 * 20);
}

TEST(Cli, ListShowsScenesAndEnginesWithVersions) {
  const Outcome o = cli("list");
  EXPECT_EQ(o.status, 0);
  EXPECT_NE(o.out.find("seed-bowl"), std::string::npos);
  EXPECT_NE(o.out.find("home-seed    thesis-2017    thesis"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("box2d        2.4.1          external"), std::string::npos) << o.out;
}

// The names in a folder, sorted.
std::vector<std::string> names_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Every output is compared with every input and every other output before anything runs, by
// device and inode (or resolved path): another spelling, a symbolic or a hard link is the same file.
TEST(Cli, OutputsOntoInputsOrEachOtherAreRefusedHoweverSpelled) {
  const Scratch s("bb_clash");
  const std::string d = s.dir.string(), scene = s / "scene.toml";
  std::ofstream(scene) << kSchemaExample;
  std::filesystem::create_directories(s / "sub");
  const std::string run = "run --quiet --scene seed-box --engine home --steps 2 --no-reference ";
  expect_one_line_error(cli(run + "--json " + d + "/./a.json --trajectory " + d + "/a.json"),
                        "--trajectory " + d + "/a.json: same file as --json " + d + "/./a.json");
  expect_one_line_error(cli(run + "--json " + d + "/sub/../a.json --trajectory " + d + "/a.json"),
                        "same file as --json " + d + "/sub/../a.json");
  EXPECT_FALSE(std::filesystem::exists(s / "a.json"));
  const std::string before = slurp(scene);
  std::filesystem::create_symlink(scene, s / "link.json");
  std::filesystem::create_hard_link(scene, s / "hard.csv");
  const std::string own = "run --quiet --scene " + scene + " --engine home --steps 2 --no-reference ";
  expect_one_line_error(cli(own + "--json " + s / "link.json"), "--json " + s / "link.json" + ": same file as --scene " + scene);
  expect_one_line_error(cli(own + "--trajectory " + s / "hard.csv"), "same file as --scene " + scene);
  expect_one_line_error(cli("stress --quiet --scene " + scene + " --engine home --json " + d + "/./scene.toml"),
                        "--json " + d + "/./scene.toml: same file as --scene " + scene);
  EXPECT_EQ(slurp(scene), before);
  // The engines file given to the whole command.
  std::ofstream(s / "engines.toml") << "# no engines\n";
  expect_one_line_error(cli("run --engines " + s / "engines.toml" + " --quiet --scene seed-box --engine home --steps 2 --json " +
                            d + "/./engines.toml"),
                        "--json " + d + "/./engines.toml: same file as --engines " + s / "engines.toml");
  EXPECT_EQ(slurp(s / "engines.toml"), "# no engines\n");
  // view, sweep and merge.
  ASSERT_EQ(cli(run + "--frames 2 --json " + s / "r.json").status, 0);
  std::filesystem::copy_file(s / "r.json", s / "r2.json");
  const std::string results = slurp(s / "r.json");
  expect_one_line_error(cli("view " + s / "r.json" + " --out " + d + "/./r.json"),
                        "--out " + d + "/./r.json: same file as RESULTS " + s / "r.json");
  expect_one_line_error(cli("sweep --quiet --scene seed-box --engine home --json " + s / "s.json" + " --csv " + d +
                            "/sub/../s.json"),
                        "--csv " + d + "/sub/../s.json: same file as --json " + s / "s.json");
  expect_one_line_error(cli("merge " + s / "r.json" + " " + s / "r2.json" + " --out " + s / "r2.json"),
                        "--out " + s / "r2.json" + ": same file as SHARD " + s / "r2.json");
  EXPECT_EQ(slurp(s / "r.json"), results);
  EXPECT_EQ(slurp(s / "r2.json"), results);
  // No file at all, or a folder, is refused before the run, not after it.
  expect_one_line_error(cli(run + "--json ''"), "empty path");
  expect_one_line_error(cli(run + "--json " + d + "/out/"), "is a folder");
  expect_one_line_error(cli(run + "--trajectory " + d), "is a folder");
  EXPECT_FALSE(std::filesystem::exists(s / "out"));
  // A user's own FILE.tmp is not ours to overwrite; and nothing of ours is left.
  std::ofstream(s / "out.json.tmp") << "mine";
  std::ofstream(s / "out.csv.tmp") << "mine too";
  const auto listed = names_in(s.dir);
  const Outcome ok = cli(run + "--json " + s / "out.json" + " --trajectory " + s / "out.csv");
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(slurp(s / "out.json.tmp"), "mine");
  EXPECT_EQ(slurp(s / "out.csv.tmp"), "mine too");
  EXPECT_NE(slurp(s / "out.json").find("\"checksum\""), std::string::npos);
  auto expected = listed;
  expected.push_back("out.csv"), expected.push_back("out.json");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names_in(s.dir), expected);
}

// An output path through a folder that does not exist yet is resolved as the OS will resolve it
// once the writer has made that folder: "new/../scene.toml" is the scene, and is refused.
TEST(Cli, AnOutputThroughAMissingFolderIsResolvedBeforeItIsWritten) {
  const Scratch s("bb_missing_dir");
  const std::string d = s.dir.string(), scene = s / "scene.toml";
  std::ofstream(scene) << kSchemaExample;
  const std::string before = slurp(scene);
  const std::string own = "run --quiet --scene " + scene + " --engine home --steps 2 --no-reference ";
  expect_one_line_error(cli(own + "--json " + d + "/new/../scene.toml"),
                        "--json " + d + "/new/../scene.toml: same file as --scene " + scene);
  expect_one_line_error(cli(own + "--json " + d + "/a/b/../../scene.toml --trajectory " + d + "/t.csv"),
                        "same file as --scene " + scene);
  ASSERT_EQ(cli(own + "--frames 2 --json " + s / "r.json").status, 0);
  const std::string results = slurp(s / "r.json");
  expect_one_line_error(cli("view " + s / "r.json" + " --out " + d + "/v/../r.json"),
                        "--out " + d + "/v/../r.json: same file as RESULTS " + s / "r.json");
  std::filesystem::copy_file(s / "r.json", s / "r2.json");
  expect_one_line_error(cli("merge " + s / "r.json" + " " + s / "r2.json" + " --out " + d + "/m/../r2.json"),
                        "--out " + d + "/m/../r2.json: same file as SHARD " + s / "r2.json");
  EXPECT_EQ(slurp(scene), before);
  EXPECT_EQ(slurp(s / "r.json"), results);
  EXPECT_EQ(slurp(s / "r2.json"), results);
  for (const char* made : {"new", "a", "v", "m"}) EXPECT_FALSE(std::filesystem::exists(s / made)) << made;
}

// A results file its owner made write-protected is not replaced (a rename would need only the
// folder's permission): one line before the run, the file as it was.
TEST(Cli, AWriteProtectedOutputIsNotReplaced) {
  const Scratch s("bb_protected");
  std::ofstream(s / "r.json") << "kept";
  std::filesystem::permissions(s / "r.json", std::filesystem::perms::owner_read | std::filesystem::perms::group_read);
  const Outcome o = cli("run --quiet --scene seed-box --engine home --steps 2 --no-reference --json " + s / "r.json");
  expect_one_line_error(o, "--json " + s / "r.json" + ": cannot write the results: the file is write-protected (mode 0440)");
  EXPECT_EQ(o.err.find("ran "), std::string::npos) << o.err;
  EXPECT_EQ(slurp(s / "r.json"), "kept");
}

// A write the system refuses part way (a file-size limit here; a full disk alike) keeps the file it
// would have replaced, names that file and why, and leaves no temporary file behind.
TEST(Cli, AWriteRefusedPartWayKeepsTheFileItWouldReplace) {
  const Scratch s("bb_fsize");
  std::ofstream(s / "t.csv") << "mine";
  const std::string cmd = "ulimit -f 64; " + std::string(BALLBENCH_CLI) +
                          " run --quiet --no-reference --scene seed-box --engine home --steps 400 --trajectory " +
                          s / "t.csv" + " >" + s / "out" + " 2>" + s / "err; echo $? >" + s / "status";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(slurp(s / "status"), "1\n") << slurp(s / "err");
  EXPECT_NE(slurp(s / "err").find("--trajectory " + s / "t.csv" + ": writing failed: File too large"), std::string::npos)
      << slurp(s / "err");
  EXPECT_NE(slurp(s / "out").find("home               ok"), std::string::npos) << slurp(s / "out");
  EXPECT_EQ(slurp(s / "t.csv"), "mine");
  EXPECT_EQ(names_in(s.dir), (std::vector<std::string>{"err", "out", "status", "t.csv"}));
}

// A scene path that is a loop of symbolic links says so, not "not found".
TEST(Cli, ASymbolicLinkLoopIsNamedAsSuch) {
  const Scratch s("bb_loop");
  std::filesystem::create_symlink(s / "b.toml", s / "a.toml");
  std::filesystem::create_symlink(s / "a.toml", s / "b.toml");
  expect_one_line_error(cli("run --scene " + s / "a.toml" + " --engine home"),
                        s / "a.toml" + ": cannot read the scene file: Too many levels of symbolic links");
  expect_one_line_error(cli("run --scene " + s / "none.toml" + " --engine home"), s / "none.toml" + ": scene file not found");
}

// Rendering checks what it joins: a scene's results file with no run, a run whose counts are out
// of range and a run listed twice are each one line naming the file and the run, not a report
// that drops a scene or counts a run twice.
TEST(Cli, RenderingRefusesEmptyOutOfRangeAndRepeatedRuns) {
  const Scratch s("bb_render_checks");
  std::filesystem::create_directories(s.dir / "results");
  std::ofstream(s / "results/run.json") << R"({"command": "ballbench report", "suite": "quick", "scenes": ["seed-box"]})";
  ASSERT_EQ(cli("run --quiet --no-reference --scene seed-box --engine home --steps 3 --json " + s / "one.json").status, 0);
  const nlohmann::json run = nlohmann::json::parse(slurp(s / "one.json"))[0];
  const auto render_with = [&](const nlohmann::json& runs) {
    std::ofstream(s / "results/seed-box.json") << runs.dump();
    return cli("report --out " + s.dir.string() + " --render-only");
  };
  expect_one_line_error(render_with(nlohmann::json::array()), s / "results/seed-box.json" + ": holds no run");
  nlohmann::json negative = run;
  negative["steps_done"] = -5;
  expect_one_line_error(render_with(nlohmann::json::array({negative})), "runs[0].steps_done: -5 is not between 0 and the run's steps (3)");
  expect_one_line_error(render_with(nlohmann::json::array({run, run})), "runs[1]: the same run as runs[0] (home on seed-box, placement 0)");
  // Results of two builds, or of two contents of one scene, are never one report.
  nlohmann::json other_build = run;
  other_build["build"] = "0123456789abcdef";
  std::ofstream(s / "results/seed-bowl.json") << nlohmann::json::array({other_build}).dump();
  const Outcome two_builds = render_with(nlohmann::json::array({run}));
  expect_one_line_error(two_builds, "a report renders one build's results");
  EXPECT_NE(two_builds.err.find("0123456789abcdef"), std::string::npos) << two_builds.err;
  std::filesystem::remove(s / "results/seed-bowl.json");
  std::ofstream(s / "results/run.json") << R"({"command": "ballbench report", "suite": "quick", "scenes": ["seed-box"],
                                              "scene_digests": {"seed-box": "ffffffffffffffff"}})";
  expect_one_line_error(render_with(nlohmann::json::array({run})), "hold other contents of scene seed-box");
  EXPECT_FALSE(std::filesystem::exists(s / "REPORT.md"));
  std::ofstream(s / "results/run.json") << R"({"command": "ballbench report", "suite": "quick", "scenes": ["seed-box"]})";
  ASSERT_EQ(render_with(nlohmann::json::array({run})).status, 0);
}

// Trajectory parts are the run's own: a killed run's leftovers (of any naming) are never joined
// into another run's file, and are left alone.
TEST(Cli, APartLeftByAnotherRunIsNeverJoined) {
  const Scratch s("bb_parts");
  const std::string csv = s / "t.csv";
  const std::string intruder = "engine,profile,step,t,id,x,y,vx,vy\nintruder,default,0,0,0,1,1,1,1\n";
  for (const std::string& left : {csv + ".part0", csv + ".part1", csv + ".part0.tmp", csv + ".part.tmp.1.deadbeef",
                                  csv + ".tmp", csv + ".joining"})
    std::ofstream(left) << intruder;
  const auto before = names_in(s.dir);
  const Outcome o = cli("run --quiet --no-reference --scene seed-box --engine home-seed,home --steps 3 --trajectory " + csv);
  ASSERT_EQ(o.status, 0) << o.err;
  const std::string rows = slurp(csv);
  EXPECT_EQ(rows.find("intruder"), std::string::npos) << rows.substr(0, 400);
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 1 + 2 * 4 * 20);
  auto expected = before;
  expected.push_back("t.csv");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names_in(s.dir), expected);
  for (const std::string& left : {csv + ".part0", csv + ".tmp"}) EXPECT_EQ(slurp(left), intruder);
}

// Two runs writing one trajectory at once: each writes its own temporary files and renames the
// whole file into place, so the file is one run's, never a mix.
TEST(Cli, TwoRunsWritingOneTrajectoryAtOnceDoNotMixRows) {
  const Scratch s("bb_two_writers");
  const std::string csv = s / "t.csv";
  const std::string run = std::string(BALLBENCH_CLI) + " run --quiet --no-reference --scene seed-box --engine home --trajectory " + csv;
  const std::string cmd = "(" + run + " --steps 300 >/dev/null 2>&1 & " + run + " --steps 200 >/dev/null 2>&1 & wait)";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string rows = slurp(csv);
  const long lines = std::count(rows.begin(), rows.end(), '\n');
  EXPECT_TRUE(lines == 1 + 301 * 20 || lines == 1 + 201 * 20) << lines << " lines: rows of both runs in one file";
  EXPECT_EQ(rows.find("engine,", 1), std::string::npos);  // one header
  EXPECT_EQ(names_in(s.dir), std::vector<std::string>{"t.csv"});
}

// A trajectory that cannot be written (a full disk: /dev/full) loses the trajectory, not the
// table or the JSON; one line says so, and the exit status is 1.
TEST(Cli, AFailedTrajectoryWriteKeepsTheTableAndTheJson) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const Scratch s("bb_full");
  const Outcome o = cli("run --quiet --no-reference --scene seed-box --engine home-seed,home --steps 20 --json " +
                        s / "r.json" + " --trajectory /dev/full");
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_NE(o.out.find("home-seed          ok"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("home               ok"), std::string::npos) << o.out;
  EXPECT_NE(slurp(s / "r.json").find("\"checksum\""), std::string::npos);
  EXPECT_NE(o.err.find("ballbench: error: /dev/full: writing the trajectory failed"), std::string::npos) << o.err;
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
}

// A second SIGINT hurries: the run in a child that does not answer (an engine process stuck in a
// step) is killed at once, and the rows finished are still printed and written.
TEST(Cli, ASecondInterruptKeepsTheFinishedRows) {
  const Scratch s("bb_second_int");
  const std::string hang = "process:python3 " + std::string(BALLBENCH_SOURCE_DIR) +
                           "/tests/process_engines/misbehaving_engine.py hang";
  const std::string cmd = std::string(BALLBENCH_CLI) + " run --quiet --no-reference --scene seed-box --steps 50 --engine 'home-seed," +
                          hang + "' --json " + s / "r.json" + " >" + s / "out" + " 2>" + s / "err" +
                          " & pid=$!; sleep 4; kill -INT $pid; sleep 1; kill -INT $pid; wait $pid; echo $? >" + s / "status";
  std::system(cmd.c_str());
  EXPECT_EQ(slurp(s / "status"), "130\n") << slurp(s / "err");
  const std::string results = slurp(s / "r.json");
  EXPECT_NE(results.find("\"engine\": \"home-seed\""), std::string::npos) << slurp(s / "err");
  EXPECT_NE(results.find("\"status\": \"interrupted\""), std::string::npos) << results.substr(0, 300);
  EXPECT_NE(slurp(s / "out").find("home-seed          ok"), std::string::npos) << slurp(s / "out");
  const std::string e = slurp(s / "err");
  EXPECT_NE(e.find("ballbench: interrupted by SIGINT: 2 row(s) written"), std::string::npos) << e;
}

// Every file read is checked before it is opened (regular files only, a size cap) and bounded while
// read (nesting); counts and step caps are checked; each problem is one line and exit status 2.
TEST(Cli, InputsAreBoundedAndRegularFilesOnly) {
  const Scratch s("bb_bounded");
  expect_one_line_error(cli("run --scene /dev/zero --engine home"), "/dev/zero: cannot read the scene file: not a regular file");
  const std::string fifo = s / "fifo.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_one_line_error(cli("run --scene " + fifo + " --engine home"), "not a regular file (a FIFO)");
  {
    std::ofstream big(s / "big.toml");
    const std::string comment = "# " + std::string(1022, 'x') + "\n";
    for (int k = 0; k < 17 * 1024; ++k) big << comment;
  }
  expect_one_line_error(cli("run --scene " + s / "big.toml" + " --engine home"), "above the limit of 16 MiB");
  std::ofstream(s / "nested.json") << std::string(1'000'000, '[') << std::string(1'000'000, ']');
  expect_one_line_error(cli("view " + s / "nested.json"), "nests deeper than 64 levels");
  expect_one_line_error(cli("merge " + s / "nested.json" + " --out " + s / "m.json"), "nests deeper than 64 levels");
  // Wrong types: the file named, exit 2, never an internal error.
  std::ofstream(s / "typed.json") << R"({"scene": 5, "points": "many"})";
  expect_one_line_error(cli("merge " + s / "typed.json" + " --out " + s / "m.json"),
                        s / "typed.json" + ": scene: expected a string, got a number");
  std::ofstream(s / "point.json") << R"({"scene": "seed-box", "n": 20, "horizon": 0.2, "reference": "exact", "repeats": 1,
                                        "points": [{"engine": "home", "profile": "default", "knob": "dt", "value": 0.01, "dt": "fast"}]})";
  expect_one_line_error(cli("merge " + s / "point.json" + " --out " + s / "m.json"),
                        s / "point.json" + ": points[0].dt: expected a number, got a string");
  std::filesystem::create_directories(s / "report/results");
  std::ofstream(s / "report/results/run.json") << R"({"command": 5, "scenes": "seed-box", "suite": []})";
  expect_one_line_error(cli("report --out " + s / "report" + " --render-only"), "run.json");
  // The cap of 1e9 steps, however it is reached.
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2147483647"), "at most 1e9 steps");
  expect_one_line_error(cli("stress --scene seed-box --engine home --steps 2000000000"), "at most 1e9 steps");
  expect_one_line_error(cli("sweep --scene seed-box --engine home --dt-factors 1e-9"), "cap of 1e9 steps");
  expect_one_line_error(cli("sweep --scene seed-box --engine home --horizon 1e12"), "cap of 1e9 steps");
  // A radius too small to hold a contact, as one too large.
  const std::string tiny = write_scene("ballbench_tiny_radius.toml", R"(dt = 0.01
duration = 0.1
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [0.0, 0.0]
radius = 1e-300
)");
  expect_one_line_error(cli("run --scene " + tiny + " --engine home"), ":8: ball[0].radius: must be at least 1e-09 m");
  expect_one_line_error(cli("run --scene deep-pile --engine home --frames 5"), "at most 1000 balls");
}

// `view` checks the frames it draws: of the run's length, finite and of a scene's size.
TEST(Cli, ViewRefusesFramesNoRunWrites) {
  const Scratch s("bb_view_frames");
  ASSERT_EQ(cli("run --quiet --no-reference --scene seed-box --engine home --steps 4 --frames 2 --json " + s / "r.json").status, 0);
  const nlohmann::json good = nlohmann::json::parse(slurp(s / "r.json"));
  ASSERT_EQ(good[0]["series"]["frames"][0].size(), 20u);
  const auto broken = [&](const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = good;
    edit(j[0]);
    std::ofstream(s / name) << j.dump();
    return cli("view " + s / name + " --out " + s / "page.html");
  };
  expect_one_line_error(broken("short.json", [](nlohmann::json& r) { r["series"]["frames"][1].erase(0); }),
                        "series.frames[1] holds 19 positions for 20 balls");
  expect_one_line_error(broken("null.json", [](nlohmann::json& r) { r["series"]["frames"][0][3][0] = nullptr; }),
                        "series.frames[0][3] holds nan, not a position");
  expect_one_line_error(broken("huge.json", [](nlohmann::json& r) { r["series"]["frames"][0][3][1] = 1e300; }),
                        "series.frames[0][3] holds 1e+300, not a position");
  expect_one_line_error(broken("many.json", [](nlohmann::json& r) { r["n"] = 1000000000; }), "n: 1000000000 balls");
  expect_one_line_error(broken("pair.json", [](nlohmann::json& r) { r["series"]["frames"][0][3] = {1.0}; }), "pair.json");
  EXPECT_FALSE(std::filesystem::exists(s / "page.html"));
  ASSERT_EQ(cli("view " + s / "r.json" + " --out " + s / "page.html").status, 0);
}

// Text from outside is printed escaped, on one line, and cut when huge.
TEST(Cli, ErrorsAreOneEscapedLineCutWhenHuge) {
  const Outcome escape = cli("run --scene \"$(printf 'a\\033[31mb')\" --engine home");
  expect_one_line_error(escape, "unknown scene 'a\\x1b[31mb'");
  EXPECT_EQ(escape.err.find('\033'), std::string::npos);
  const Outcome huge = cli("run --scene " + std::string(9000, 'x') + ".toml --engine home");
  expect_one_line_error(huge, " bytes cut) ...");
  EXPECT_LT(huge.err.size(), 2200u);
  // The cut is in the middle: the reason after a huge value is kept.
  EXPECT_NE(huge.err.find("xxx.toml: cannot read the scene file: File name too long"), std::string::npos) << huge.err;
}

// A built-in scene's name is the built-in scene, whatever the working folder holds; a path says so
// by a '/' or by .toml (README, --scene).
TEST(Cli, ABuiltInSceneIsNotShadowedByAFolderOfItsName) {
  const Scratch s("bb_shadow");
  std::filesystem::create_directories(s / "seed-box");
  const std::string cmd = "cd " + s.dir.string() + " && " + BALLBENCH_CLI +
                          " run --quiet --no-reference --scene seed-box --engine home --steps 2 >/dev/null 2>" + s / "err";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(s / "err");
  expect_one_line_error(cli("run --scene " + s / "seed-box" + " --engine home --steps 2"), "is a directory");
}

// A sweep of which not one point ran to a result exits 1, saying so.
TEST(Cli, ASweepWithoutOneMeasuredPointExitsOne) {
  const Scratch s("bb_sweep_failed");
  const std::string crash = "process:python3 " + std::string(BALLBENCH_SOURCE_DIR) +
                            "/tests/process_engines/misbehaving_engine.py crash";
  const Outcome o = cli("sweep --quiet --scene seed-box --engine '" + crash + "' --no-knobs --dt-factors 1,0.5 --repeats 1 --json " +
                        s / "s.json");
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_NE(o.err.find("none of the 2 point(s) ran to a result"), std::string::npos) << o.err;
  EXPECT_TRUE(std::filesystem::exists(s / "s.json"));
}

// A regress baseline's tolerances are checked before anything runs: a negative one is refused; and
// a baseline that cannot be read is replaced by --update.
TEST(Cli, RegressRefusesANegativeToleranceAndUpdatesACorruptBaseline) {
  const Scratch s("bb_regress_tolerance");
  nlohmann::json baseline = nlohmann::json::parse(slurp(std::string(BALLBENCH_REGRESS_DIR) + "/baseline.json"));
  ASSERT_TRUE(baseline["tolerances"].is_object());
  const std::string key = baseline["tolerances"].begin().key();
  baseline["tolerances"][key]["rel"] = -1;
  std::ofstream(s / "baseline.json") << baseline.dump();
  expect_one_line_error(cli("regress --baseline " + s / "baseline.json"),
                        "tolerances." + key + ".rel: expected a finite number >= 0, got -1");
  // --update replaces a baseline it cannot read (the reason to update it), with the defaults.
  std::ofstream(s / "corrupt.json") << "{\"runs\": [";
  const Outcome update = cli("regress --update --baseline " + s / "corrupt.json");
  EXPECT_EQ(update.status, 0) << update.err;
  EXPECT_EQ(cli("regress --baseline " + s / "corrupt.json").status, 0);
}

// A run killed outright (SIGKILL, or the machine going down) cannot remove its temporary files.
// The next command writing the same output removes those whose process is gone, and only those:
// the files of a live process, and any file of another name, are kept.
TEST(Cli, TheNextRunRemovesTheTemporaryFilesOfADeadRunBesideItsOutputs) {
  const Scratch s("bb_stale_temps");
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const std::string gone = std::to_string(child), live = std::to_string(::getpid());
  const std::vector<std::string> stale = {
      "t.csv.tmp." + gone + ".0123abcd",      "t.csv.tmp." + gone + ".0123abcd.header",
      "t.csv.part.tmp." + gone + ".89abcdef", "t.csv.part.tmp." + gone + ".89abcdef.tmp",
      "r.json.tmp." + gone + ".deadbeef"};
  const std::vector<std::string> kept = {
      "t.csv.tmp." + live + ".0123abcd",  "t.csv.part.tmp." + live + ".89abcdef.tmp", "t.csv.tmp",
      "t.csv.tmp." + gone + ".0123abcd.bak", "t.csv.tmp." + gone + ".0123ABCD",      "t.csv.tmp." + gone + ".0123abc",
      "u.csv.tmp." + gone + ".0123abcd",  "xt.csv.tmp." + gone + ".0123abcd"};
  for (const auto* names : {&stale, &kept})
    for (const std::string& name : *names) std::ofstream(s / name) << "x";
  const Outcome o = cli("run --quiet --no-reference --scene seed-box --engine home --steps 2 --trajectory " +
                        s / "t.csv" + " --json " + s / "r.json");
  EXPECT_EQ(o.status, 0) << o.err;
  for (const std::string& name : stale) EXPECT_FALSE(std::filesystem::exists(s / name)) << "left: " << name;
  for (const std::string& name : kept) EXPECT_TRUE(std::filesystem::exists(s / name)) << "removed: " << name;
}

// A real run killed while it writes its trajectory (the isolated run's child dies with it) leaves
// its temporary files; the next run writing that trajectory leaves only the trajectory.
TEST(Cli, ARunKilledWhileWritingItsTrajectoryIsCleanedUpByTheNext) {
  const Scratch s("bb_killed_run");
  const std::string csv = s / "t.csv";
  // home on the pile takes minutes: killed half a second after its temporary files appear.
  const std::string cmd = std::string(BALLBENCH_CLI) + " run --quiet --no-reference --scene pile --engine home " +
                          "--trajectory " + csv + " >/dev/null 2>&1 & pid=$!; for i in $(seq 300); do ls " +
                          s.dir.string() + " | grep -q tmp && break; sleep 0.1; done; sleep 0.5; " +
                          "kill -KILL $pid; { wait $pid; } 2>/dev/null";
  std::system(cmd.c_str());
  const std::vector<std::string> left = names_in(s.dir);
  const auto temporary = [](const std::string& name) { return name.find(".tmp.") != std::string::npos; };
  ASSERT_TRUE(std::any_of(left.begin(), left.end(), temporary)) << "the killed run left no temporary file to clean up";
  const Outcome o = cli("run --quiet --no-reference --scene seed-box --engine home --steps 2 --trajectory " + csv);
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(names_in(s.dir), std::vector<std::string>{"t.csv"});
}

// SIGINT before the first step of a scene of ten million balls, while they are placed (random) or
// checked and built into the engine's and the reference's worlds (a lattice, placed in a moment):
// the command ends within seconds, 130, saying so in one line. The bound is a hang guard, not a
// speed: the run to its end takes some 46 s (this build, idle), and a signal that waited for the
// world in progress would wait tens of seconds; beside another test's job (ctest -j2) it took 6.8 s.
TEST(Cli, AnInterruptBeforeTheFirstStepOfTenMillionBallsActsAtOnce) {
  const Scratch s("bb_huge_interrupt");
  const std::string head = "dt = 0.001\nduration = 0.002\n[container]\nkind = \"box\"\nmin = [-50.0, -50.0]\n"
                           "max = [50.0, 50.0]\n";
  std::ofstream(s / "random.toml") << head << "[random]\ncount = 10000000\nradius = 0.005\nvel_min = [-1.0, -1.0]\n"
                                              "vel_max = [1.0, 1.0]\n";
  std::ofstream(s / "lattice.toml") << head << "[lattice]\ncount = 10000000\nradius = 0.005\nspacing = 0.02\n"
                                               "vel_min = [-1.0, -1.0]\nvel_max = [1.0, 1.0]\n";
  for (const auto& [scene, delay] : {std::pair{"random.toml", "1.5"}, {"lattice.toml", "1"}, {"lattice.toml", "4"}}) {
    const std::string cmd = std::string(BALLBENCH_CLI) + " run --quiet --scene " + s / scene + " --engine home >" +
                            s / "out" + " 2>" + s / "err" + " & pid=$!; sleep " + delay +
                            "; kill -INT $pid; t0=$(date +%s%N); wait $pid; " +
                            "echo $? $(( ($(date +%s%N) - t0) / 1000000 )) >" + s / "status";
    std::system(cmd.c_str());
    int status = -1;
    long ms = -1;
    std::istringstream(slurp(s / "status")) >> status >> ms;
    const std::string e = slurp(s / "err");
    EXPECT_EQ(status, 130) << scene << " after " << delay << " s: " << e;
    EXPECT_LT(ms, 15000) << scene << " after " << delay << " s: the signal waited " << ms << " ms";
    EXPECT_NE(e.find("ballbench: interrupted by SIGINT"), std::string::npos) << scene << ": " << e;
    EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 1) << scene << ": " << e;
  }
}

}  // namespace

// A results file read back (`view`, `report --render-only`, `merge`) with a value of another type
// than ballbench writes is one line naming the file and the field's path, exit 2, never an internal
// error: whatever the field, at any depth.
TEST(Cli, AResultsFileOfWrongTypesNamesTheField) {
  const Scratch s("bb_wrong_types");
  ASSERT_EQ(cli("run --quiet --no-reference --scene seed-box --engine home,home-seed --steps 4 --frames 2 --json " +
                s / "r.json")
                .status,
            0);
  const nlohmann::json good = nlohmann::json::parse(slurp(s / "r.json"));
  const auto edited = [&](const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = good;
    edit(j);
    std::ofstream(s / name) << j.dump();
    return s / name;
  };
  struct Case {
    std::string name;
    std::function<void(nlohmann::json&)> edit;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"drift.json", [](nlohmann::json& j) { j[1]["energy"]["max_rel_drift"] = "x"; },
       "runs[1].energy.max_rel_drift: expected a number, got a string"},
      {"tunnel.json", [](nlohmann::json& j) { j[0]["tunnelling"]["wall"] = nlohmann::json::array(); },
       "runs[0].tunnelling.wall: expected a number, got an array"},
      {"n.json", [](nlohmann::json& j) { j[0]["n"] = "twenty"; }, "runs[0].n: expected a number, got a string"},
      {"engine.json", [](nlohmann::json& j) { j[1]["engine"] = 5; }, "runs[1].engine: expected a string, got a number"},
      {"missing.json", [](nlohmann::json& j) { j[1].erase("engine"); }, "runs[1].engine: missing"},
      {"status.json", [](nlohmann::json& j) { j[0]["status"] = true; }, "runs[0].status: expected a string, got true or false"},
      {"word.json", [](nlohmann::json& j) { j[0]["status"] = "frobbed"; }, "runs[0].status: unknown run status 'frobbed'"},
      {"frame.json", [](nlohmann::json& j) { j[0]["series"]["frames"][1][7][0] = "x"; },
       "runs[0].series.frames[1][7][0]: expected a number, got a string"},
      {"events.json", [](nlohmann::json& j) { j[0]["events"] = 7; }, "runs[0].events: expected an array, got a number"},
      {"config.json", [](nlohmann::json& j) { j[0]["metrics_config"]["stuck_samples"] = "many"; },
       "runs[0].metrics_config.stuck_samples: expected a number, got a string"},
      {"top.json", [](nlohmann::json& j) { j = 5; }, "runs: expected an array, got a number"},
  };
  for (const Case& c : cases) {
    const std::string path = edited(c.name, c.edit);
    expect_one_line_error(cli("view " + path + " --out " + s / "page.html"), path + ": " + c.says);
    std::filesystem::create_directories(s / "report/results");
    std::ofstream(s / "report/results/run.json") << R"({"command": "ballbench report", "scenes": ["seed-box"]})";
    std::filesystem::copy_file(path, s / "report/results/seed-box.json", std::filesystem::copy_options::overwrite_existing);
    expect_one_line_error(cli("report --out " + s / "report" + " --render-only"), "seed-box.json: " + c.says);
  }
  EXPECT_FALSE(std::filesystem::exists(s / "page.html"));
  // The report's own run record, and a shard that is not a sweep's or a match's.
  std::ofstream(s / "report/results/run.json") << R"({"command": 5, "scenes": ["seed-box"]})";
  std::filesystem::copy_file(s / "r.json", s / "report/results/seed-box.json", std::filesystem::copy_options::overwrite_existing);
  expect_one_line_error(cli("report --out " + s / "report" + " --render-only"),
                        "run.json: command: expected a string, got a number");
  std::ofstream(s / "report/results/run.json") << R"({"command": "c", "scenes": "seed-box"})";
  expect_one_line_error(cli("report --out " + s / "report" + " --render-only"),
                        "run.json: scenes: expected an array, got a string");
  std::ofstream(s / "report/results/run.json") << R"({"command": "c", "scenes": ["seed-box"]})";
  std::ofstream(s / "report/results/bench.json") << R"({"benchmarks": [{"name": 5}]})";
  expect_one_line_error(cli("report --out " + s / "report" + " --render-only"),
                        "bench.json: benchmarks[0].name: expected a string, got a number");
  std::filesystem::create_directories(s / "shard/results");
  std::ofstream(s / "shard/results/run.json") << R"({"shard": {"index": "1", "count": 2}, "parts": []})";
  expect_one_line_error(cli("merge " + s / "shard" + " --out " + s / "merged"),
                        "run.json: shard.index: expected a number, got a string");
  std::ofstream(s / "kind.json") << R"({"kind": 5, "scene": "seed-box"})";
  expect_one_line_error(cli("merge " + s / "kind.json" + " --out " + s / "m.json"), "kind.json: ");
  std::ofstream(s / "pos.json") << R"({"scene": "seed-box", "n": 20, "horizon": 0.2, "reference": "exact", "repeats": 1,
      "points": [{"engine": "home", "profile": "default", "knob": "dt", "value": 0.01, "dt": 0.01, "steps": 2,
                  "settings": {}, "status": "ok", "error": "", "ns_per_ball_step": [1], "engine_s": [1],
                  "pos_rms": "far", "vel_rms": 0, "energy_rel": 0, "tunnelling": 0, "sticking": 0, "pareto": true}]})";
  expect_one_line_error(cli("merge " + s / "pos.json" + " --out " + s / "m.json"),
                        "pos.json: points[0].pos_rms: expected a number, got a string");
}

// The report reads nothing from where it writes: an engines file or a benchmark inside OUT/results
// or OUT/figures (which --fresh empties), or a result file that OUT/REPORT.md links to.
TEST(Cli, AReportWritesNoneOfItsInputs) {
  const Scratch s("bb_report_inputs");
  std::filesystem::create_directories(s / "rep/results");
  std::ofstream(s / "rep/results/e.toml") << "# no engines\n";
  expect_one_line_error(cli("--engines " + s / "rep/results/e.toml" + " report --out " + s / "rep" +
                            " --fresh --no-bench --engine home"),
                        "--engines " + s / "rep/results/e.toml" + ": inside --out " + s / "rep/results");
  expect_one_line_error(cli("--engines " + s.dir.string() + "/rep/figures/../results/./e.toml report --out " +
                            s / "rep" + " --no-bench --engine home"),
                        "inside --out " + s / "rep/results");
  EXPECT_EQ(slurp(s / "rep/results/e.toml"), "# no engines\n");
  ASSERT_EQ(cli("run --quiet --no-reference --scene seed-box --engine home --steps 2 --json " + s / "rep/results/seed-box.json")
                .status,
            0);
  const std::string results = slurp(s / "rep/results/seed-box.json");
  std::ofstream(s / "rep/results/run.json") << R"({"command": "c", "scenes": ["seed-box"]})";
  std::filesystem::create_symlink("results/seed-box.json", s / "rep/REPORT.md");
  expect_one_line_error(cli("report --out " + s / "rep" + " --render-only"), "same file as the results file");
  EXPECT_EQ(slurp(s / "rep/results/seed-box.json"), results);
}

// view, merge and list stop on SIGINT, SIGTERM or SIGHUP as every command does: exit 128 + the
// signal, named, nothing half written. A wait for an engine's handshake ends at once.
TEST(Cli, ListViewAndMergeStopOnASignalNamingIt) {
  const Scratch s("bb_signal_list");
  std::ofstream(s / "slow.toml") << "[[engine]]\nname = \"slow\"\ncommand = [\"sleep\", \"100\"]\ntimeout_s = 600\n";
  for (const auto& [signal, status] : {std::pair{"HUP", 129}, {"TERM", 143}, {"INT", 130}}) {
    // The project's engines (Node) left out: the one awaited is `sleep 100`.
    const std::string cmd = std::string("BALLBENCH_ENGINES= timeout --preserve-status -s ") + signal + " 2 " +
                            BALLBENCH_CLI + " --engines " + s / "slow.toml" + " list >/dev/null 2>" + s / "err";
    const int rc = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(rc)) << signal;
    EXPECT_EQ(WEXITSTATUS(rc), status) << signal << ": " << slurp(s / "err");
    const std::string e = slurp(s / "err");
    EXPECT_NE(e.find(std::string("ballbench: interrupted by SIG") + signal + " while waiting for a reply from engine "
                     "process `sleep 100`"),
              std::string::npos)
        << e;
    EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 1) << e;
  }
}

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
#include <string>
#include <thread>

#include "cli_runner.h"

namespace {

using Outcome = ballbench::testing::CliOutcome;
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

TEST(Cli, SettingsOfEnginesNotRunAreCheckedToo) {
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set box2d.bogus=1"), "settings.box2d.bogus");
  expect_one_line_error(cli("run --scene seed-box --engine home --steps 2 --set xyz.a=1"), "--set xyz.KEY: unknown engine");
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
  expect_one_line_error(cli("run --quiet --scene " + scene + " --engine home --steps 2 --json " + scene), "scene file");
  EXPECT_EQ(slurp(scene), before);
  const auto dir = std::filesystem::temp_directory_path();
  const std::string same = (dir / "ballbench_same.out").string();
  expect_one_line_error(cli("run --quiet --scene seed-box --engine home --steps 2 --json " + same + " --trajectory " + same),
                        "both name");
  expect_one_line_error(cli("run --quiet --scene seed-box --engine home --steps 2 --json /proc/no/such/x.json"),
                        "cannot write the results there");
  expect_one_line_error(cli("run --quiet --scene seed-box --engine home --steps 2 --json " + dir.string()), "it is a folder");
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
  for (const auto& [signal, status] : {std::pair{"INT", 130}, {"TERM", 143}}) {
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
  };
  // home's event path on the pile takes minutes a run, so the signal lands in a run.
  const std::vector<Case> cases = {
      {"sweep --quiet --scene pile --engine home --no-knobs --horizon 4 --repeats 1 --json " + d + "/s.json", d + "/s.json"},
      {"stress --quiet --scene pile --engine home --knobs dt --json " + d + "/f.json", d + "/f.json"},
      {"report --no-bench --out " + d + "/report", d + "/report/results"},
  };
  for (const Case& c : cases) {
    const std::string err = d + "/err";
    const std::string cmd = std::string("timeout --preserve-status -s INT 6 ") + BALLBENCH_CLI + " " + c.args +
                            " >/dev/null 2>" + err;
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
  *) exit 3 ;;
esac
)";
  std::filesystem::permissions(bin, std::filesystem::perms::owner_all);
  const Outcome o = cli("report --out " + (dir / "out").string() + " --engine home --bench-binary " + bin.string());
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find("scaling: part skipped: " + bin.string() + " --benchmark_filter='^pipe/': it failed (exit status 3)"),
            std::string::npos)
      << o.err;
  const std::string bench = slurp((dir / "out" / "results" / "bench.json").string());
  EXPECT_NE(bench.find("step/home/default/gas/1000"), std::string::npos) << bench;
  EXPECT_NE(slurp((dir / "out" / "REPORT.md").string()).find("## Scaling"), std::string::npos);
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

}  // namespace

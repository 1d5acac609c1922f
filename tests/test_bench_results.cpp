// The report reads Google Benchmark's JSON: our step benchmarks by name, errors kept as errors,
// aggregates and other benchmarks left out, and a file that is not such JSON named in one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "bench_results.h"
#include "input_error.h"
#include "report_text.h"
#include "report_writer.h"

namespace ballbench {
namespace {

TEST(BenchResults, ReadsStepBenchmarksFromGoogleBenchmarkJson) {
  const auto path = std::filesystem::temp_directory_path() / ("bb_bench." + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({
  "context": {"host_name": "x", "num_cpus": 2},
  "benchmarks": [
    {"name": "step/home/default/gas/1000/min_time:0.200", "run_type": "iteration", "ns_per_ball_step": 55.5,
     "balls": 1000},
    {"name": "step/ode/stock/gas/10000/min_time:0.200", "run_type": "iteration", "error_occurred": true,
     "error_message": "ode: out of memory"},
    {"name": "step/home/default/gas/1000_mean", "run_type": "aggregate", "ns_per_ball_step": 1},
    {"name": "BM_other", "run_type": "iteration"},
    {"name": "step/home/default/bowl/1000000", "run_type": "iteration", "ns_per_ball_step": 20,
     "peak_rss_bytes_per_ball": 150},
    {"name": "pour/home/default/bowl/1000000/iterations:100/real_time", "run_type": "iteration",
     "ns_per_ball_step": 300, "steps_per_s": 3.3}
  ]})";
  const BenchResults b = read_bench_file(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(b.context["num_cpus"], 2);
  ASSERT_EQ(b.rows.size(), 3u);
  EXPECT_EQ(b.rows[0].engine, "home");
  EXPECT_EQ(b.rows[0].scene, "gas");
  EXPECT_EQ(b.rows[0].n, 1000);
  EXPECT_EQ(b.rows[0].ns_per_ball_step, 55.5);
  EXPECT_EQ(b.rows[1].profile, "stock");
  EXPECT_EQ(b.rows[1].error, "ode: out of memory");
  EXPECT_EQ(b.rows[2].n, 1000000);
  EXPECT_EQ(b.rows[2].peak_rss_bytes_per_ball, 150);
  // The pour's window is kept apart: it is not a point of the scaling curve.
  ASSERT_EQ(b.pour.size(), 1u);
  EXPECT_EQ(b.pour[0].window, "pour");
  EXPECT_EQ(b.pour[0].n, 1000000);
  EXPECT_EQ(b.pour[0].steps_per_s, 3.3);
}

TEST(BenchResults, ReadsHarnessBenchmarksAndTheReportShowsThem) {
  const auto path = std::filesystem::temp_directory_path() / ("bb_harness." + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({
  "context": {"num_cpus": 2},
  "benchmarks": [
    {"name": "tunnelling/home/gas/100000/min_time:1.000/manual_time", "run_type": "iteration", "ns_per_ball_step": 20},
    {"name": "harness/home/gas/100000/sample_every:1/min_time:1.000/manual_time", "run_type": "iteration",
     "engine_ns_per_ball_step": 40.0, "harness_ns_per_ball_step": 110.0, "overhead": 2.75},
    {"name": "harness/home/gas/100000/sample_every:10/min_time:1.000/manual_time", "run_type": "iteration",
     "engine_ns_per_ball_step": 35.0, "harness_ns_per_ball_step": 38.5, "overhead": 1.1},
    {"name": "harness/box2d/gas/100000/sample_every:10", "run_type": "iteration", "error_occurred": true,
     "error_message": "out of memory"},
    {"name": "floor/home/gas/100000/min_time:1.000/manual_time", "run_type": "iteration",
     "engine_ns_per_ball_step": 28.0, "engine_cores": 1.33, "threads": 2, "copy_ns_per_ball_step": 1.75,
     "pass_ns_per_ball_step": 1.61, "floor": 0.12}
  ]})";
  const BenchResults b = read_bench_file(path.string());
  std::filesystem::remove(path);
  EXPECT_TRUE(b.rows.empty());
  ASSERT_EQ(b.harness.size(), 3u);
  EXPECT_EQ(b.harness[0].engine, "home");
  EXPECT_EQ(b.harness[0].scene, "gas");
  EXPECT_EQ(b.harness[0].n, 100000);
  EXPECT_EQ(b.harness[0].sample_every, 1);
  EXPECT_EQ(b.harness[1].sample_every, 10);
  EXPECT_EQ(b.harness[1].harness_ns_per_ball_step, 38.5);
  EXPECT_EQ(b.harness[1].overhead, 1.1);
  EXPECT_EQ(b.harness[2].error, "out of memory");
  ASSERT_EQ(b.floor.size(), 1u);
  EXPECT_EQ(b.floor[0].n, 100000);
  EXPECT_EQ(b.floor[0].threads, 2);
  EXPECT_EQ(b.floor[0].copy_ns_per_ball_step, 1.75);
  EXPECT_EQ(b.floor[0].floor, 0.12);

  ReportInputs in;
  in.run = nlohmann::json::object();
  in.harness = b;
  const std::string md = all_pages(render_report(in));
  for (const char* want : {"## Harness overhead", "| home | gas | 100000 | 10 | 35.0 | 38.5 | 1.10 |",
                           "| home | gas | 100000 | 1 | 40.0 | 110.0 | 2.75 |", "failed: out of memory",
                           "keeping 1.33 of 2 cores", "together **0.12** of the engine's step"})
    EXPECT_NE(md.find(want), std::string::npos) << want << "\n" << md;
}

// The scaling tables time every engine at the scene's own step, whatever accuracy that gives:
// they rank no engine against another (the equal-accuracy sections do). Our solver, told by its
// role and not its name, gets its rate at its largest count; the others do not.
TEST(BenchResults, TheScalingTablesRankNoEngineAndTellOursByRole) {
  BenchResults b;
  const auto row = [](std::string engine, double ns) {
    BenchRow r;
    r.engine = std::move(engine);
    r.profile = "default";
    r.scene = "gas";
    r.n = 1000;
    r.ns_per_ball_step = ns;
    r.steps_per_s = 1e9 / (ns * 1000);
    return r;
  };
  b.rows = {row("mine", 10), row("theirs", 50), row("oracle", 20), row("seed", 1)};
  ReportInputs in;
  in.run = nlohmann::json::object();
  in.bench = b;
  in.roles = {{"mine", EngineRole::ours}, {"oracle", EngineRole::reference}, {"seed", EngineRole::thesis}};
  const std::string md = all_pages(render_report(in));
  EXPECT_EQ(md.find("against the fastest"), std::string::npos) << md;
  EXPECT_NE(md.find("not which is cheaper"), std::string::npos) << md;
  EXPECT_NE(md.find("`mine` at 1000 balls: 100000.0 steps per second"), std::string::npos) << md;
  EXPECT_EQ(md.find("`theirs` at"), std::string::npos) << md;
  EXPECT_EQ(md.find("`oracle` at"), std::string::npos) << md;
}

// An engine in another process: the harness's time, its own step and the pipe alone (pipe/noop,
// kept apart from the scaling rows) side by side.
TEST(BenchResults, TheReportShowsWhatIsTheEngineAndWhatIsThePipe) {
  const auto path = std::filesystem::temp_directory_path() / ("bb_pipe." + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({
  "context": {"num_cpus": 2},
  "benchmarks": [
    {"name": "step/rapier/tuned/gas/1000/min_time:0.200/real_time", "run_type": "iteration",
     "ns_per_ball_step": 1739, "engine_process_ns_per_ball_step": 1210},
    {"name": "step/home/default/gas/1000/min_time:0.200/real_time", "run_type": "iteration", "ns_per_ball_step": 24},
    {"name": "pipe/noop/default/gas/1000/min_time:0.200", "run_type": "iteration", "ns_per_ball_step": 262}
  ]})";
  const BenchResults b = read_bench_file(path.string());
  std::filesystem::remove(path);
  ASSERT_EQ(b.rows.size(), 2u);  // the pipe is not a point of the scaling curve
  ASSERT_EQ(b.pipe.size(), 1u);
  EXPECT_EQ(b.pipe[0].window, "pipe");
  // The engine's own step is its headline figure, the harness's time with the pipe beside it.
  EXPECT_EQ(b.rows[0].ns_per_ball_step, 1210);
  EXPECT_EQ(b.rows[0].pipe_ns_per_ball_step, 1739);
  EXPECT_EQ(b.rows[1].ns_per_ball_step, 24);
  EXPECT_FALSE(b.rows[1].pipe_ns_per_ball_step);
  ReportInputs in;
  in.run = nlohmann::json::object();
  in.bench = b;
  const std::string md = all_pages(render_report(in));
  EXPECT_NE(md.find("| rapier/tuned | gas | 1000 | 1739 | 1210 | 262 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| home | gas | 1000 |"), std::string::npos) << md;  // in this process: no pipe
}

// A settled pile or the fluid judged against its scene's spec (bench/spec_check.h): the verdict is
// read with the row, a run that did not meet it is marked in its cell and named with why below.
TEST(BenchResults, TheScalingPageSaysWhichRunsMetTheirSpec) {
  const auto path = std::filesystem::temp_directory_path() / ("bb_spec." + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"json({
  "context": {"num_cpus": 2},
  "benchmarks": [
    {"name": "step/home/default/settled/1000/real_time", "run_type": "iteration", "ns_per_ball_step": 984,
     "spec_met": 1, "label": "spec met: overlap 0.000554 (<= 0.01), rest_speed 0.000619 (<= 0.0156605)"},
    {"name": "step/box2d/stock/settled/1000/real_time", "run_type": "iteration", "ns_per_ball_step": 1036,
     "spec_met": 0, "label": "spec not met: overlap 0.0213 > 0.01"},
    {"name": "step/home/default/gas/1000/real_time", "run_type": "iteration", "ns_per_ball_step": 24}
  ]})json";
  const BenchResults b = read_bench_file(path.string());
  std::filesystem::remove(path);
  ASSERT_EQ(b.rows.size(), 3u);
  EXPECT_EQ(b.rows[0].spec_met, true);
  EXPECT_EQ(b.rows[1].spec_met, false);
  EXPECT_EQ(b.rows[1].spec, "not met: overlap 0.0213 > 0.01");
  EXPECT_FALSE(b.rows[2].spec_met);  // not judged
  ReportInputs in;
  in.run = nlohmann::json::object();
  in.bench = b;
  const std::string md = all_pages(render_report(in));
  EXPECT_NE(md.find("| box2d/stock | 1036 (spec not met) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| home | 984 |"), std::string::npos) << md;
  EXPECT_NE(md.find("not met by box2d/stock at 1000: overlap 0.0213 > 0.01"), std::string::npos) << md;
}

TEST(BenchResults, AHarnessRowWithoutItsCountersIsAnInputError) {
  const auto path = std::filesystem::temp_directory_path() / ("bb_harness_bad." + std::to_string(::getpid()) + ".json");
  for (const char* row : {R"({"name": "harness/home/gas/10/sample_every:1", "run_type": "iteration", "overhead": 1.0})",
                          R"({"name": "floor/home/gas/10", "run_type": "iteration", "floor": 0.1})"}) {
    std::ofstream(path) << R"({"benchmarks": [)" << row << "]}";
    EXPECT_THROW(read_bench_file(path.string()), InputError) << row;
  }
  std::filesystem::remove(path);
}

TEST(BenchResults, AFileThatIsNotBenchmarkJsonIsAnInputError) {
  const auto path = std::filesystem::temp_directory_path() / ("bb_bench_bad." + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({"results": []})";
  try {
    read_bench_file(path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ballbench

#pragma once
// The step benchmark's results (bench/step_benchmark.cpp run with --benchmark_format=json or
// --benchmark_out), read for the report's scaling figure and table. Read through nlohmann-json from
// Google Benchmark's own JSON output, never from its console text.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ballbench {

struct BenchRow {
  std::string window = "step";         // "step" (a few steps after warm-up), "pour" (the first 100 steps) or
                                       // "pipe" (the process protocol alone: an engine that moves nothing)
  std::string engine, profile, scene;  // from the benchmark name WINDOW/ENGINE/PROFILE/SCENE/N
  long n = 0;
  // The engine's own step time: the benchmark's counter, or for an engine in another process the
  // step time its process measured (the counter, with the pipe, is then pipe_ns_per_ball_step).
  double ns_per_ball_step = 0;
  std::optional<double> steps_per_s;              // when the benchmark reports it
  std::optional<double> peak_rss_bytes_per_ball;  // the process's peak resident set over n
  std::optional<double> engine_bytes_per_ball;    // resident growth while the engine was built and run
  std::optional<double> settle_steps;             // settled pile: steps before the timed ones
  std::optional<double> start_rms_speed;          // settled pile: RMS speed when the timed steps began (m/s)
  std::optional<double> pipe_ns_per_ball_step;  // an engine in another process: the harness's time, pipe included
  // The settled piles and the fluid: whether the run met its scene's spec on the states the
  // benchmark read outside its timing (bench/spec_check.h), and its verdict ("met: overlap ...").
  std::optional<bool> spec_met;
  std::string spec;
  std::string error;                   // the benchmark skipped with this message ("" = ran)
};

// What the harness costs beside the engine (bench/harness_benchmark.cpp): a run of `ENGINE` on the
// scaled SCENE with N balls, the sampled metrics seeing every K-th step.
struct HarnessRow {
  std::string engine, scene;           // from the benchmark name harness/ENGINE/SCENE/N/sample_every:K
  long n = 0;
  int sample_every = 1;
  double engine_ns_per_ball_step = 0, harness_ns_per_ball_step = 0;  // the benchmark's counters
  double overhead = 0;                 // harness time over engine time, the same run
  std::string error;                   // the benchmark skipped with this message ("" = ran)
};

// The least a per-step check from states costs beside the engine (bench/harness_benchmark.cpp,
// floor/ENGINE/SCENE/N): copying the state once and one streaming pass over two states.
struct FloorRow {
  std::string engine, scene;           // from the benchmark name floor/ENGINE/SCENE/N
  long n = 0;
  double engine_ns_per_ball_step = 0;
  double engine_cores = 0;             // the engine's CPU time over its wall time
  int threads = 1;                     // the copy's and the pass's threads
  double copy_ns_per_ball_step = 0, pass_ns_per_ball_step = 0;
  double floor = 0;                    // (copy + pass) over the engine's time, the same run
  std::string error;                   // the benchmark skipped with this message ("" = ran)
};

struct BenchResults {
  nlohmann::json context;              // Google Benchmark's context: host, CPU, library versions
  std::vector<BenchRow> rows;          // step/ rows in the file's order; aggregates (mean, median) left out
  std::vector<BenchRow> pour;          // pour/ rows (window "pour"), apart: they are not scaling points
  std::vector<BenchRow> pipe;          // pipe/ rows: the process protocol's own cost per step
  std::vector<HarnessRow> harness;     // harness/ rows
  std::vector<FloorRow> floor;         // floor/ rows
};

// Rows whose names do not start step/, pour/ or pipe/ENGINE/PROFILE/SCENE/N or
// harness/ENGINE/SCENE/N/sample_every:K or floor/ENGINE/SCENE/N (other benchmarks in the same file) are skipped. Throws
// InputError naming the file if it is not Google Benchmark JSON.
BenchResults read_bench_file(const std::string& path);

}  // namespace ballbench

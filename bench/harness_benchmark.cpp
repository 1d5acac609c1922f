// What the harness costs beside the engine: `run_engine` (core/runner.h) on `home` in the scaled
// gas, engine step time and harness time (reading states, metrics, checksums) taken from the same
// run's Result, for the sampled metrics seeing every step and every 10th. Tunnelling sees every
// step in both. Counters: engine and harness ns per ball-step, and overhead = harness / engine.
//
//   build/release/bench/ballbench_harness_benchmark --benchmark_format=json > harness.json
#include <benchmark/benchmark.h>

#include "bench_main.h"

#include <map>

#include <fmt/format.h>

#include "registry.h"
#include "runner.h"
#include "scaled_scene.h"

namespace ballbench::bench {
namespace {

constexpr long kSteps = 100;  // enough for the one-time costs (first sample, final statistics) to fade

void harness_benchmark(benchmark::State& state, int n, int sample_every) {
  static std::map<int, Scene> scenes;
  auto it = scenes.find(n);
  if (it == scenes.end()) it = scenes.emplace(n, scaled_scene(SceneKind::Gas, n)).first;
  RunOptions options;
  options.steps = kSteps;
  options.metrics.sample_every = sample_every;
  double engine_s = 0, harness_s = 0;
  for (auto _ : state) {
    const Result r = run_engine(it->second, find_engine("home"), options);
    if (r.status != "ok") {
      state.SkipWithError(r.error.c_str());
      return;
    }
    engine_s += r.wall_s, harness_s += r.harness_s;
    state.SetIterationTime(r.wall_s + r.harness_s);
  }
  const double ball_steps = static_cast<double>(state.iterations()) * kSteps * n;
  state.counters["engine_ns_per_ball_step"] = 1e9 * engine_s / ball_steps;
  state.counters["harness_ns_per_ball_step"] = 1e9 * harness_s / ball_steps;
  state.counters["overhead"] = harness_s / engine_s;
}

}  // namespace

void register_benchmarks() {
  for (int n : {10'000, 100'000})
    for (int k : {1, 10})
      benchmark::RegisterBenchmark(fmt::format("harness/home/gas/{}/sample_every:{}", n, k).c_str(), harness_benchmark,
                                   n, k)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond)
          ->MinTime(1.0);
}

}  // namespace ballbench::bench


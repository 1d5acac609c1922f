// What the harness costs beside the engine: `run_engine` (core/runner.h) on `home` in the scaled
// gas, engine step time and harness time (reading states, metrics, checksums) taken from the same
// run's Result, for the sampled metrics seeing every step and every 10th. Tunnelling sees every
// step in both. Counters: engine and harness ns per ball-step, and overhead = harness / engine.
// `tunnelling/...` times the per-step check alone (finiteness, wall escapes, pass-throughs) on
// recorded states of the same gas: ns per ball-step, and the events it counted (0 for home).
//
//   build/release/bench/ballbench_harness_benchmark --benchmark_format=json > harness.json
#include <benchmark/benchmark.h>

#include "bench_main.h"

#include <chrono>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "registry.h"
#include "runner.h"
#include "scaled_scene.h"

namespace ballbench::bench {
namespace {

constexpr long kSteps = 100;  // enough for the one-time costs (first sample, final statistics) to fade

void harness_benchmark(benchmark::State& state, int n, int sample_every) {
  const Scene& scene = shared_scaled_scene(SceneKind::Gas, n);
  RunOptions options;
  options.steps = kSteps;
  options.metrics.sample_every = sample_every;
  double engine_s = 0, harness_s = 0;
  for (auto _ : state) {
    const Result r = run_engine(scene, find_engine("home"), options);
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

// The states of `home` in the scaled gas, steps 0..kSteps, recorded once per size.
const std::vector<State>& gas_states(int n) {
  static std::map<int, std::vector<State>> recorded;
  auto it = recorded.find(n);
  if (it != recorded.end()) return it->second;
  const Scene& scene = shared_scaled_scene(SceneKind::Gas, n);
  const EngineEntry& home = find_engine("home");
  auto engine = home.create(scene, home.info.profiles.front(), nlohmann::json::object());
  std::vector<State> states(kSteps + 1);
  engine->read(states[0]);
  for (long k = 1; k <= kSteps; ++k) engine->step(scene.dt), engine->read(states[k]);
  return recorded.emplace(n, std::move(states)).first->second;
}

// The per-step check alone (finiteness, wall escapes, pass-throughs) over the recorded gas steps.
// Each step's new state is first copied into a scratch state, untimed, as the runner's read does:
// the check then finds it in cache as it would in a run.
void tunnelling_benchmark(benchmark::State& state, int n) {
  const Scene& scene = shared_scaled_scene(SceneKind::Gas, n);
  const std::vector<State>& states = gas_states(n);
  long passthroughs = 0;
  double total_s = 0;
  for (auto _ : state) {
    MetricsAccumulator metrics(scene, {});
    State prev = states[0], cur;
    double seconds = 0;
    for (long k = 1; k <= kSteps; ++k) {
      cur = states[k];
      const auto t0 = std::chrono::steady_clock::now();
      const bool ok = metrics.observe_motion(prev, cur);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      benchmark::DoNotOptimize(ok);
      std::swap(prev, cur);
    }
    passthroughs = metrics.summary().tunnelling_pair + metrics.summary().tunnelling_wall;
    state.SetIterationTime(seconds);
    total_s += seconds;
  }
  state.counters["ns_per_ball_step"] = 1e9 * total_s / (static_cast<double>(state.iterations()) * kSteps * n);
  state.counters["tunnelling"] = static_cast<double>(passthroughs);
}

}  // namespace

void register_benchmarks() {
  for (int n : {10'000, 100'000})
    benchmark::RegisterBenchmark(fmt::format("tunnelling/home/gas/{}", n).c_str(), tunnelling_benchmark, n)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond)
        ->MinTime(1.0);
  for (int n : {10'000, 100'000})
    for (int k : {1, 10})
      benchmark::RegisterBenchmark(fmt::format("harness/home/gas/{}/sample_every:{}", n, k).c_str(), harness_benchmark,
                                   n, k)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond)
          ->MinTime(1.0);
}

}  // namespace ballbench::bench


// What the harness costs beside the engine: `run_engine` (core/runner.h) on `home` in the scaled
// gas, engine step time and harness time (reading states, metrics, checksums) taken from the same
// run's Result, for the sampled metrics seeing every step and every 10th. Tunnelling sees every
// step in both. Counters: engine and harness ns per ball-step, and overhead = harness / engine.
// `tunnelling/...` times the per-step check alone (finiteness, wall escapes, pass-throughs) on
// recorded states of the same gas: ns per ball-step, and the events it counted (0 for home).
// `floor/home/gas/N` measures, in one run, what any per-step check from states must at least pay
// beside the engine's step: copying the state out once (32 bytes per ball, on as many threads as
// the machine has cores, as `home` steps at 10^5), and one streaming pass comparing two consecutive
// states (finiteness and the longest step: 48 bytes read, 16 written per ball). Neither is harness
// code; together they are a lower bound on a harness that reads the state and compares it with the
// last one, with no pair search. `engine_cores` is the engine's CPU time over its wall time: the
// cores it keeps busy, so the rest is what a harness running beside it could use.
//
//   build/release/bench/ballbench_harness_benchmark --benchmark_format=json > harness.json
#include <benchmark/benchmark.h>

#include "bench_main.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "fork_join.h"
#include "metrics/meter_set.h"
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
    if (r.status != RunStatus::ok) {
      state.SkipWithError(r.error.c_str());
      return;
    }
    engine_s += r.engine_s, harness_s += r.harness_s;
    state.SetIterationTime(r.engine_s + r.harness_s);
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
    MeterSet metrics(scene, {});
    State prev = states[0], cur;
    double seconds = 0;
    for (long k = 1; k <= kSteps; ++k) {
      cur = states[k];
      const auto t0 = std::chrono::steady_clock::now();
      metrics.motion(prev, cur);
      const bool ok = !metrics.stop_after_motion();
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      benchmark::DoNotOptimize(ok);
      std::swap(prev, cur);
    }
    const MetricValues values = metrics.values();
    passthroughs = values.tunnelled();
    state.SetIterationTime(seconds);
    total_s += seconds;
  }
  state.counters["ns_per_ball_step"] = 1e9 * total_s / (static_cast<double>(state.iterations()) * kSteps * n);
  state.counters["tunnelling"] = static_cast<double>(passthroughs);
}

double process_cpu_s() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// See the top of the file: the engine's step beside the least a per-step check from states costs.
void floor_benchmark(benchmark::State& state, int n) {
  const Scene& scene = shared_scaled_scene(SceneKind::Gas, n);
  const EngineEntry& home = find_engine("home");
  ForkJoin pool(ForkJoin::threads_for(n, 0, 0));
  const int parts = pool.parts();
  double engine_s = 0, engine_cpu_s = 0, copy_s = 0, pass_s = 0;
  long moving_steps = 0;  // steps the pass found finite with a ball moving: its result used, so computed
  for (auto _ : state) {
    auto engine = home.create(scene, home.info.profiles.front(), nlohmann::json::object());
    State read, copy;
    engine->read(read);
    copy = read;
    std::vector<double> last_x(read.pos.col(0).data(), read.pos.col(0).data() + n);
    std::vector<double> last_y(read.pos.col(1).data(), read.pos.col(1).data() + n);
    std::vector<double> longest(parts);
    std::vector<int> finite(parts);
    double seconds = 0;
    for (long k = 1; k <= kSteps; ++k) {
      const double cpu0 = process_cpu_s();
      auto t0 = std::chrono::steady_clock::now();
      engine->step(scene.dt);
      const double step_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      engine_s += step_s, engine_cpu_s += process_cpu_s() - cpu0;
      engine->read(read);  // untimed: the copy below stands for it
      t0 = std::chrono::steady_clock::now();
      pool.run([&](int p) {
        const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
        for (int c = 0; c < 2; ++c) {
          std::memcpy(copy.pos.col(c).data() + b, read.pos.col(c).data() + b, sizeof(double) * (e - b));
          std::memcpy(copy.vel.col(c).data() + b, read.vel.col(c).data() + b, sizeof(double) * (e - b));
        }
      });
      const double copied_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      t0 = std::chrono::steady_clock::now();
      pool.run([&](int p) {
        const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
        const double *x = copy.pos.col(0).data(), *y = copy.pos.col(1).data();
        const double *vx = copy.vel.col(0).data(), *vy = copy.vel.col(1).data();
        double *lx = last_x.data(), *ly = last_y.data();
        int ok = 1;
        double m2 = 0;
        for (long i = b; i < e; ++i) {
          ok &= ((x[i] - x[i]) + (y[i] - y[i])) + ((vx[i] - vx[i]) + (vy[i] - vy[i])) == 0;
          const double dx = x[i] - lx[i], dy = y[i] - ly[i];
          m2 = std::max(m2, dx * dx + dy * dy);
          lx[i] = x[i], ly[i] = y[i];
        }
        finite[p] = ok, longest[p] = m2;
      });
      const double passed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      copy_s += copied_s, pass_s += passed_s, seconds += step_s + copied_s + passed_s;
      moving_steps += std::all_of(finite.begin(), finite.end(), [](int f) { return f != 0; }) &&
                       *std::max_element(longest.begin(), longest.end()) > 0;
    }
    state.SetIterationTime(seconds);
  }
  const double ball_steps = static_cast<double>(state.iterations()) * kSteps * n;
  state.counters["engine_ns_per_ball_step"] = 1e9 * engine_s / ball_steps;
  state.counters["engine_cores"] = engine_cpu_s / engine_s;
  state.counters["threads"] = parts;
  state.counters["copy_ns_per_ball_step"] = 1e9 * copy_s / ball_steps;
  state.counters["pass_ns_per_ball_step"] = 1e9 * pass_s / ball_steps;
  state.counters["floor"] = (copy_s + pass_s) / engine_s;
  state.counters["moving_steps"] = static_cast<double>(moving_steps);
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
  benchmark::RegisterBenchmark("floor/home/gas/100000", floor_benchmark, 100'000)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond)
      ->MinTime(1.0);
}

}  // namespace ballbench::bench


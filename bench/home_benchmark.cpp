// What each of the home solver's performance choices saves, on one scene, in one run
// (core/solver/PERFORMANCE.md quotes these figures):
//
//   home/threads/T/SCENE/N           the per-ball loops on T threads (1 = serial)
//   home/reorder/K/SCENE/N           balls renumbered in cell order every K steps (0 = never)
//   home/shortcut/NAME/on|off/SCENE/N  a scene-wide shortcut taken (on) or the general path (off)
//
// Each shortcut is timed on a scene that allows it: the gas for no_gravity, equal_radii and
// equal_masses, the gas without its box for no_walls, a single ball for no_pairs.
//
//   build/perf/bench/ballbench_home_benchmark --benchmark_format=json > home.json
//
// Read the on/off ratios within one run, not the nanoseconds: the machines are shared.
#include <benchmark/benchmark.h>

#include "bench_main.h"

#include <functional>
#include <map>

#include <fmt/format.h>

#include "scaled_scene.h"
#include "scene_loader.h"
#include "solver/home.h"

namespace ballbench::bench {
namespace {

const Scene& gas(int n) {
  return shared_scaled_scene(SceneKind::Gas, n);
}

// The gas in open space: the same balls, no box (they drift apart slowly over the timed steps).
const Scene& open_gas(int n) {
  static std::map<int, Scene> scenes;
  auto it = scenes.find(n);
  if (it == scenes.end()) {
    Scene s = gas(n);
    s.container.kind = ContainerKind::None;
    it = scenes.emplace(n, std::move(s)).first;
  }
  return it->second;
}

const Scene& one_ball() {
  static const Scene s = parse_scene(R"(
name = "one-ball"
dt = 0.01
duration = 1.0
restitution = 1.0
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [0.0, 0.0]
vel = [3.0, 2.0]
radius = 0.25
mass = 1.0
)",
                                     "one-ball");
  return s;
}

void run(benchmark::State& state, const Scene& scene, const HomeSettings& settings) {
  std::unique_ptr<Engine> engine = make_home(scene, settings);
  for (int k = 0; k < 5; ++k) engine->step(scene.dt);
  for (auto _ : state) engine->step(scene.dt);
  const double n = scene.n();
  state.counters["balls"] = n;
  state.counters["ns_per_ball_step"] =
      benchmark::Counter(n * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

void register_benchmarks() {
  for (int threads : {1, 2})
    for (int n : {10'000, 20'000, 50'000, 100'000, 1'000'000}) {
      HomeSettings s;
      s.threads = threads;
      benchmark::RegisterBenchmark(fmt::format("home/threads/{}/gas/{}", threads, n).c_str(),
                                   [s, n](benchmark::State& st) { run(st, gas(n), s); })
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime()
          ->MinTime(0.3);
    }
  for (int every : {0, 16})
    for (int n : {10'000, 100'000, 1'000'000}) {
      HomeSettings s;
      s.threads = 1;
      s.reorder_steps = every;
      benchmark::RegisterBenchmark(fmt::format("home/reorder/{}/gas/{}", every, n).c_str(),
                                   [s, n](benchmark::State& st) { run(st, gas(n), s); })
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime()
          ->MinTime(1.0);
    }
  struct Case {
    const char* name;
    bool HomeShortcuts::*field;
    std::function<const Scene&()> scene;
    const char* scene_name;
    int n;
  };
  const std::vector<Case> cases = {
      {"no_gravity", &HomeShortcuts::no_gravity, []() -> const Scene& { return gas(10'000); }, "gas", 10'000},
      {"no_walls", &HomeShortcuts::no_walls, []() -> const Scene& { return open_gas(10'000); }, "open-gas", 10'000},
      {"equal_radii", &HomeShortcuts::equal_radii, []() -> const Scene& { return gas(10'000); }, "gas", 10'000},
      {"equal_masses", &HomeShortcuts::equal_masses, []() -> const Scene& { return gas(10'000); }, "gas", 10'000},
      {"no_pairs", &HomeShortcuts::no_pairs, []() -> const Scene& { return one_ball(); }, "one-ball", 1},
      {"elastic", &HomeShortcuts::elastic, []() -> const Scene& { return gas(10'000); }, "gas", 10'000},
  };
  for (const Case& c : cases)
    for (bool on : {true, false}) {
      HomeSettings s;
      s.threads = 1;  // serial, so the saving is not hidden in thread hand-over noise
      s.allow.*c.field = on;
      benchmark::RegisterBenchmark(fmt::format("home/shortcut/{}/{}/{}/{}", c.name, on ? "on" : "off", c.scene_name, c.n).c_str(),
                                   [s, c](benchmark::State& st) { run(st, c.scene(), s); })
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime()
          ->MinTime(0.3);
    }
}

}  // namespace ballbench::bench


// Step cost of every engine (every profile) on the scaled standard scenes, across ball counts
// 10 .. 10^5 (10^6 for home). The world is built and warmed up outside the timed loop; the loop
// times Engine::step only, in wall-clock time (home runs its per-ball loops on every core).
// Counters: ns per ball-step, balls per second, steps per second, and memory:
// - peak_rss_bytes_per_ball: the process's peak resident set (getrusage ru_maxrss) over n. It
//   counts everything the process ever held (the scenes of earlier benchmarks too), so read it
//   from a fresh process running one benchmark: --benchmark_filter='step/home/default/bowl/1000000/'.
// - engine_bytes_per_ball: growth of the current resident set (/proc/self/statm) from just before
//   the engine is built (the heap trimmed first) to the end of the timed steps, over n: what the
//   engine holds.
//
//   build/release/bench/ballbench_step_benchmark --benchmark_format=json > step.json
//
// pour/home/default/bowl/1000000 is the same measure over a window that matters to a user: the
// pour's first second, 100 steps from rest (no warm-up, exactly 100 timed steps), where the step
// benchmark's window is a few steps after 5 of warm-up, while the balls are still falling freely.
//
// settled/ENGINE/PROFILE/N times a pile at rest (settled_pile.h) from its saved state; the
// variants settled/home/soft, settled/home/soft-sleep and settled/box2d/stock-sleep say their
// settings in the profile's place.
//
// Read the ratios within one run, not the nanoseconds: the machines are shared.
#include <benchmark/benchmark.h>

#include "bench_main.h"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include <fmt/format.h>

#include "registry.h"
#include "scaled_scene.h"
#include "settled_pile.h"

namespace ballbench::bench {
namespace {

// Largest ball count per engine: home-seed is O(n^2) by design; the rest stop at 10^5 except
// home, which the scaling target takes to 10^6.
// ODE's stock profile uses its hash space, whose cost per ball grows with n (adapters/ode/README.md:
// 49 us per ball-step at 10^4): 10^5 would take minutes per benchmark.
int max_balls(const std::string& engine, const std::string& profile) {
  if (engine == "home-seed") return 1000;
  if (engine == "home") return 1'000'000;
  if (engine == "ode" && profile == "stock") return 10'000;
  return 100'000;
}

// Current resident set (bytes), from /proc/self/statm.
double resident_bytes() {
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

// Peak resident set of the process so far (bytes; ru_maxrss is in KiB on Linux).
double peak_resident_bytes() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) * 1024.0;
}

// The scene a benchmark times, built when the benchmark first runs (so a filter that leaves it out
// does not pay for it).
using SceneOf = const Scene& (*)(int n);
const Scene& gas_scene(int n) { return shared_scaled_scene(SceneKind::Gas, n); }
const Scene& bowl_scene(int n) { return shared_scaled_scene(SceneKind::Bowl, n); }

void step_benchmark(benchmark::State& state, const EngineEntry* entry, std::string profile, SceneOf scene_of, int n,
                    int warm_up, nlohmann::json settings) {
  const Scene& scene = scene_of(n);
  std::unique_ptr<Engine> engine;
  // Memory the scene generator freed stays in the heap; the engine would reuse it, and the growth
  // would miss that share of what it holds (measured at 10^6 bowl balls: 126 bytes per ball
  // without this, 167 with it). Handed back first, the growth is the engine's whole footprint.
  ::malloc_trim(0);
  const double resident_before = resident_bytes();
  try {
    engine = entry->create(scene, profile, settings);
    for (int k = 0; k < warm_up; ++k) engine->step(scene.dt);  // contacts, caches
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  for (auto _ : state) {
    try {
      engine->step(scene.dt);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["balls"] = n;
  state.counters["ns_per_ball_step"] =
      benchmark::Counter(static_cast<double>(n) * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
  state.counters["balls_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["steps_per_s"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_rss_bytes_per_ball"] = peak_resident_bytes() / n;
  state.counters["engine_bytes_per_ball"] = (resident_bytes() - resident_before) / n;
}

}  // namespace

void register_benchmarks() {
  for (const auto& e : engine_registry()) {
    benchmark::AddCustomContext("engine." + e.info.name, e.info.version);
    for (const auto& profile : e.info.profiles)
      for (SceneKind kind : {SceneKind::Gas, SceneKind::Bowl})
        for (int n = 10; n <= max_balls(e.info.name, profile); n *= 10)
          benchmark::RegisterBenchmark(
              fmt::format("step/{}/{}/{}/{}", e.info.name, profile, scene_kind_name(kind), n).c_str(),
              step_benchmark, &e, profile, kind == SceneKind::Gas ? gas_scene : bowl_scene, n, 5,
              nlohmann::json::object())
              ->Unit(benchmark::kMicrosecond)
              ->UseRealTime()
              ->MinTime(0.2);
  }
  // A pile at rest (settled_pile.h), 10^2 .. 10^4 balls for every engine; `home` also with its soft
  // resting path (home/soft), to 10^6. Not `exact`: an event-driven solver without a resting
  // contact model, it does not finish a step of a pile at rest (100 balls: no step in 100 s).
  for (const auto& e : engine_registry())
    for (const auto& profile : e.info.profiles)
      if (e.info.name != "exact")
      for (int n = 100; n <= std::min(10'000, max_balls(e.info.name, profile)); n *= 10)
        benchmark::RegisterBenchmark(fmt::format("settled/{}/{}/{}", e.info.name, profile, n).c_str(), step_benchmark,
                                     &e, profile, shared_settled_pile, n, 5, nlohmann::json::object())
            ->Unit(benchmark::kMicrosecond)
            ->UseRealTime()
            ->MinTime(0.2);
  // Variants with their settings in the name's profile place: home's soft path, and sleeping, which
  // every engine has off unless asked (each adapter's README), for home and for Box2D, whose default
  // it is. A sleeping engine starts from the saved state awake: its warm-up (1 s, 100 steps) passes
  // the half second after which a still body sleeps in both (b2_timeToSleep, home.sleep_time).
  struct Variant {
    const char *engine, *label, *profile;
    nlohmann::json settings;
    int max_n, warm_up;
  };
  const Variant variants[] = {
      {"home", "soft", "default", {{"resting", "soft"}}, 1'000'000, 5},
      {"home", "soft-sleep", "default", {{"resting", "soft"}, {"sleep_speed", 0.05}}, 1'000'000, 300},
      {"box2d", "stock-sleep", "stock", {{"allow_sleep", true}}, 10'000, 300},
  };
  for (const Variant& v : variants)
    for (int n = 100; n <= v.max_n; n *= 10)
      benchmark::RegisterBenchmark(fmt::format("settled/{}/{}/{}", v.engine, v.label, n).c_str(), step_benchmark,
                                   &find_engine(v.engine), std::string(v.profile), shared_settled_pile, n, v.warm_up,
                                   v.settings)
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime()
          ->MinTime(0.2);
  constexpr int kPourSteps = 100;  // one second of the scaled bowl (dt 0.01)
  benchmark::RegisterBenchmark("pour/home/default/bowl/1000000", step_benchmark, &find_engine("home"),
                               std::string("default"), bowl_scene, 1'000'000, 0, nlohmann::json::object())
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(kPourSteps);
}

}  // namespace ballbench::bench


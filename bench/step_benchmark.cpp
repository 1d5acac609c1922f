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
// step/ENGINE/PROFILE/settled/N times a pile at rest (settled_pile.h) from its saved state, the
// engine settled once per benchmark (Prepared); the variants soft-sleep (home) and stock-sleep
// (box2d) say their settings in the profile's place.
// step/ENGINE/PROFILE/fluid/N times the fluid (scaled_scene.h) over its first 3 s, the pour and
// the settle: 300 steps from the start, no warm-up; a ball that leaves the box (checked every 10
// steps, outside the timing) ends the benchmark as diverged.
//
// The settled piles and the fluid are judged against their scene's spec (spec_check.h) on states
// read outside the timing: the label says "spec met: overlap 0.0041 (<= 0.01), ..." or "spec not
// met: ...", and the counters spec_met (1 or 0) and overlap (the deepest after the timing's start,
// over the radius). A pile's spec: overlap <= 1%, at rest (RMS speed <= 0.01 sqrt(g r)); the fluid's
// overlap <= 2%, no ball out of the box.
//
// A benchmark whose steps (warm-up included) pass --budget_s (default 30 s) stops with an error
// that says how far it got and what a step cost: a slow engine is reported, not waited for.
//
// Read the ratios within one run, not the nanoseconds: the machines are shared.
#include <benchmark/benchmark.h>

#include "bench_main.h"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "process/process_engine.h"
#include "registry.h"
#include "scaled_scene.h"
#include "settled_pile.h"
#include "spec_check.h"

namespace ballbench::bench {
namespace {

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

// The fluid's window: its first 3 s.
constexpr int kFluidSteps = 300;
constexpr int kDivergenceCheckSteps = 10;

// The scene a benchmark times, built when the benchmark first runs (so a filter that leaves it out
// does not pay for it).
using SceneOf = const Scene& (*)(int n);
const Scene& gas_scene(int n) { return shared_scaled_scene(SceneKind::Gas, n); }
const Scene& bowl_scene(int n) { return shared_scaled_scene(SceneKind::Bowl, n); }
const Scene& fluid_scene(int n) { return shared_scaled_scene(SceneKind::Fluid, n); }

struct StepOptions {
  int warm_up = 5;
  bool check_divergence = false;  // read the state every kDivergenceCheckSteps steps, untimed
  // Before the warm-up, step until the engine's own pile is at rest again (RMS speed below
  // kSettledSpeed, read every kSettleCheckSteps steps; at most kSettleSteps steps or half the
  // budget): an engine starts from a saved state without the contact impulses that held it, so the
  // pile first sags and rebounds (measured for home at 10^4 balls: balls up to 0.65 m/s 1 s after
  // the start, at rest again after 6 s).
  bool settle = false;
  // Judge the run against the scene's spec (spec_check.h) on the states read untimed: where the
  // timing starts, every kDivergenceCheckSteps steps when those are read, and at the end.
  bool judge = false;
};

constexpr int kSettleCheckSteps = 50;

double rms_speed(const State& s) { return std::sqrt(s.vel.rowwise().squaredNorm().mean()); }

// A settled pile's engine, built, settled and warmed up on Google Benchmark's first run of its
// benchmark and kept for the later runs it makes to find how many steps fill the minimum time: the
// settling, seconds for an engine whose pile keeps moving, is paid once, and the later runs time
// the same pile at rest, a few steps on. One at a time: the next benchmark's setup frees it first.
struct Prepared {
  std::string name;  // the benchmark's
  std::unique_ptr<Engine> engine;
  double resident_before = 0;
  int settle_steps = 0;
  double start_rms = -1;
  std::unique_ptr<SpecCheck> check;
};
Prepared& prepared() {
  static Prepared p;
  return p;
}

void step_benchmark(benchmark::State& state, const std::string& name, const EngineEntry* entry, std::string profile,
                    SceneOf scene_of, int n, StepOptions options, nlohmann::json settings) {
  Prepared& kept = prepared();
  if (kept.name != name) kept = Prepared{};  // another benchmark's engine, freed before this one's is built
  const Scene& scene = scene_of(n);
  std::unique_ptr<Engine>& engine = kept.engine;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto seconds_since_start = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const int warm_up = options.warm_up;
  State read;
  int& settle_steps = kept.settle_steps;
  double& start_rms = kept.start_rms;
  if (!engine) try {
    // Memory the scene generator freed stays in the heap; the engine would reuse it, and the growth
    // would miss that share of what it holds (measured at 10^6 bowl balls: 126 bytes per ball
    // without this, 167 with it). Handed back first, the growth is the engine's whole footprint.
    ::malloc_trim(0);
    kept.resident_before = resident_bytes();
    settle_steps = 0, start_rms = -1;
    engine = entry->create(scene, profile, settings);
    const auto over_budget = [&](const std::string& where) {
      if (seconds_since_start() <= budget_seconds()) return false;
      state.SkipWithError(fmt::format("stopped at the {:.0f} s budget {}: {:.0f} ns per ball-step", budget_seconds(),
                                      where, seconds_since_start() * 1e9 / (static_cast<double>(settle_steps) * n))
                              .c_str());
      return true;
    };
    // The saved state is at rest; the sag comes in the steps after it, so the first check is after
    // some. Settling takes at most half the budget: an engine still moving then is timed as it is,
    // and start_rms_speed says so.
    const auto settling_time_left = [&] { return seconds_since_start() < 0.5 * budget_seconds(); };
    // Each phase plans its steps: an engine that steps ahead in batches (another process) never
    // carries steps paid for in one phase into the next, the timed one above all.
    if (options.settle) do {
        engine->plan_steps(kSettleCheckSteps);
        for (int k = 0; k < kSettleCheckSteps && settling_time_left(); ++k) {
          engine->step(scene.dt);
          ++settle_steps;
        }
        engine->read(read);
        start_rms = rms_speed(read);
      } while (start_rms >= kSettledSpeed && settle_steps < kSettleSteps && settling_time_left());
    engine->plan_steps(warm_up);
    for (int k = 0; k < warm_up; ++k) {
      engine->step(scene.dt);  // contacts, caches
      ++settle_steps;
      if (over_budget(fmt::format("in warm-up step {} of {}", k + 1, warm_up))) return;
    }
    if (options.settle) engine->read(read), start_rms = rms_speed(read), kept.name = name;
    if (options.judge) engine->read(read), kept.check = std::make_unique<SpecCheck>(scene), kept.check->sample(read);
  } catch (const std::exception& e) {
    engine.reset();
    state.SkipWithError(e.what());
    return;
  }
  engine->plan_steps(static_cast<long>(state.max_iterations));
  const auto timed_start = Clock::now();
  const std::optional<double> own_before = engine->own_step_seconds();
  long steps = 0;
  const auto ball_left_the_box = [&] {
    engine->read(read);
    if (kept.check) kept.check->sample(read);
    return left_the_box(scene, read);
  };
  const auto report_diverged = [&] {
    state.SkipWithError(fmt::format("diverged: a ball left the box by step {}", steps).c_str());
  };
  for (auto _ : state) {
    try {
      engine->step(scene.dt);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
    ++steps;
    if (options.check_divergence && steps % kDivergenceCheckSteps == 0) {
      state.PauseTiming();
      const bool left = ball_left_the_box();
      state.ResumeTiming();  // (before SkipWithError: the timer cannot resume after it)
      if (left) {
        report_diverged();
        break;
      }
    }
    if (seconds_since_start() > budget_seconds()) {
      const double timed = std::chrono::duration<double>(Clock::now() - timed_start).count();
      // A run slowed down by balls flying apart is a divergence, not a slow engine.
      if (options.check_divergence && steps % kDivergenceCheckSteps != 0 && ball_left_the_box()) {
        report_diverged();
        break;
      }
      state.SkipWithError(fmt::format("stopped at the {:.0f} s budget after {} timed steps: {:.0f} ns per ball-step",
                                      budget_seconds(), steps, timed * 1e9 / (static_cast<double>(steps) * n))
                              .c_str());
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
  // An engine in another process: its own step time as that process measured it, beside the
  // harness's, which adds the pipe (compare pipe/noop, the pipe alone).
  if (const auto own_after = engine->own_step_seconds(); own_before && own_after && steps > 0)
    state.counters["engine_process_ns_per_ball_step"] = (*own_after - *own_before) * 1e9 / (static_cast<double>(steps) * n);
  state.counters["peak_rss_bytes_per_ball"] = peak_resident_bytes() / n;
  state.counters["engine_bytes_per_ball"] = (resident_bytes() - kept.resident_before) / n;
  if (kept.check) {
    engine->read(read);
    kept.check->sample(read);
    state.SetLabel("spec " + kept.check->verdict(read));
    state.counters["spec_met"] = kept.check->met() ? 1 : 0;
    state.counters["overlap"] = kept.check->overlap();  // deepest after the timing's start, over the radius
  }
  if (options.settle) {
    state.counters["settle_steps"] = settle_steps;  // warm-up included
    state.counters["start_rms_speed"] = start_rms;  // m/s, when the first run's timed steps began
  }
  if (!options.settle) kept = Prepared{};  // only a settled pile's engine outlives its run: its setup is the costly one
}

}  // namespace

void register_benchmarks() {
  const auto add = [](const std::string& name, const EngineEntry* e, const std::string& profile, SceneOf scene, int n,
                      StepOptions options, nlohmann::json settings) {
    return benchmark::RegisterBenchmark(name.c_str(), step_benchmark, name, e, profile, scene, n, options,
                                        std::move(settings))
        ->Unit(benchmark::kMicrosecond)
        ->UseRealTime();
  };
  for (const auto& e : engine_registry()) {
    if (!e.info.unavailable.empty()) continue;  // an engine process that cannot run here (no Node)
    benchmark::AddCustomContext("engine." + e.info.name, e.info.version);
    for (const auto& profile : e.info.profiles)
      for (SceneKind kind : {SceneKind::Gas, SceneKind::Bowl})
        for (int n = 10; n <= e.info.bench.for_profile(profile).free_balls; n *= 10)
          add(fmt::format("step/{}/{}/{}/{}", e.info.name, profile, scene_kind_name(kind), n), &e, profile,
              kind == SceneKind::Gas ? gas_scene : bowl_scene, n, {}, e.info.bench.settings);
  }
  // A pile at rest (settled_pile.h) from 10^2 balls, and the fluid from 10^3, each to the engine's
  // sizes (EngineInfo::bench).
  for (const auto& e : engine_registry())
    for (const auto& profile : e.info.profiles) {
      // Not engines whose every run is costly (engines in other processes, LAMMPS): settling a pile
      // takes them most of the budget, and the fluid's 300 steps of thousands of sub-steps each far more.
      if (e.info.costly_runs) continue;
      const BenchSizes& sizes = e.info.bench.for_profile(profile);
      for (int n = 100; n <= sizes.settled_balls; n *= 10)
        add(fmt::format("step/{}/{}/settled/{}", e.info.name, profile, n), &e, profile, shared_settled_pile, n,
            {.settle = true, .judge = true}, nlohmann::json::object());
      for (int n = 1000; n <= sizes.fluid_balls; n *= 10)
        add(fmt::format("step/{}/{}/fluid/{}", e.info.name, profile, n), &e, profile, fluid_scene, n,
            {.warm_up = 0, .check_divergence = true, .judge = true},
            nlohmann::json::object())
            ->Iterations(kFluidSteps);
    }
  // Variants with their settings in the name's profile place: sleeping, which every engine has off
  // unless asked (each adapter's README), for home's soft profile and for Box2D, whose default it
  // is. A sleeping engine's warm-up (1 s, 100 steps, after its pile is at rest) passes the half
  // second after which a still body sleeps in both (b2_timeToSleep, home.sleep_time).
  struct Variant {
    const char *engine, *label, *profile;
    nlohmann::json settings;
    int max_n, warm_up;
  };
  const Variant variants[] = {
      {"home", "soft-sleep", "soft", {{"sleep_speed", 0.05}}, 1'000'000, 100},
      {"box2d", "stock-sleep", "stock", {{"allow_sleep", true}}, 10'000, 100},
  };
  for (const Variant& v : variants)
    for (int n = 100; n <= v.max_n; n *= 10)
      add(fmt::format("step/{}/{}/settled/{}", v.engine, v.label, n), &find_engine(v.engine), v.profile,
          shared_settled_pile, n, {.warm_up = v.warm_up, .settle = true, .judge = true}, v.settings)
          ;
  // The engine process protocol's own cost: a Node process engine that moves nothing
  // (adapters/node/noop.js), so its time per step is the request, the reply and the state block
  // through the pipes, to read beside the Node engines' (engine_process_ns_per_ball_step is their
  // own step alone). Not in the registry, and named pipe/ rather than step/: it is not an engine,
  // so the report's scaling tables, which read step/ and pour/, leave it out of their ratios.
  static const EngineEntry noop = [] {
    ProcessEngineSpec spec;
    spec.name = "pipe";
    spec.command = {"node", "adapters/node/noop.js"};
    spec.cwd = BALLBENCH_SOURCE_DIR;
    spec.source = "step_benchmark";
    return process_engine_entry(spec);
  }();
  if (noop.info.unavailable.empty())
    for (int n = 10; n <= 1000; n *= 10)
      add(fmt::format("pipe/noop/default/gas/{}", n), &noop, "default", gas_scene, n, {}, nlohmann::json::object());
  constexpr int kPourSteps = 100;  // one second of the scaled bowl (dt 0.01)
  add("pour/home/default/bowl/1000000", &find_engine("home"), "default", bowl_scene, 1'000'000, {.warm_up = 0},
      nlohmann::json::object())
      ->Unit(benchmark::kMillisecond)
      ->Iterations(kPourSteps);
}

}  // namespace ballbench::bench

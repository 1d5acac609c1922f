#pragma once
// Runs one engine on one scene: builds it, steps it, times the steps, samples states into metrics.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cost_pace.h"
#include "engine.h"
#include "metrics/metrics_config.h"
#include "result.h"
#include "scene.h"

namespace ballbench {

class TrajectoryCsv;
struct RecordedReference;

// How Result::skipped's note for an engine read only every k steps (Engine::state_stride) begins:
// "tunnelling judged on samples every k steps: ...". `run` prints it under its table.
inline constexpr const char* kStrideNote = "tunnelling judged on samples";

// Sub-steps per step of a converged reference run: at dt / 64 a first-order engine's error is 64
// times smaller than at dt, as Erez, Tassa and Todorov (ICRA 2015) took their reference runs.
inline constexpr int kConvergedSubsteps = 64;

// How often a run with RunOptions::cost_limit reads the CPU clock (a system call): every this many
// steps, and after any step that brings this much engine time (s) since the last read, so a slow
// step (a dense solver on thousands of balls: minutes for 64 of them) is stopped after itself.
inline constexpr long kCostCheckSteps = 64;
inline constexpr double kCostCheckSeconds = 0.05;

// A step this long (s, the engine's mean step so far) is timed on the process's CPU clock as well
// as the wall clock: a read is a system call (1.3 us on this VM, so 2.6% of such a step), and on a
// loaded core the wall time of the harness's work between steps (allocations, kernel entries, where
// a time slice ends) swells far more than the steps', so one share of CPU over wall for the whole
// run reads the steps low (a 0.08 s run of our solver as 0.04 - 0.06 s beside four CPU-bound jobs).
inline constexpr double kBracketStep_s = 100e-6;

// Timing passes (RunOptions::passes) end with one that is not kWarmGain faster than the one before,
// once the passes have spent kWarmSeconds of the engine's time. A JIT compiles its hot code as it
// runs, between pauses of its collector: box2d3's 500-step seed-box window took 41, 20, 10, 10, 11,
// 29, 16, 17, 9 and 18 ms in ten passes in one process. Stopped at the first pass that gained
// nothing, its cost there read 967 - 1 755 ns; after the passes of 0.25 s (eight), 849 - 912.
inline constexpr double kWarmGain = 0.1;
inline constexpr double kWarmSeconds = 0.25;

// The points of a window's pace (Result::window_pace): the engine time at the end of each
// 1/kWindowPoints of its steps.
inline constexpr int kWindowPoints = 16;
// The steps of a window of `steps` steps up to its pace's point i (0 .. kWindowPoints - 1).
inline long window_prefix_steps(long steps, int i) { return std::max(1L, steps * (i + 1) / kWindowPoints); }
// A timing runs the first prefix of a window that held this much of the engine's time (s) in its
// try, or the whole window: its passes and repeats then hold about a second of the engine's time.
inline constexpr double kTimedWindowSeconds = 0.2;

struct RunOptions {
  long steps = -1;               // < 0: the scene's duration / dt
  std::string profile;           // settings profile; "" = the engine's first
  nlohmann::json overrides = nlohmann::json::object();  // settings on top of the scene's table
  MetricsConfig metrics;
  TrajectoryCsv* trajectory = nullptr;
  // Run this engine (normally `exact`) in lockstep and report the error against it; null: none.
  const EngineEntry* reference = nullptr;
  // Where `reference` refuses the scene (exact: rough balls on each other under gravity): this
  // engine's first profile at dt / kConvergedSubsteps stands in, a converged run (registry.h's
  // converged_reference_engine()); null: no error is reported for such a scene.
  const EngineEntry* converged_reference = nullptr;
  // The reference recorded once for this scene (recorded_reference.h; run_all records it): replayed
  // where it is the one the run would step, instead of stepping it again. Null: stepped in lockstep.
  std::shared_ptr<const RecordedReference> recorded_reference;
  // Points kept in Result::series (energy, centre of mass, a few tracks) for the report's figures.
  int series_points = 300;
  // Whole-scene frames kept in Result::series for animations and the trajectory viewer (0: none):
  // about this many, every k-th sampled step; only for scenes of at most 1000 balls, whose frames
  // stay small.
  int frames = 0;
  // Stop the run (RunStatus::missed) at the first sample where a term of this spec whose figure
  // only grows (SpecTermDef::grows) is past its bound: the run can no longer meet it. Null: run on.
  const AccuracySpec* stop_on_miss = nullptr;
  // A window of steps [start, start + steps): the engine's time over it goes to
  // Result::window_engine_s, and over each of its first window_prefix_steps(steps, i) steps to
  // Result::window_pace; where `checkpoint` names a file, the state at its start is written there
  // as a scene running the window (core/scene_writer.h), to time the window, or a prefix of it, again.
  struct Window {
    long start = -1;  // < 0: none
    long steps = 0;
    std::string checkpoint;
  } window;
  // Stop the run (RunStatus::over_cost) once the engine's CPU time (Result::engine_cpu_s, read
  // every kCostCheckSteps steps or kCostCheckSeconds) passes `seconds`, or once that time projects
  // a whole run past kPaceMargin times `seconds` at its `pace` (cost_pace.h), or, with no pace, in
  // proportion to its steps past `linear_margin` times it; none: no limit. A search sets it to the
  // whole-run time of the cheapest configuration it has found, which a costlier one cannot beat, or
  // to a margin over its ceiling; `what` names that cost in the run's message.
  struct CostLimit {
    double seconds = 0;
    std::string what;
    std::optional<CostPace> pace{};
    std::optional<double> linear_margin{};  // none: no projection without a pace
  };
  std::optional<CostLimit> cost_limit;
  // Record the run's pace (Result::pace): its engine time at each 1/kPacePoints of its steps.
  bool record_pace = false;
  // Timing: the run made up to this many times in this process, each pass on a world built afresh
  // from the scene (an engine in a process of its own keeps that process), until the engine is warm
  // (kWarmGain, kWarmSeconds); the result is the last pass's, with the mean of the warm passes
  // (Result::warm). The passes warm the engine as a game's minutes of play would: a JIT's compiled
  // code, caches, the allocator's pages. 1: one run.
  int passes = 1;
  // The run ends at the first step boundary past this time (RunStatus::timed_out), keeping what it
  // measured (an isolated run's child sets it to its time limit; its parent kills a child stuck in
  // a step a grace later); none: no limit.
  std::optional<std::chrono::steady_clock::time_point> deadline;
  // For an engine in another process, run without a forked child (EngineInfo::own_process): a step
  // stuck past `wall_end`, or whose process spends `cpu_s` of CPU on it, ends the run there
  // (timed_out, over_cost) with that process killed (Engine::bound_step); `*_what` says the bound.
  struct StuckBound {
    std::optional<std::chrono::steady_clock::time_point> wall_end;
    std::string wall_what;
    std::optional<double> cpu_s;
    std::string cpu_what;
  } stuck;
  // Where the run's last good state is copied at its end (a run in this process only); null: nowhere.
  State* last_state = nullptr;
  // Called now and then with (steps done, steps total), for progress on long runs.
  std::function<void(long, long)> progress;
};

// Never throws for what an engine does (an exception from it marks the result "failed"); throws
// InputError for bad settings.
Result run_engine(const Scene& scene, const EngineEntry& entry, const RunOptions& options);

// XXH3-64 (xxHash) over the bytes of the doubles of the state in scene order, as they lie in memory
// (IEEE-754, little-endian on the machines we build for): the x column, the y column, then vx and
// vy, seeded with `seed`. The time is left out: it follows from the step count. Two states hash
// alike only if bit-identical (up to a 2^-64 chance), whatever precision the engine stepped in.
inline constexpr uint64_t kChecksumSeed = 0;
uint64_t state_checksum(const State& s, uint64_t seed = kChecksumSeed);

// The trajectory checksum: each state's checksum hashed onto the trajectory's so far, in step order.
uint64_t chain_checksum(uint64_t trajectory, uint64_t state);

// 16 lower-case hex digits.
std::string checksum_hex(uint64_t h);

// What a result says before anything runs: engine, version, limits, profile, scene, n, dt, steps,
// metrics configuration. Also the start of the results of runs that crashed or timed out.
Result result_header(const Scene& scene, const EngineEntry& entry, const RunOptions& options);

// The engine's settings overrides: the scene's [settings.NAME] table, then `overrides` on top.
nlohmann::json merged_settings(const Scene& scene, const std::string& engine, const nlohmann::json& overrides);

}  // namespace ballbench

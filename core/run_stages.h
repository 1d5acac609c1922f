#pragma once
// One run's stages (runner.h's run_engine is the list of them), each a function over one
// RunContext, as Box2D v3's step is a list of stages over b2StepContext. Each stage states what it
// reads and what it writes; the context holds nothing a stage does not pass on to a later one.
//
//   set_up            profile, capability refusal, the engine, its state stride
//   set_up_reference  the reference engine (or a converged stand-in) that runs in lockstep, or its recording
//   set_up_sampling   metrics, figures' and frames' spacing
//   read_initial      step 0: the first state, its metrics, figures and checksum
//   step_loop         steps, times and reads the engine until the last step or a stop
//   sample_last       the last good state, when the run ended between samples
//   final_metrics     metrics of the final state, the reference's summary, the skipped notes
//   timing            engine, harness and per-step times
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "engine.h"
#include "metrics/meter_set.h"
#include "metrics/reference_error.h"
#include "result.h"
#include "run_status.h"
#include "runner.h"
#include "scene.h"
#include "state.h"

namespace ballbench {

// CPU time of this process, every thread (s).
double process_cpu_seconds();

struct RunContext {
  RunContext(const Scene& scene, const EngineEntry& entry, const RunOptions& options);
  // Engines built here may hold references into it (the converged reference's scene): it stays put.
  RunContext(const RunContext&) = delete;
  RunContext& operator=(const RunContext&) = delete;

  // What is run: never changed by a stage.
  const Scene& scene;
  const EngineEntry& entry;
  const RunOptions& options;
  const bool rotation;  // the scene rotates: the engine must read back spins (decided once, not per step)

  Result r;  // filled stage by stage; its header (result_header) from the start

  // set_up: the engine and the steps at which it provides a state (1: every step).
  std::unique_ptr<Engine> engine;
  long stride = 1;
  std::optional<SpeedCap> speed_cap;  // the engine's, at this step and settings (EngineInfo::speed_cap)

  // set_up_reference: the reference, stepped ref_substeps times by ref_dt per step; null when none
  // runs (or it failed: `error` then holds why). ref_entry names what ran.
  const EngineEntry* ref_entry = nullptr;
  std::unique_ptr<Engine> reference;
  std::optional<ReferenceErrorTracker> error;
  State ref_state;
  int ref_substeps = 1;
  double ref_dt = 0;
  std::optional<Scene> converged_scene;  // the scene at a converged run's step

  // set_up_sampling: the meters of the metrics the scene calls for, and the steps at which they,
  // the figures and the frames sample.
  std::optional<MeterSet> metrics;
  long every = 1;         // the metrics' sample spacing, a multiple of the stride
  long series_every = 1;  // figures' spacing, a multiple of `every`
  long frame_every = 0;   // frames' spacing (0: no frames)

  // read_initial and step_loop: the last good state, the scratch the next one is read into, and
  // the checksums of the states the metrics saw.
  State state, next;
  double cost_checked_s = 0;  // engine_s when the cost limit was last checked
  uint64_t final_sum = 0, trajectory_sum = 0;
  long sampled = 0;  // the last step the sampled metrics saw

  // timing: the engine's step time, and when the harness started (on the clock and in the
  // process's CPU time).
  std::chrono::steady_clock::time_point harness_start;
  double harness_start_cpu = 0;
  double engine_s = 0;
  // The steps timed on the CPU clock as well (a long step: kBracketStep_s), their CPU and wall time.
  double bracketed_cpu_s = 0, bracketed_s = 0;
  double window_start_s = -1;  // engine_s where options.window began
};

// Reads: profile, scene, entry, options. Writes: r's status and error on refusal, r.settings,
// engine, stride, r.metrics_config.sample_every and the stride note. False: the run ends here.
bool set_up(RunContext& c);

// Reads: options.reference, options.converged_reference, scene. Writes: ref_entry, reference,
// error, ref_state, ref_substeps, ref_dt, converged_scene, and a skipped note when none can run.
void set_up_reference(RunContext& c);

// Reads: r.metrics_config, r.steps, options.series_points and frames. Writes: metrics, every,
// series_every, frame_every, and r.series' constant parts (radii, box).
void set_up_sampling(RunContext& c);

// Reads the engine's first state. Writes: state, the metrics' and figures' step 0, the trajectory
// file's first row, the checksums; on failure r's status and error. False: the run ends here.
bool read_initial(RunContext& c);

// Steps the engine (and the reference) to r.steps, timing the engine's steps alone. Writes: state,
// engine_s, r.steps_done, r.out_of_plane_max, the samples, the checksums; on a stop r.status,
// r.error and r.diverged_step, each set in one place by stop().
void step_loop(RunContext& c);

// Samples the last good state when the run ended between samples (steps_done past `sampled`).
void sample_last(RunContext& c);

// Reads: the final state, the meters, the reference's tracker. Writes: r.metrics (the final-state
// meters see the last good state first), r.events, r.reference, the skipped notes,
// r.series.final_pos and the checksums.
void final_metrics(RunContext& c);

// Reads: engine_s, harness_start, r.steps_done. Writes: r.engine_s, r.engine_process_s,
// r.harness_s, r.ns_per_step, r.ns_per_ball_step.
void timing(RunContext& c);

}  // namespace ballbench

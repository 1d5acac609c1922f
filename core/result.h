#pragma once
// One run of one engine on one scene: metrics, timing, versions, settings. Written as one JSON
// object; the report reads these files and nothing else.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <array>

#include "metrics/events.h"
#include "metrics/metric_values.h"
#include "metrics/metrics_config.h"
#include "metrics/reference_error.h"
#include "run_status.h"
#include "scene.h"

namespace ballbench {

struct Result {
  std::string engine, engine_version, profile;
  std::string engine_limits;  // EngineInfo::limits: what in the engine shapes its results
  std::string scene, scene_source;
  // The scene's content (scene_digest.h) and the harness build that ran it (build_id()): a report
  // reuses a run only of the same scene content and build. "" in files written before they were
  // recorded.
  std::string scene_digest, build;
  int64_t seed_offset = 0;  // the placement: added to the scene's random seeds (`run --seeds K`: 0 .. K-1)
  int n = 0;
  double dt = 0;
  long steps = 0;        // asked for
  long steps_done = 0;   // completed (less when the run diverged or failed)
  RunStatus status = RunStatus::ok;  // how the run ended (run_status.h); JSON "status", as text
  std::string error;
  // A clamp of the engine's that bound in this run (EngineInfo::speed_cap): what, which ball, when;
  // "" if none bound. JSON "clamped", present only then.
  std::string clamped;
  long diverged_step = -1;  // the step a diverged run stopped at
  // JSON "diverged", derived from the status.
  bool diverged() const { return status == RunStatus::diverged; }
  // The harness read states back from the engine: its metrics and timings are measurements (of the
  // steps done). A run refused, or one that failed, crashed or timed out before its first step, has
  // none: its JSON holds null for each, never a 0 that reads as a perfect, infinitely fast run.
  bool measured() const { return steps_done > 0; }
  // What the scene has (gravity, walls, elasticity...): which metrics mean something on it, for the
  // report. JSON "scene_features"; none in results files written before it was recorded.
  std::optional<SceneFeatures> scene_features;
  double engine_s = 0;          // engine step time summed over the run (s); JSON "engine_s"
  // The engine's own step time per step and per ball-step: self-timed by an engine in another
  // process (engine_process_s), the harness's timing of step() for every other.
  double ns_per_step = 0;
  double ns_per_ball_step = 0;
  double harness_s = 0;         // reading states, metrics and trajectory output (s)
  // Engines in another process (adapters/process/): their step time as that process measured it
  // around its own step calls (s), beside engine_s, which adds the pipe. JSON "engine_process_s"
  // and "ns_per_ball_step_pipe" (engine_s per ball-step), present only for such engines.
  std::optional<double> engine_process_s;
  // The engine's step time as CPU time (s): a long step's on the process's CPU clock, a short one's
  // wall time times the share of the run's wall time the process spent on a core (more than 1 for an
  // engine's own threads), so that a run sharing the cores with other work is costed nearly as one
  // alone (core/runner.h, kBracketStep_s); for an engine in another process, its own step time less
  // its wait for a core. JSON "engine_cpu_s"; runs that time it.
  std::optional<double> engine_cpu_s;
  // What a search costs the engine by: its CPU time where the run timed it, else its own step
  // clock's, else the harness's (s). Load barely changes it.
  double cost_s() const { return engine_cpu_s.value_or(engine_process_s.value_or(engine_s)); }
  // A timing's warm passes (RunOptions::passes): each from the first that was not kWarmGain faster
  // than the one before, their count and their mean cost_s() and engine_s (s). A timing reads this
  // mean over a quarter of a second of passes where one pass of a window of milliseconds would read
  // a cache miss. JSON "warm"; none for a run of one pass, or one whose passes all grew faster.
  struct WarmPasses {
    int count = 0;
    double cost_s = 0, engine_s = 0;
  };
  std::optional<WarmPasses> warm;
  // The engine's step time over RunOptions::window (s), by its own clock where it has one
  // (engine_process_s's), else its long steps' CPU time and its short steps' wall time (the window's
  // clock): how that window's cost relates to the whole run's. JSON "window_engine_s"; none for a run
  // without a window or one that stopped in it.
  std::optional<double> window_engine_s;
  // The engine's time over the whole run on the window's clock (s), where the run measured its
  // window: the window's share of the run is window_engine_s over this, both on one clock. Over
  // engine_cpu_s, whose short steps are their wall time scaled by the run's CPU share, the share of
  // a run that waited for a core reads high (its wall time over its CPU time: 2.2 times for home on
  // rolling-balls beside another search), and its timing alone low by as much. JSON "window_clock_s".
  std::optional<double> window_clock_s;
  // The engine's time (the same clock) from the window's start to each of its points
  // (window_prefix_steps), as far as the run went: a prefix of the window holding enough time to
  // time is timed instead of the whole. JSON "window_pace".
  std::vector<double> window_pace;
  // The run's pace where RunOptions::record_pace asked for it: the engine's time (by the window's
  // clock) at each 1/kPacePoints of its steps, as far as it went (a shape: a projection takes its
  // ratios, to CPU time). JSON "pace"; absent when not recorded.
  std::vector<double> pace;
  double out_of_plane_max = 0;  // 3D engines: max |z| position or velocity seen (see Engine)
  // Every metric of the run's states by catalog key (metrics/catalog.h), as its meters measured
  // them; none for a metric its scene does not call for, or a run not measured.
  MetricValues metrics;
  // Where and when: the run's first kEventsKept tunnelling and sticking events (metrics/events.h),
  // in the order counted; metrics' counts are the totals.
  std::vector<Event> events;
  ReferenceErrorSummary reference;  // error against `exact`, when it ran alongside
  std::vector<std::string> skipped;  // metrics not computed for this scene, each with the reason
  // Sampled every ~steps / RunOptions::series_points steps, for figures: time (s), energy (J),
  // centre of mass (m), position RMS error against the reference (m; empty without one), the
  // tracks of the first few balls (x, y per sample) and every ball's final position (n <= 5000).
  struct Series {
    std::vector<double> t, energy, com_x, com_y, pos_err;
    std::vector<std::vector<std::array<double, 2>>> tracks;
    std::vector<std::array<double, 2>> final_pos;
    // Every ball's position at evenly spaced times, for animations (RunOptions::frames; empty
    // unless asked): frame_t[k] is the time of frames[k]; positions rounded to 0.1 mm.
    std::vector<double> frame_t;
    std::vector<std::vector<std::array<double, 2>>> frames;
    std::vector<double> radius;  // every ball's radius (m), with frames
    std::optional<std::array<double, 4>> box;  // container x0, y0, x1, y1 (m), for pictures
    double radius_mean = 0;                    // (m), for pictures
  } series;
  MetricsConfig metrics_config;
  nlohmann::json settings = nlohmann::json::object();  // the engine's effective settings
  // XXH3 checksums (16 hex digits; state_checksum and chain_checksum in runner.h) of the last state
  // the metrics saw and of every such state, step 0 to steps_done in order: equal checksums mean
  // bit-identical runs. JSON: "checksum": {"final": ..., "trajectory": ...}.
  // Empty when no state was read (unsupported, failed to build, crashed, timed out).
  std::string checksum_final, checksum_trajectory;
};

// "engine" for an engine with one profile, "engine/profile" otherwise: how tables and the
// trajectory CSV name a run.
std::string run_label(const std::string& engine, const std::string& profile);
std::string run_label(const Result& r);

nlohmann::json to_json(const Result& r);
Result result_from_json(const nlohmann::json& j);

// Reading checks each run's counts (0 <= steps_done <= steps, n >= 0) and that no run is listed
// twice (one scene, engine, profile, placement, step and settings): a field out of range or a
// repeat is an InputError naming the run ("runs[3].steps_done: ...").
// Writes `results` as a JSON array to `path`, via a temporary file and a rename, so a reader never
// sees half a file.
void write_results_file(const std::string& path, const std::vector<Result>& results);
std::vector<Result> read_results_file(const std::string& path);

}  // namespace ballbench

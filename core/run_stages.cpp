#include "run_stages.h"

#include <time.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "input_error.h"
#include "interrupt.h"
#include "recorded_reference.h"
#include "scene_writer.h"
#include "spec_verdict.h"
#include "data_file.h"
#include "trajectory_csv.h"

namespace ballbench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Ends the run as `status` with `message`; a diverged run records the step it diverged at. Always
// false, so a stage returns stop(...) to end the run.
bool stop(RunContext& c, RunStatus status, long step, std::string message) {
  c.r.status = status;
  c.r.error = std::move(message);
  if (status == RunStatus::diverged) c.r.diverged_step = step;
  return false;
}

// A scene that rotates is judged on its spins too: an engine that reads none back fails the run.
bool spins_missing(const RunContext& c, const State& s) {
  return c.rotation && (s.w.size() != c.scene.n() || s.angle.size() != c.scene.n());
}

// The state at step k for the figures: the reference error, a frame, and every series_every steps
// (and at the last step) a point of each series.
void record(RunContext& c, long k) {
  const Scene& scene = c.scene;
  const State& state = c.state;
  Result::Series& series = c.r.series;
  if (c.reference) c.error->observe(state, c.ref_state);
  if (c.frame_every && k % c.frame_every == 0) {
    auto& frame = series.frames.emplace_back(scene.n());
    for (int b = 0; b < scene.n(); ++b)
      frame[b] = {std::round(state.pos(b, 0) * 1e4) / 1e4, std::round(state.pos(b, 1) * 1e4) / 1e4};
    series.frame_t.push_back(state.t);
  }
  if (k % c.series_every != 0 && k != c.r.steps) return;
  series.t.push_back(state.t);
  series.energy.push_back(c.metrics->now(Metric::energy_final).value_or(0.0));
  const Eigen::Vector2d com = state.pos.transpose() * scene.mass / scene.mass.sum();
  series.com_x.push_back(com.x()), series.com_y.push_back(com.y());
  if (c.reference) series.pos_err.push_back(c.error->summary().pos_rms_final);
  for (size_t b = 0; b < series.tracks.size(); ++b) series.tracks[b].push_back({state.pos(b, 0), state.pos(b, 1)});
}

// The sampled metrics, the figures and the checksums see the state of step k; an interrupt cuts
// the initial one short (run_engine).
void sample(RunContext& c, long k) {
  c.sampled = k;
  c.metrics->sample(c.state, k == 0);
  record(c, k);
  c.final_sum = state_checksum(c.state), c.trajectory_sum = chain_checksum(c.trajectory_sum, c.final_sum);
}

// A ball at the engine's speed cap (to 1e-4: a float32 engine's clamped speed is the cap to
// its precision) is where the clamp bound: noted once, with the first such ball.
void note_clamp(RunContext& c) {
  if (!c.speed_cap || !c.r.clamped.empty() || c.state.n() == 0) return;
  Eigen::Index ball = 0;
  const double fastest2 = c.state.vel.rowwise().squaredNorm().maxCoeff(&ball);
  const double cap = c.speed_cap->m_per_s;
  if (!(fastest2 >= cap * cap * (1 - 2e-4))) return;
  c.r.clamped = fmt::format("{} (a speed cap of {:.4g} m/s) bound: ball {} at {:.4g} m/s at t = {:g} s",
                            c.speed_cap->what, cap, ball, std::sqrt(fastest2), c.state.t);
}

// The reference steps with the engine, every step; it is read only where the engine is. Its
// failure ends the comparison only.
void step_reference(RunContext& c, long k, bool read) {
  if (!c.reference) return;
  try {
    for (int sub = 0; sub < c.ref_substeps; ++sub) c.reference->step(c.ref_dt);
    if (read) c.reference->read(c.ref_state);
  } catch (const std::exception& e) {
    c.error->reference_failed(k, e.what());
    c.reference.reset();
  }
}

// The engine's step time so far as CPU time: its long steps on the CPU clock (kBracketStep_s), the
// others' wall time times the share of the wall time since the harness started that this process
// spent on a core (more than 1 for an engine's own threads); for an engine in another process, the
// step time it measured itself less its wait for a core. A short step is not timed on the CPU
// clock: the read, a system call, would cost more than the step. On a loaded core that share reads
// short steps low (the harness's work between them is where time slices end), their wall time
// high (a slice that ends inside a step of microseconds adds milliseconds).
double engine_cpu_seconds(const RunContext& c) {
  if (const auto alone = c.engine->own_step_cpu_seconds()) return *alone;
  if (const auto own = c.engine->own_step_seconds()) return *own;
  const double wall = seconds_since(c.harness_start);
  const double share = wall > 0 ? (process_cpu_seconds() - c.harness_start_cpu) / wall : 1.0;
  return c.bracketed_cpu_s + (c.engine_s - c.bracketed_s) * share;
}

// The engine's time so far by its own clock where it has one (an engine in another process, which
// may step ahead in batches: the harness's clock around a step would hold a whole batch), else its
// long steps on the CPU clock and its short ones on the wall clock. The pace and the window are
// read from it: it never runs backwards, which engine_cpu_seconds may as a run's share falls.
double engine_clock_s(const RunContext& c) {
  if (const auto own = c.engine->own_step_seconds()) return *own;
  return c.bracketed_cpu_s + (c.engine_s - c.bracketed_s);
}

// Why the run is past its cost limit at step k: its engine time so far passed it, or, from
// kPaceFrom of its steps on, projects a whole run past its margin over it (at the limit's pace, or
// in proportion to its steps where it has none and a margin for that).
std::optional<std::string> past_cost_limit(const RunContext& c, const RunOptions::CostLimit& limit, long k) {
  const double spent = engine_cpu_seconds(c);
  if (spent > limit.seconds)
    return fmt::format("its engine time passed {:.3g} s at step {} (t = {:g} s), {}", limit.seconds, k, c.state.t,
                       limit.what);
  if (!limit.pace && !limit.linear_margin) return std::nullopt;
  const double share = double(k) / double(std::max(1L, c.r.steps));
  const double margin = limit.pace ? kPaceMargin : *limit.linear_margin;
  if (const auto whole = whole_run_cost(spent, share, limit.pace ? &*limit.pace : nullptr);
      whole && *whole > margin * limit.seconds)
    return fmt::format("its engine time of {:.3g} s at step {} (t = {:g} s), {}, projects {:.3g} s for the run, past "
                       "{:g} times {:.3g} s, {}",
                       spent, k, c.state.t,
                       limit.pace ? "grown as its engine's pace grows from there" : "in proportion to its steps",
                       *whole, margin, limit.seconds, limit.what);
  return std::nullopt;
}

// The window of steps options.window asks for: its start's state written as a scene, and the
// engine's time over it.
void window(RunContext& c, long k) {
  const RunOptions::Window& w = c.options.window;
  if (w.start < 0) return;
  if (k == w.start) {
    c.window_start_s = engine_clock_s(c);
    if (!w.checkpoint.empty()) {
      const std::string name = c.scene.name + "-window";
      write_file_atomically(w.checkpoint, scene_at_state(c.scene, c.state, name, double(w.steps) * c.scene.dt).text,
                            "the window's scene");
    }
  }
  if (c.window_start_s < 0) return;
  // A window of fewer steps than points has points that share a step: each gets its time.
  while (int(c.r.window_pace.size()) < kWindowPoints &&
         k == w.start + window_prefix_steps(w.steps, int(c.r.window_pace.size())))
    c.r.window_pace.push_back(engine_clock_s(c) - c.window_start_s);
  if (k == w.start + w.steps) c.r.window_engine_s = engine_clock_s(c) - c.window_start_s;
}

// Step k of the loop: the engine's step (timed), then, where the engine provides a state, its
// reading, the per-step checks, the reference and the samples. False: the run stops here.
bool advance(RunContext& c, long k) {
  Result& r = c.r;
  if (interrupt_signal())  // SIGINT or SIGTERM: end at this step boundary, keeping what was measured
    return stop(c, RunStatus::interrupted, k,
                fmt::format("interrupted by {} after step {}", interrupt_name(), r.steps_done));
  // On the CPU clock too where the engine's steps are long (kBracketStep_s).
  const bool bracket = r.steps_done > 0 && c.engine_s >= kBracketStep_s * double(r.steps_done) &&
                       !c.engine->own_step_seconds();
  const double cpu0 = bracket ? process_cpu_seconds() : 0.0;
  const auto t0 = Clock::now();
  if (c.options.deadline && t0 >= *c.options.deadline)
    return stop(c, RunStatus::timed_out, k,
                fmt::format("the time limit passed after step {} of {}: stopped there, its figures kept",
                            r.steps_done, r.steps));
  try {
    c.engine->step(c.scene.dt);
  } catch (const StepStuck& e) {
    c.engine_s += seconds_since(t0);
    const RunOptions::StuckBound& b = c.options.stuck;
    const std::string after = fmt::format("after step {} of {}", r.steps_done, r.steps);
    switch (e.by) {
      case StepStuck::By::cpu:
        return stop(c, RunStatus::over_cost, k,
                    fmt::format("its process spent {:.3g} s of CPU inside a step {}, {}: killed", e.cpu_s, after,
                                b.cpu_what));
      case StepStuck::By::time_limit:
        return stop(c, RunStatus::timed_out, k,
                    fmt::format("no result within {} {} (stuck in a step): killed", b.wall_what, after));
      case StepStuck::By::interrupt:
        return stop(c, RunStatus::interrupted, k,
                    fmt::format("interrupted by {} {}, its engine's process stuck in the step: killed",
                                interrupt_name(), after));
    }
  } catch (const std::exception& e) {
    c.engine_s += seconds_since(t0);
    return stop(c, RunStatus::failed, k, fmt::format("step {} threw: {}", k, e.what()));
  }
  const double stepped_s = seconds_since(t0);
  c.engine_s += stepped_s;
  if (bracket) c.bracketed_cpu_s += process_cpu_seconds() - cpu0, c.bracketed_s += stepped_s;
  if (k % c.stride != 0 && k != r.steps) {  // no state to read before the engine's next sample
    step_reference(c, k, false);
    return true;
  }
  // Read into a scratch state and keep it only if finite: a run that blew up ends with its last
  // good state, from which the final figures (positions, jitter, speed distribution) come.
  try {
    c.engine->read(c.next);
  } catch (const std::exception& e) {
    return stop(c, RunStatus::failed, k, fmt::format("step {}: reading the state threw: {}", k, e.what()));
  }
  if (spins_missing(c, c.next))
    return stop(c, RunStatus::failed, k,
                fmt::format("step {}: the engine read back no angular velocities and angles", k));
  r.out_of_plane_max = std::max(r.out_of_plane_max, c.engine->out_of_plane());
  // Tunnelling, every step, with finiteness and leaving the box in the same sweep: after a state
  // that is not finite or a ball out of the box, the run ends with the state before.
  c.metrics->motion(c.state, c.next);
  if (const auto why = c.metrics->stop_after_motion())
    return stop(c, RunStatus::diverged, k, fmt::format("{} at step {}", *why, k));
  std::swap(c.state, c.next);
  note_clamp(c);
  step_reference(c, k, true);
  if (c.options.trajectory) c.options.trajectory->write(r.engine, r.profile, k, c.state);
  r.steps_done = k;
  window(c, k);
  if (c.options.record_pace)
    for (const size_t reached = pace_points_reached(k, r.steps); r.pace.size() < reached;) r.pace.push_back(engine_clock_s(c));
  if (const auto& limit = c.options.cost_limit;
      limit && (k % kCostCheckSteps == 0 || c.engine_s - c.cost_checked_s > kCostCheckSeconds)) {
    c.cost_checked_s = c.engine_s;
    if (const auto why = past_cost_limit(c, *limit, k)) return stop(c, RunStatus::over_cost, k, *why);
  }
  if (k % c.every == 0 || k == r.steps) {
    sample(c, k);
    if (const auto why = c.metrics->stop_after_sample())
      return stop(c, RunStatus::diverged, k, fmt::format("{} at step {}", *why, k));
    if (c.options.stop_on_miss)
      if (const auto why = grown_past(*c.options.stop_on_miss, *c.metrics))
        return stop(c, RunStatus::missed, k, fmt::format("{} at t = {:g} s (step {})", *why, c.state.t, k));
  }
  return true;
}

}  // namespace

RunContext::RunContext(const Scene& scene_, const EngineEntry& entry_, const RunOptions& options_)
    : scene(scene_),
      entry(entry_),
      options(options_),
      rotation(scene_.features().rotation),
      r(result_header(scene_, entry_, options_)) {}

bool set_up(RunContext& c) {
  Result& r = c.r;
  const EngineEntry& entry = c.entry;
  // Every engine's profiles are checked here, once, against what it declares.
  const auto& profiles = entry.info.profiles;
  if (std::find(profiles.begin(), profiles.end(), r.profile) == profiles.end())
    throw InputError(
        fmt::format("{}: unknown profile '{}' (known: {})", entry.info.name, r.profile, fmt::join(profiles, ", ")));

  if (std::string why = unsupported_reason(entry.info, c.scene); !why.empty())
    return stop(c, RunStatus::unsupported, 0, why);

  try {
    c.engine = entry.create(c.scene, r.profile, merged_settings(c.scene, entry.info.name, c.options.overrides));
  } catch (const InputError&) {
    throw;
  } catch (const SceneUnsupported& e) {  // a limit only the engine can judge: reported as a capability refusal
    r.settings = e.settings();
    return stop(c, RunStatus::unsupported, 0, e.what());
  } catch (const std::exception& e) {
    return stop(c, RunStatus::failed, 0, fmt::format("building the world failed: {}", e.what()));
  }
  r.settings = c.engine->settings();
  c.engine->plan_steps(r.steps);
  c.engine->bound_step(c.options.stuck.wall_end, c.options.stuck.cpu_s);
  if (entry.info.speed_cap) c.speed_cap = entry.info.speed_cap(c.scene.dt, r.settings);
  // An engine that provides a state only every `stride` steps is read at those steps alone: every
  // per-step metric (tunnelling, finiteness, leaving the box) is judged on those samples, and the
  // sampled metrics see a multiple of the stride.
  const long stride = c.stride = std::max(1, c.engine->state_stride());
  if (stride > 1) {
    r.metrics_config.sample_every = static_cast<int>((r.metrics_config.sample_every + stride - 1) / stride * stride);
    r.skipped.push_back(fmt::format("{} every {} steps: {} provides states only every {} steps, so tunnelling and the "
                                    "finiteness check see those samples, not every step",
                                    kStrideNote, stride, entry.info.name, stride));
  }
  return true;
}

// A reference that cannot run the scene faithfully is never compared against: a converged run of
// another engine stands in, or there is none. A recording of it made for this scene is replayed.
void set_up_reference(RunContext& c) {
  const Scene& scene = c.scene;
  const ReferenceChoice choice = choose_reference(scene, c.options);
  if (!choice.skipped.empty()) c.r.skipped.push_back(choice.skipped);
  c.ref_entry = choice.entry;
  c.ref_substeps = choice.substeps;
  c.ref_dt = scene.dt / choice.substeps;
  if (!c.ref_entry) return;
  c.error.emplace(scene);
  if (c.ref_substeps > 1) {
    c.converged_scene = scene;
    c.converged_scene->dt = c.ref_dt;
  }
  const auto& recorded = c.options.recorded_reference;
  try {
    if (recorded && recording_fits(*recorded, scene, choice, c.r.steps)) {
      if (recorded->failed_step == 0) throw std::runtime_error(recorded->failure);
      c.reference = replay_reference(recorded);
    } else {
      const Scene& ref_scene = c.converged_scene ? *c.converged_scene : scene;
      c.reference = c.ref_entry->create(ref_scene, c.ref_entry->info.profiles.front(),
                                        merged_settings(scene, c.ref_entry->info.name, {}));
    }
    c.reference->read(c.ref_state);
  } catch (const std::exception& e) {
    c.error->reference_failed(0, e.what());
    c.reference.reset();
  }
}

void set_up_sampling(RunContext& c) {
  const Scene& scene = c.scene;
  Result& r = c.r;
  c.metrics.emplace(scene, r.metrics_config);
  r.series.radius_mean = scene.radius.mean();
  if (scene.container.kind == ContainerKind::Box)
    r.series.box = {scene.container.min.x(), scene.container.min.y(), scene.container.max.x(), scene.container.max.y()};
  c.every = r.metrics_config.sample_every;  // a multiple of the stride
  // Figures take every sampled state they can, up to series_points of them.
  c.series_every = c.every * std::max(1L, r.steps / c.every / std::max(1, c.options.series_points));
  constexpr int kTracks = 4;
  r.series.tracks.resize(std::min(kTracks, scene.n()));
  constexpr int kMaxFrameBalls = 1000;
  // Every ceil(samples / frames)-th sample: at most frames + 1 of them, step 0 included.
  const int frames = c.options.frames;
  c.frame_every = frames > 0 && scene.n() <= kMaxFrameBalls
                      ? c.every * std::max(1L, (r.steps / c.every + frames - 1) / frames)
                      : 0;
  if (c.frame_every) r.series.radius.assign(scene.radius.data(), scene.radius.data() + scene.n());
}

bool read_initial(RunContext& c) {
  try {
    c.engine->read(c.state);
  } catch (const std::exception& e) {
    return stop(c, RunStatus::failed, 0, fmt::format("reading the initial state threw: {}", e.what()));
  }
  if (spins_missing(c, c.state))
    return stop(c, RunStatus::failed, 0,
                "the engine reads back no angular velocities and angles for a scene that rotates");
  c.trajectory_sum = kChecksumSeed;
  sample(c, 0);
  if (c.options.trajectory) c.options.trajectory->write(c.r.engine, c.r.profile, 0, c.state);
  return true;
}

void step_loop(RunContext& c) {
  const long steps = c.r.steps;
  const long report_every = std::max(1L, steps / 100);
  for (long k = 1; k <= steps; ++k) {
    if (!advance(c, k)) break;
    if (c.options.progress && k % report_every == 0) c.options.progress(k, steps);
  }
}

void sample_last(RunContext& c) {
  // A run that ended between samples: its last good state counts.
  if (c.sampled < c.r.steps_done) sample(c, c.r.steps_done);
}

void final_metrics(RunContext& c) {
  const Scene& scene = c.scene;
  const State& state = c.state;
  Result& r = c.r;
  c.metrics->final_state(state);
  c.metrics->write(r.metrics);
  r.events = c.metrics->events();
  for (std::string& note : c.metrics->notes()) r.skipped.push_back(std::move(note));
  if (!c.options.reference) r.skipped.push_back("error against the reference: no reference ran (--no-reference)");
  if (c.error) {
    r.reference = c.error->summary();
    // Named as it ran: "exact", or "chipmunk/tuned at dt/64" for a converged run.
    const auto& name = c.ref_entry->info.name;
    const std::string label = run_label(name, c.ref_entry->info.profiles.front());
    r.reference.reference = c.ref_substeps == 1 ? name : fmt::format("{} at dt/{}", label, c.ref_substeps);
    r.reference.reference_dt = c.ref_dt;
  }
  constexpr int kMaxFinalPositions = 5000;  // a picture of more balls is a grey smear anyway
  if (scene.n() <= kMaxFinalPositions)
    for (int b = 0; b < scene.n(); ++b) r.series.final_pos.push_back({state.pos(b, 0), state.pos(b, 1)});
  r.checksum_final = checksum_hex(c.final_sum), r.checksum_trajectory = checksum_hex(c.trajectory_sum);
  if (c.options.last_state) *c.options.last_state = state;
}

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void timing(RunContext& c) {
  Result& r = c.r;
  r.engine_s = c.engine_s;
  r.engine_cpu_s = engine_cpu_seconds(c);
  r.engine_process_s = c.engine->own_step_seconds();
  if (r.window_engine_s) r.window_clock_s = engine_clock_s(c);
  r.harness_s = std::max(0.0, seconds_since(c.harness_start) - c.engine_s);
  const long stepped = std::max(1L, r.steps_done);
  // The headline is the engine's own step time: an engine in another process times its step calls
  // itself, and the harness's time, which adds the pipe, stands beside it (engine_s).
  r.ns_per_step = r.engine_process_s.value_or(c.engine_s) * 1e9 / stepped;
  r.ns_per_ball_step = r.ns_per_step / std::max(1, r.n);
}

}  // namespace ballbench

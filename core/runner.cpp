#include "runner.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <optional>
#include <cmath>

#include <fmt/format.h>
#include <xxhash.h>
#include <fmt/ranges.h>

#include "input_error.h"
#include "interrupt.h"
#include "metrics/angle_of_repose.h"
#include "metrics/rolling.h"
#include "metrics/speed_distribution.h"
#include "trajectory_csv.h"

namespace ballbench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

// XXH3 (xxHash, Collet) over the raw bytes of the positions and velocities, column by column: it
// mixes every input bit into every output bit, so states of float32 values (whose low 29 mantissa
// bits are zero) are told apart in all 64 bits of the checksum, as doubles are.
// A state that rotates chains its angular velocities and angles on, so a state without rotation
// keeps the checksum it had before rotation existed.
uint64_t state_checksum(const State& s, uint64_t seed) {
  const auto bytes = [](const auto& m) { return sizeof(double) * static_cast<size_t>(m.size()); };
  const uint64_t p = XXH3_64bits_withSeed(s.pos.data(), bytes(s.pos), seed);
  const uint64_t v = XXH3_64bits_withSeed(s.vel.data(), bytes(s.vel), p);
  if (!s.rotates()) return v;
  return XXH3_64bits_withSeed(s.angle.data(), bytes(s.angle), XXH3_64bits_withSeed(s.w.data(), bytes(s.w), v));
}

uint64_t chain_checksum(uint64_t trajectory, uint64_t state) {
  return XXH3_64bits_withSeed(&state, sizeof state, trajectory);
}

std::string checksum_hex(uint64_t h) { return fmt::format("{:016x}", h); }

nlohmann::json merged_settings(const Scene& scene, const std::string& engine, const nlohmann::json& overrides) {
  nlohmann::json merged = scene.engine_settings.value(engine, nlohmann::json::object());
  merged.merge_patch(overrides);
  return merged;
}

Result result_header(const Scene& scene, const EngineEntry& entry, const RunOptions& options) {
  Result r;
  r.engine = entry.info.name;
  r.engine_version = entry.info.version;
  r.engine_limits = entry.info.limits;
  r.profile = options.profile.empty() ? entry.info.profiles.front() : options.profile;
  r.scene = scene.name;
  r.seed_offset = scene.seed_offset;
  r.scene_source = scene.source;
  r.n = scene.n();
  r.dt = scene.dt;
  r.steps = options.steps >= 0 ? options.steps : scene.steps();
  r.metrics_config = options.metrics;
  if (r.metrics_config.sample_every < 1) throw InputError("sample_every: must be at least 1");
  return r;
}

Result run_engine(const Scene& scene, const EngineEntry& entry, const RunOptions& options) {
  Result r = result_header(scene, entry, options);
  // Every engine's profiles are checked here, once, against what it declares.
  const auto& profiles = entry.info.profiles;
  if (std::find(profiles.begin(), profiles.end(), r.profile) == profiles.end())
    throw InputError(fmt::format("{}: unknown profile '{}' (known: {})", entry.info.name, r.profile, fmt::join(profiles, ", ")));

  if (std::string why = unsupported_reason(entry.info, scene); !why.empty()) {
    r.status = RunStatus::unsupported;
    r.error = why;
    return r;
  }

  std::unique_ptr<Engine> engine;
  try {
    engine = entry.create(scene, r.profile, merged_settings(scene, entry.info.name, options.overrides));
  } catch (const InputError&) {
    throw;
  } catch (const SceneUnsupported& e) {  // a limit only the engine can judge: reported as a capability refusal
    r.status = RunStatus::unsupported;
    r.error = e.what();
    r.settings = e.settings();
    return r;
  } catch (const std::exception& e) {
    r.status = RunStatus::failed;
    r.error = fmt::format("building the world failed: {}", e.what());
    return r;
  }
  r.settings = engine->settings();
  // An engine that provides a state only every `stride` steps is read at those steps alone: every
  // per-step metric (tunnelling, finiteness, leaving the box) is judged on those samples, and the
  // sampled metrics see a multiple of the stride.
  const long stride = std::max(1, engine->state_stride());
  if (stride > 1) {
    r.metrics_config.sample_every = static_cast<int>((r.metrics_config.sample_every + stride - 1) / stride * stride);
    r.skipped.push_back(fmt::format("{} every {} steps: {} provides states only every {} steps, so tunnelling and the "
                                    "finiteness check see those samples, not every step",
                                    kStrideNote, stride, entry.info.name, stride));
  }

  MetricsAccumulator metrics(scene, r.metrics_config);
  State state;
  // The reference runs in lockstep, outside the timed region; its failure ends the comparison only.
  // A reference that cannot run the scene faithfully is never compared against: a converged run of
  // another engine stands in, or there is none.
  std::unique_ptr<Engine> reference;
  std::optional<ReferenceErrorTracker> error;
  State ref_state;
  const EngineEntry* ref_entry = options.reference;
  int ref_substeps = 1;
  std::optional<Scene> converged_scene;  // the scene at a converged run's step
  double ref_dt = scene.dt;
  if (ref_entry) {
    if (const std::string why = unsupported_reason(ref_entry->info, scene); !why.empty()) {
      const EngineEntry* stand_in = options.converged_reference;
      if (stand_in && unsupported_reason(stand_in->info, scene).empty()) {
        ref_entry = stand_in, ref_substeps = kConvergedSubsteps;
      } else {
        r.skipped.push_back(fmt::format("error against the reference: {}, and no converged run stands in", why));
        ref_entry = nullptr;
      }
    }
  }
  if (ref_entry) {
    error.emplace(scene);
    if (ref_substeps > 1) {
      converged_scene = scene;
      converged_scene->dt = ref_dt = scene.dt / ref_substeps;
    }
    try {
      reference = ref_entry->create(converged_scene ? *converged_scene : scene, ref_entry->info.profiles.front(),
                                    merged_settings(scene, ref_entry->info.name, {}));
      reference->read(ref_state);
    } catch (const std::exception& e) {
      error->reference_failed(0, e.what());
      reference.reset();
    }
  }
  r.series.radius_mean = scene.radius.mean();
  if (scene.container.kind == ContainerKind::Box)
    r.series.box = {scene.container.min.x(), scene.container.min.y(), scene.container.max.x(), scene.container.max.y()};
  const long every = r.metrics_config.sample_every;  // a multiple of the stride
  // Figures take every sampled state they can, up to series_points of them.
  const long series_every = every * std::max(1L, r.steps / every / std::max(1, options.series_points));
  constexpr int kTracks = 4;
  r.series.tracks.resize(std::min(kTracks, scene.n()));
  constexpr int kMaxFrameBalls = 1000;
  // Every ceil(samples / frames)-th sample: at most frames + 1 of them, step 0 included.
  const long frame_every = options.frames > 0 && scene.n() <= kMaxFrameBalls
                               ? every * std::max(1L, (r.steps / every + options.frames - 1) / options.frames)
                               : 0;
  if (frame_every) r.series.radius.assign(scene.radius.data(), scene.radius.data() + scene.n());
  auto record = [&](long k) {
    if (reference) error->observe(state, ref_state);
    if (frame_every && k % frame_every == 0) {
      auto& frame = r.series.frames.emplace_back(scene.n());
      for (int b = 0; b < scene.n(); ++b)
        frame[b] = {std::round(state.pos(b, 0) * 1e4) / 1e4, std::round(state.pos(b, 1) * 1e4) / 1e4};
      r.series.frame_t.push_back(state.t);
    }
    if (k % series_every != 0 && k != r.steps) return;
    r.series.t.push_back(state.t);
    r.series.energy.push_back(metrics.summary().energy.final);
    const Eigen::Vector2d com = state.pos.transpose() * scene.mass / scene.mass.sum();
    r.series.com_x.push_back(com.x()), r.series.com_y.push_back(com.y());
    if (reference) r.series.pos_err.push_back(error->summary().pos_rms_final);
    for (size_t b = 0; b < r.series.tracks.size(); ++b) r.series.tracks[b].push_back({state.pos(b, 0), state.pos(b, 1)});
  };
  const auto harness_start = Clock::now();
  double engine_s = 0;
  State next;
  // A scene that rotates is judged on its spins too: an engine that reads none back fails the run.
  const bool rotation = scene.features().rotation;
  const auto spins_missing = [&](const State& s) {
    return rotation && (s.w.size() != scene.n() || s.angle.size() != scene.n());
  };
  try {
    engine->read(state);
  } catch (const std::exception& e) {
    r.status = RunStatus::failed;
    r.error = fmt::format("reading the initial state threw: {}", e.what());
    return r;
  }
  if (spins_missing(state)) {
    r.status = RunStatus::failed;
    r.error = "the engine reads back no angular velocities and angles for a scene that rotates";
    return r;
  }
  metrics.observe(state);
  record(0);
  if (options.trajectory) options.trajectory->write(r.engine, r.profile, 0, state);
  uint64_t final_sum = state_checksum(state), trajectory_sum = chain_checksum(kChecksumSeed, final_sum);

  // The reference steps with the engine, every step; it is read only where the engine is.
  auto step_reference = [&](long k, bool read) {
    if (!reference) return;
    try {
      for (int sub = 0; sub < ref_substeps; ++sub) reference->step(ref_dt);
      if (read) reference->read(ref_state);
    } catch (const std::exception& e) {
      error->reference_failed(k, e.what());
      reference.reset();
    }
  };
  const long report_every = std::max(1L, r.steps / 100);
  long sampled = 0;  // the last step the sampled metrics saw
  for (long k = 1; k <= r.steps; ++k) {
    if (interrupt_signal()) {  // SIGINT or SIGTERM: end at this step boundary, keeping what was measured
      r.status = RunStatus::interrupted;
      r.error = fmt::format("interrupted by {} after step {}", interrupt_name(), r.steps_done);
      break;
    }
    const auto t0 = Clock::now();
    try {
      engine->step(scene.dt);
    } catch (const std::exception& e) {
      engine_s += seconds_since(t0);
      r.status = RunStatus::failed;
      r.error = fmt::format("step {} threw: {}", k, e.what());
      break;
    }
    engine_s += seconds_since(t0);
    if (k % stride != 0 && k != r.steps) {  // no state to read before the engine's next sample
      step_reference(k, false);
      if (options.progress && k % report_every == 0) options.progress(k, r.steps);
      continue;
    }
    // Read into a scratch state and keep it only if finite: a run that blew up ends with its last
    // good state, from which the final figures (positions, jitter, speed distribution) come.
    try {
      engine->read(next);
    } catch (const std::exception& e) {
      r.status = RunStatus::failed;
      r.error = fmt::format("step {}: reading the state threw: {}", k, e.what());
      break;
    }
    if (spins_missing(next)) {
      r.status = RunStatus::failed;
      r.error = fmt::format("step {}: the engine read back no angular velocities and angles", k);
      break;
    }
    r.out_of_plane_max = std::max(r.out_of_plane_max, engine->out_of_plane());
    if (!metrics.observe_motion(state, next)) {  // tunnelling, every step, and finiteness in one sweep
      r.status = RunStatus::diverged, r.diverged_step = k;
      r.error = fmt::format("non-finite position or velocity at step {}", k);
      break;
    }
    // A ball out of the box: no figure of the run means anything from here; like a non-finite
    // state, the run ends with the state before.
    if (metrics.left_container()) {
      r.status = RunStatus::diverged, r.diverged_step = k;
      r.error = fmt::format("a ball left the container (beyond a wall by more than its diameter) at step {}", k);
      break;
    }
    std::swap(state, next);
    step_reference(k, true);
    if (options.trajectory) options.trajectory->write(r.engine, r.profile, k, state);
    r.steps_done = k;
    if (k % every == 0 || k == r.steps) {
      sampled = k;
      metrics.observe(state);
      record(k);
      final_sum = state_checksum(state), trajectory_sum = chain_checksum(trajectory_sum, final_sum);
      if (metrics.energy_blew_up()) {
        r.status = RunStatus::diverged, r.diverged_step = k;
        r.error =
            fmt::format("energy above {} x its initial value at step {}", options.metrics.divergence_energy_factor, k);
        break;
      }
    }
    if (options.progress && k % report_every == 0) options.progress(k, r.steps);
  }
  if (sampled < r.steps_done) {  // a run that ended between samples: its last good state counts
    metrics.observe(state);
    record(r.steps_done);
    final_sum = state_checksum(state), trajectory_sum = chain_checksum(trajectory_sum, final_sum);
  }
  r.metrics = metrics.summary();
  r.events = metrics.events();
  if (speed_distribution_applies(scene)) {
    r.speed_ks = rayleigh_ks_statistic(state);
    r.speed_ks_critical = rayleigh_ks_critical(scene.n());
  } else {
    r.skipped.push_back("speed distribution (Rayleigh KS): only for elastic, gravity-free, equal-mass scenes of >= 100 balls");
  }
  if (scene.features().gravity && scene.features().walls)
    r.jitter = std::sqrt(state.vel.rowwise().squaredNorm().mean());
  else
    r.skipped.push_back("jitter (final RMS speed): only for scenes with gravity and walls, where balls come to rest");
  if (scene.metrics.rolling) {
    const RollingClosedForm closed = rolling_closed_form(scene);
    r.rolling.speed = state.vel(0, 0);
    r.rolling.expected_speed = closed.speed;
    r.rolling.expected_time_to_roll = closed.time_to_roll;
  }
  if (scene.metrics.angle_of_repose) {
    r.angle_of_repose = angle_of_repose(state, scene);
    if (!r.angle_of_repose)
      r.skipped.push_back(fmt::format("{}: no flank of the final heap had {} columns within [{:g} H, {:g} H] of its "
                                      "height H (a layer spread flat, or a column standing)",
                                      kReposeUnmeasuredNote, kReposeMinColumns, kReposeBandLow, kReposeBandHigh));
  }
  if (scene.features().gravity || scene.features().walls)
    r.skipped.push_back("momentum drift is reported but not judged: walls and gravity change momentum");
  if (!r.metrics.slip.measured)
    r.skipped.push_back("slip and time to roll: only for scenes that rotate and have walls");
  if (!options.reference) r.skipped.push_back("error against the reference: no reference ran (--no-reference)");
  if (error) {
    r.reference = error->summary();
    // Named as it ran: "exact", or "chipmunk/tuned at dt/64" for a converged run.
    const auto& name = ref_entry->info.name;
    r.reference.reference =
        ref_substeps == 1 ? name : fmt::format("{} at dt/{}", run_label(name, ref_entry->info.profiles.front()), ref_substeps);
    r.reference.reference_dt = ref_dt;
  }
  constexpr int kMaxFinalPositions = 5000;  // a picture of more balls is a grey smear anyway
  if (scene.n() <= kMaxFinalPositions)
    for (int b = 0; b < scene.n(); ++b) r.series.final_pos.push_back({state.pos(b, 0), state.pos(b, 1)});
  r.checksum_final = checksum_hex(final_sum), r.checksum_trajectory = checksum_hex(trajectory_sum);
  r.engine_s = engine_s;
  r.engine_process_s = engine->own_step_seconds();
  r.harness_s = std::max(0.0, seconds_since(harness_start) - engine_s);
  const long stepped = std::max(1L, r.steps_done);
  r.ns_per_step = engine_s * 1e9 / stepped;
  r.ns_per_ball_step = r.ns_per_step / std::max(1, r.n);
  return r;
}

}  // namespace ballbench

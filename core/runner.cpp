#include "runner.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "input_error.h"
#include "trajectory_csv.h"

namespace ballbench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

bool finite(const State& s) { return s.pos.allFinite() && s.vel.allFinite(); }

constexpr uint64_t kFnvPrime = 1099511628211ull;

uint64_t fnv1a(uint64_t h, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * kFnvPrime;
  return h;
}

}  // namespace

uint64_t state_checksum(const State& s, uint64_t h) {
  for (int i = 0; i < s.n(); ++i) {
    const double v[4] = {s.pos(i, 0), s.pos(i, 1), s.vel(i, 0), s.vel(i, 1)};
    h = fnv1a(h, v, sizeof v);
  }
  return h;
}

uint64_t chain_checksum(uint64_t trajectory, uint64_t state) { return fnv1a(trajectory, &state, sizeof state); }

std::string checksum_hex(uint64_t h) { return fmt::format("{:016x}", h); }

nlohmann::json merged_settings(const Scene& scene, const std::string& engine, const nlohmann::json& overrides) {
  nlohmann::json merged = scene.engine_settings.value(engine, nlohmann::json::object());
  merged.merge_patch(overrides);
  return merged;
}

Result run_engine(const Scene& scene, const EngineEntry& entry, const RunOptions& options) {
  Result r;
  r.engine = entry.info.name;
  r.engine_version = entry.info.version;
  r.engine_limits = entry.info.limits;
  r.profile = options.profile.empty() ? entry.info.profiles.front() : options.profile;
  r.scene = scene.name;
  r.scene_source = scene.source;
  r.n = scene.n();
  r.dt = scene.dt;
  r.steps = options.steps >= 0 ? options.steps : scene.steps();
  r.metrics_config = options.metrics;

  if (std::string why = unsupported_reason(entry.info, scene); !why.empty()) {
    r.status = "unsupported";
    r.error = why;
    return r;
  }

  std::unique_ptr<Engine> engine;
  try {
    engine = entry.create(scene, r.profile, merged_settings(scene, entry.info.name, options.overrides));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    r.status = "failed";
    r.error = fmt::format("building the world failed: {}", e.what());
    return r;
  }
  r.settings = engine->settings();

  MetricsAccumulator metrics(scene, options.metrics);
  State state;
  const auto harness_start = Clock::now();
  double engine_s = 0;
  engine->read(state);
  metrics.observe(state);
  if (options.trajectory) options.trajectory->write(run_label(r), 0, state);
  uint64_t final_sum = state_checksum(state), trajectory_sum = chain_checksum(kFnvBasis, final_sum);

  const long report_every = std::max(1L, r.steps / 100);
  for (long k = 1; k <= r.steps; ++k) {
    const auto t0 = Clock::now();
    try {
      engine->step(scene.dt);
    } catch (const std::exception& e) {
      engine_s += seconds_since(t0);
      r.status = "failed";
      r.error = fmt::format("step {} threw: {}", k, e.what());
      break;
    }
    engine_s += seconds_since(t0);
    engine->read(state);
    r.out_of_plane_max = std::max(r.out_of_plane_max, engine->out_of_plane());
    if (!finite(state)) {
      r.status = "diverged", r.diverged = true, r.diverged_step = k;
      r.error = fmt::format("non-finite position or velocity at step {}", k);
      break;
    }
    metrics.observe(state);
    if (options.trajectory) options.trajectory->write(run_label(r), k, state);
    final_sum = state_checksum(state), trajectory_sum = chain_checksum(trajectory_sum, final_sum);
    r.steps_done = k;
    if (metrics.energy_blew_up()) {
      r.status = "diverged", r.diverged = true, r.diverged_step = k;
      r.error = fmt::format("energy above {} x its initial value at step {}", options.metrics.divergence_energy_factor, k);
      break;
    }
    if (options.progress && k % report_every == 0) options.progress(k, r.steps);
  }
  r.metrics = metrics.summary();
  r.checksum_final = checksum_hex(final_sum), r.checksum_trajectory = checksum_hex(trajectory_sum);
  r.wall_s = engine_s;
  r.harness_s = std::max(0.0, seconds_since(harness_start) - engine_s);
  const long stepped = std::max(1L, r.steps_done);
  r.ns_per_step = engine_s * 1e9 / stepped;
  r.ns_per_ball_step = r.ns_per_step / std::max(1, r.n);
  return r;
}

}  // namespace ballbench

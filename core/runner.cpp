#include "runner.h"

#include <chrono>

#include <fmt/format.h>
#include <xxhash.h>

#include "input_error.h"
#include "interrupt.h"
#include "machine_info.h"
#include "run_stages.h"
#include "scene_digest.h"

namespace ballbench {

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
  r.scene_digest = scene_digest(scene);
  r.build = build_id();
  r.scene_features = scene.features();
  r.n = scene.n();
  r.dt = scene.dt;
  r.steps = options.steps >= 0 ? options.steps : scene.steps();
  r.metrics_config = options.metrics;
  if (r.metrics_config.sample_every < 1) throw InputError("sample_every: must be at least 1");
  return r;
}

namespace {

void stop_if_asked() {
  if (interrupt_signal()) throw Interrupted{"setting up a run"};
}

// The run's stages (run_stages.h), in order. A stage that ends the run early (a refusal, a
// world that cannot be built or read) leaves the result as far as it got. Building and measuring
// the worlds of millions of balls takes seconds: an interrupt is looked for between the stages, and
// within them by our solvers' set-up loops and the initial state's meters (throwing Interrupted).
Result run_pass(const Scene& scene, const EngineEntry& entry, const RunOptions& options) {
  RunContext c(scene, entry, options);
  try {
    if (!set_up(c)) return std::move(c.r);
    stop_if_asked();
    set_up_reference(c);
    stop_if_asked();
    set_up_sampling(c);
    c.harness_start = std::chrono::steady_clock::now();
    c.harness_start_cpu = process_cpu_seconds();
    if (!read_initial(c)) return std::move(c.r);
  } catch (const Interrupted&) {  // asked to stop before the first step: the run ends there, marked
    c.r.status = RunStatus::interrupted;
    c.r.error = fmt::format("interrupted by {} before step 1", interrupt_name());
    return std::move(c.r);
  }
  step_loop(c);
  sample_last(c);
  final_metrics(c);
  timing(c);
  return std::move(c.r);
}

}  // namespace

Result run_engine(const Scene& scene, const EngineEntry& entry, const RunOptions& options) {
  Result last = run_pass(scene, entry, options);
  double spent = last.cost_s();
  Result::WarmPasses warm;
  for (int pass = 1; pass < options.passes && last.status == RunStatus::ok && !interrupt_signal(); ++pass) {
    Result r = run_pass(scene, entry, options);
    if (r.status != RunStatus::ok) return r;
    const bool warming = r.cost_s() < (1 - kWarmGain) * last.cost_s();
    spent += r.cost_s();
    if (!warming || warm.count > 0) ++warm.count, warm.cost_s += r.cost_s(), warm.engine_s += r.engine_s;
    last = std::move(r);
    if (!warming && spent >= kWarmSeconds) break;
  }
  if (warm.count > 0) {
    warm.cost_s /= warm.count, warm.engine_s /= warm.count;
    last.warm = warm;
  }
  return last;
}

}  // namespace ballbench

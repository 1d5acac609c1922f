#include "scaling_section.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "balls_text.h"
#include "json_value.h"
#include "figure_markdown.h"
#include "markdown_buffer.h"
#include "result.h"
#include "markdown_cell.h"
#include "no_data.h"
#include "ordered_set.h"
#include "spec_verdict.h"

namespace ballbench {
namespace {

// Engines in another process (adapters/process/): what is their step and what is the pipe.
void put_pipe_cost(MarkdownBuffer& put, const BenchResults& bench) {
  std::vector<const BenchRow*> rows;
  for (const BenchRow& r : bench.rows)
    if (r.error.empty() && r.pipe_ns_per_ball_step) rows.push_back(&r);
  if (rows.empty()) return;
  const auto pipe_at = [&](const std::string& scene, long n) -> const BenchRow* {
    for (const BenchRow& p : bench.pipe)
      if (p.scene == scene && p.n == n && p.error.empty()) return &p;
    return nullptr;
  };
  put("Engines in another process (`adapters/process/`, the Node engines) pay the pipe: a request for several steps, "
      "the reply and every step's state block. The engine's process times its own step calls (its ns per ball-step, "
      "as in the tables above); the harness times the whole round trips; `pipe/noop/default/SCENE/N` is a Node "
      "engine that moves nothing (`adapters/node/noop.js`), so its time is the pipe alone.\n\n");
  put("| engine | scene | balls | harness: step and pipe | its own step | pipe alone (`pipe/noop`) |\n"
      "|---|---|---:|---:|---:|---:|\n");
  for (const BenchRow* r : rows) {
    const BenchRow* p = pipe_at(r->scene, r->n);
    put("| {} | {} | {} | {:.0f} | {:.0f} | {} |\n", run_label(r->engine, r->profile), r->scene, r->n,
        *r->pipe_ns_per_ball_step, r->ns_per_ball_step, p ? fmt::format("{:.0f}", p->ns_per_ball_step) : kNoData);
  }
  put("\nns per ball-step. Source: `results/bench.json`.\n\n");
}

// Balls from which a benchmark's memory per ball is the balls' (see put_scaling).
constexpr long kMemoryBalls = 100000;

// The benchmark binary records the budget it ran under in its context (bench/bench_main.cpp).
void put_scaling_intro(MarkdownBuffer& put, const nlohmann::json& context) {
  const std::string budget_s = json_string_field(context, "budget_s");
  const std::string budget = budget_s.empty() ? "" : fmt::format(" ({} s here)", budget_s);
  put("## Scaling\n\n`bench/ballbench_step_benchmark` (Google Benchmark): step cost per ball on the scaled "
      "scenes. `gas`: elastic, no gravity; `bowl`: gravity, restitution 0.99; both at the seed's density in a box of "
      "side sqrt(5 n), timed after 5 warm-up steps from the start, so the bowl is timed early in its pour (from 10^5 "
      "balls on the balls are still falling). `settled`: a pile of balls of radius 0.25 (g 9.81, restitution 0.5) run "
      "until at rest, saved, and timed from the saved state once each engine's pile is at rest again (RMS speed "
      "below 1e-3 m/s: an engine starts without the contact impulses that held the pile, which sags and rebounds), "
      "then 5 warm-up steps (100 for the sleeping variants). "
      "`fluid`: the seed-bowl's 10 x 10 box, g 100, restitution 0.99, with n balls at its packing fraction (radius "
      "0.25 sqrt(72 / n)), timed over its first 3 s (300 steps from the start: the pour and the settle). Profiles "
      "`soft` and `soft-sleep` are `home` with `resting = \"soft\"` (and `sleep_speed = 0.05`), `stock-sleep` Box2D's "
      "stock profile with its sleeping on; an engine whose every ball sleeps does next to nothing in a step, so "
      "its figure is the cost of a pile at rest with sleeping, not of a solve. A benchmark that runs past its budget{} "
      "stops and is shown as failed, with how far it got and what a step cost below its table. Every engine "
      "runs at the scene's own step, whatever accuracy that gives it (`home`'s default profile builds itself for the "
      "scene's spec, the others do not), so these tables show how each engine's cost grows with the count, not "
      "which is cheaper: the equal-accuracy sections rank cost. Source: `results/bench.json`, Google Benchmark's own JSON.\n\n",
      budget);
}

// One scene's ns per ball-step, an engine a row, a ball count a column.
void put_scaling_table(MarkdownBuffer& put, const BenchResults& bench, const std::string& scene,
                       const std::vector<long>& counts, const std::vector<std::string>& engines) {
  put("ns per ball-step, `{}`:\n\n| engine |", scene);
  for (long n : counts) put(" {} |", n);
  put("\n|---|");
  for (size_t k = 0; k < counts.size(); ++k) put("---:|");
  put("\n");
  for (const auto& e : engines) {
    const bool has_rows = std::any_of(bench.rows.begin(), bench.rows.end(), [&](const BenchRow& r) {
      return r.scene == scene && run_label(r.engine, r.profile) == e;
    });
    if (!has_rows) continue;  // a variant of another scene
    put("| {} |", e);
    for (long n : counts) {
      std::string cell = "";
      for (const BenchRow& r : bench.rows)
        if (r.scene == scene && r.n == n && run_label(r.engine, r.profile) == e) {
          cell = !r.error.empty()            ? "failed"
                 : r.ns_per_ball_step >= 10 ? fmt::format("{:.0f}", r.ns_per_ball_step)
                                             : fmt::format("{:.2g}", r.ns_per_ball_step);
          if (r.spec_met == false) cell += " (spec not met)";
        }
      put(" {} |", cell);
    }
    put("\n");
  }
}

// Each of our solver's profiles: its rate and memory at its largest count. No ratio to another
// engine: each ran at the scene's own step, whatever accuracy that gives it.
void put_our_rates(MarkdownBuffer& put, const ReportInputs& in, const BenchResults& bench, const std::string& scene) {
  const auto sleeps = [](const std::string& profile) { return profile.ends_with("-sleep"); };
  std::vector<std::pair<std::string, std::string>> ours_runs;  // (engine, profile)
  for (const BenchRow& r : bench.rows)
    if (r.scene == scene && role_of(in, r.engine) == EngineRole::ours) add_once(ours_runs, {r.engine, r.profile});
  for (const auto& [engine, profile] : ours_runs) {
    // A pile asleep does no work in a step: its time is no solve, and a ratio or a rate of it no
    // measurement of one.
    if (sleeps(profile)) {
      put("\n`{}`: its balls sleep, so a step does next to nothing: its times above are the cost of a pile at rest "
          "with sleeping, not of a solve, and are not set against other engines.\n",
          run_label(engine, profile));
      continue;
    }
    const auto is_ours = [&](const BenchRow& r) { return r.engine == engine && r.profile == profile; };
    // The profile's largest run: rate and memory.
    const BenchRow* largest = nullptr;
    for (const BenchRow& r : bench.rows)
      if (r.scene == scene && is_ours(r) && r.error.empty() && (!largest || r.n > largest->n)) largest = &r;
    // Memory per ball only where the balls dominate it: below kMemoryBalls the process's fixed cost
    // (and the other benchmarks it ran) would be spread over a few balls.
    if (largest && largest->steps_per_s)
      put("\n`{}` at {}: {:.1f} steps per second{}.\n", run_label(engine, profile), balls_text(largest->n),
          *largest->steps_per_s,
          largest->n < kMemoryBalls
              ? std::string()
              : fmt::format("; memory {} bytes per ball (resident growth from a trimmed heap while the world was "
                            "built and run: what the engine holds), peak resident set of the benchmark process {} "
                            "bytes per ball",
                            largest->engine_bytes_per_ball ? fmt::format("{:.0f}", *largest->engine_bytes_per_ball) : kNoData,
                            largest->peak_rss_bytes_per_ball ? fmt::format("{:.0f}", *largest->peak_rss_bytes_per_ball)
                                                             : kNoData));
  }
}

// What did not go as planned on the scene: piles still moving when timed, failures, and the pour.
void put_scaling_notes(MarkdownBuffer& put, const ReportInputs& in, const BenchResults& bench, const std::string& scene) {
  // A settled pile that was still moving when its timed steps began (settling is bounded).
  std::vector<std::string> moving;
  for (const BenchRow& r : bench.rows)
    if (r.scene == scene && r.error.empty() && r.start_rms_speed && *r.start_rms_speed >= 1e-3)
      moving.push_back(fmt::format("{} at {} (RMS speed {:.2g} m/s after {:.0f} steps)", run_label(r.engine, r.profile),
                                   r.n, *r.start_rms_speed, r.settle_steps.value_or(0)));
  if (!moving.empty())
    put("\nNot at rest again within half the budget, so timed while still moving: {}.\n", fmt::join(moving, "; "));
  std::vector<std::string> failures;
  for (const BenchRow& r : bench.rows)
    if (r.scene == scene && !r.error.empty())
      failures.push_back(fmt::format("{} at {}: {}", run_label(r.engine, r.profile), r.n, markdown_cell(r.error)));
  if (!failures.empty()) put("\nFailed: {}.\n", fmt::join(failures, "; "));
  std::vector<std::string> judged, not_met;
  for (const BenchRow& r : bench.rows)
    if (r.scene == scene && r.spec_met) {
      add_once(judged, run_label(r.engine, r.profile));
      // The verdict without its first words: "overlap 0.031 > 0.02".
      if (!*r.spec_met)
        not_met.push_back(fmt::format("{} at {}: {}", run_label(r.engine, r.profile), r.n,
                                      markdown_cell(std::string(verdict_detail(r.spec)))));
    }
  if (!judged.empty())
    put("\nEach run judged against the scene's spec on the states read outside its timing (bench/spec_check.h: "
        "the overlap after the timing's start, a pile's rest speed, no ball out of the box): {}.\n",
        not_met.empty() ? std::string("every run met it") : fmt::format("not met by {}", fmt::join(not_met, "; ")));
  for (const BenchRow& r : bench.pour)
    if (r.scene == scene && role_of(in, r.engine) == EngineRole::ours && r.error.empty() && r.steps_per_s)
      put("\nOver the first second of the pour instead (100 steps from rest, no warm-up; `pour/{}/default/{}/{}`), "
          "`{}` at {} balls makes {:.1f} steps per second: balls reach the floor and pile up, and the grid's cells "
          "grow with the fastest fall (core/solver/PERFORMANCE.md).\n",
          r.engine, r.scene, r.n, r.engine, r.n, *r.steps_per_s);
}

void put_scaling(MarkdownBuffer& put, const ReportInputs& in, const BenchResults& bench,
                 const std::vector<Figure>& figures) {
  put_scaling_intro(put, bench.context);
  put_figures(put, figures, FigureKind::scaling, "");
  std::vector<std::string> scenes, engines;
  std::vector<long> counts;
  for (const BenchRow& r : bench.rows) {
    add_once(scenes, r.scene);
    add_once(counts, r.n);
    add_once(engines, run_label(r.engine, r.profile));
  }
  std::sort(counts.begin(), counts.end());
  for (const auto& scene : scenes) {
    put_scaling_table(put, bench, scene, counts, engines);
    put_our_rates(put, in, bench, scene);
    put_scaling_notes(put, in, bench, scene);
    put("\n");
  }
  put_pipe_cost(put, bench);
}

// The harness's target: metrics and sampling at most this share of the engine's own step time.
constexpr double kHarnessTarget = 0.10;

void put_harness(MarkdownBuffer& put, const BenchResults& bench) {
  put("## Harness overhead\n\n`bench/ballbench_harness_benchmark` (Google Benchmark): `run_engine` on the scaled "
      "`gas`, 100 steps without a reference, engine step time and harness time (reading each state back, the "
      "tunnelling and finiteness check every step, the sampled metrics and checksums every k-th step) from the same "
      "run. The target is a harness at most {:.2f} of the engine's time. Source: `results/harness.json`, Google "
      "Benchmark's own JSON.\n\n",
      kHarnessTarget);
  put("| engine | scene | balls | sampled metrics every | engine ns/ball-step | harness ns/ball-step | harness / engine "
      "| target |\n|---|---|---:|---:|---:|---:|---:|---|\n");
  for (const HarnessRow& r : bench.harness) {
    if (!r.error.empty()) {
      put("| {} | {} | {} | {} | failed: {} | | | |\n", r.engine, r.scene, r.n, r.sample_every, r.error);
      continue;
    }
    put("| {} | {} | {} | {} | {:.1f} | {:.1f} | {:.2f} | {} |\n", r.engine, r.scene, r.n, r.sample_every,
        r.engine_ns_per_ball_step, r.harness_ns_per_ball_step, r.overhead,
        r.overhead <= kHarnessTarget ? "met" : fmt::format("**missed**, {:.1f}x over", r.overhead / kHarnessTarget));
  }
  put("\n");
  // The least any per-step check from states costs, measured beside the engine in one run.
  for (const FloorRow& f : bench.floor) {
    if (!f.error.empty()) {
      put("Floor, `floor/{}/{}/{}`: failed: {}\n\n", f.engine, f.scene, f.n, f.error);
      continue;
    }
    put("Floor, `floor/{0}/{1}/{2}` (same binary, {2} balls): beside `{0}`'s step ({3:.1f} ns per ball-step, keeping "
        "{4:.2f} of {5} cores busy on average), copying the state out once costs {6:.2f} ns per ball-step and one "
        "streaming pass comparing two consecutive states (finiteness, longest step) {7:.2f} ns, both on {5} threads: "
        "together **{8:.2f}** of the engine's step, before any pair search. No harness that reads each state and "
        "compares it with the last can cost less.\n\n",
        f.engine, f.scene, f.n, f.engine_ns_per_ball_step, f.engine_cores, f.threads, f.copy_ns_per_ball_step,
        f.pass_ns_per_ball_step, f.floor);
  }
}

}  // namespace

std::string scaling_section(const ReportInputs& in, const std::vector<Figure>& figures) {
  MarkdownBuffer put;
  if (in.bench && !in.bench->rows.empty()) put_scaling(put, in, *in.bench, figures);
  if (in.harness && !in.harness->harness.empty()) put_harness(put, *in.harness);
  return put.str();
}

}  // namespace ballbench

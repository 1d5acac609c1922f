#pragma once
// Equal accuracy (`ballbench match`): for each engine and profile, the cheapest configuration that
// meets one accuracy spec (accuracy_spec.h) on a scene. The step size is searched geometrically
// (dt / 2^k, the scene's duration kept): first the profile as it is, coarse to fine until it meets
// the spec; then each of the engine's own accuracy knobs (EngineInfo::sweep_knobs, one at a time on
// top of the profile) from two halvings coarser than that down to it.
//
// What a search tries depends on what its tries measured (met or not, how far they missed), and
// on timings only where a wrong call on them changes no finding: its budget
// counts work (ball steps), a try stops where a term that only grows is past its bound
// (RunOptions::stop_on_miss), and where two completed tries show how the miss falls with the step,
// the search jumps to the step they predict and confirms the one coarser. Searches run side by side
// (`jobs`); every configuration that met the spec within kClearlyCostlier of the cheapest is then
// timed alone, their repeats interleaved, over a window of its own run started from the state it
// saved there, and the first in search order within the timing's noise of the cheapest is the one
// found; a knob's run stops once it costs as much as the cheapest that met (it could be found only
// below kKnobCostMargin of it), and any try once it costs clearly more than `within` times the
// cheapest that any engine of its role met so far (MatchOptions::within). Under a ceiling (a
// multiple of our solver's cost) a try stops once it costs kClearlyCostlier times more, and a
// configuration met past the ceiling is reported over it, as one stopped there is: the question a
// comparison asks is which engine is cheapest, and an engine at 100x the cheapest need not be
// searched to its end. A try past a limit is known long before its time reaches it: the search's
// first try (the profile as it is at the scene's own step) runs to its end, whatever it misses, and
// every try records its engine time along the scene (its pace); every later try stops once its time
// so far, grown as the nearest try's pace grows from the same point (its configuration one step
// coarser, else the profile as it is), projects past kPaceMargin times its limit (cost_pace.h).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_spec.h"
#include "match_result.h"
#include "engine.h"
#include "run_engines.h"
#include "run_status.h"
#include "scene.h"
#include "shard.h"
#include "try_store.h"

namespace ballbench::cli {

// A try is not run where its coarser try's cost, doubled per halving, projects a whole run past
// this multiple of where its run would stop (its cost limit): the projection errs low on a pile, whose
// steps grow costlier as it settles, and this margin keeps it from skipping what would pass.
inline constexpr double kCeilingProjectionMargin = 1.5;

// The pace's own run (the profile as it is at the scene's own step) has no pace to project with:
// under the ceiling it stops where its time so far, in proportion to its steps, projects past this
// multiple of its limit. That projection errs low on a forming pile and high where bodies fall
// asleep; an engine whose run at the scene's own step is already several times its limit (ODE's
// tuned profile on the pile: 5x) stops in its first seconds, not at the limit.
inline constexpr double kPaceRunLinearMargin = kClearlyCostlier;

// A found configuration's window is timed --repeats times, and more until the repeats' warm passes
// hold this much of its engine's time (s), at most kTimingRepeatsFactor times as many: a window of
// milliseconds is at the mercy of a cache miss or a frequency step, and the ceiling every other
// search stops at is a multiple of our cost.
inline constexpr double kTimedSeconds = 0.25;
inline constexpr int kTimingRepeatsFactor = 8;
// A timing repeat's passes at most (RunOptions::passes): box2d3's seed-box window of 500 steps runs
// near its compiled speed from its third pass (core/runner.h, kWarmSeconds).
inline constexpr int kTimingPasses = 8;

// The window a found configuration is timed over: this fraction of its run, from its middle, and at
// least kMinWindowSteps of its steps (up to the run's second half): a window of a cheap engine at a
// coarse step lasts milliseconds, too short to time.
inline constexpr double kWindowFraction = 0.1;
inline constexpr long kMinWindowSteps = 500;

// Whether a configuration whose try's whole run took `run_s` of its engine's time is timed over its
// whole run, from the scene's start, rather than over its window: at most kTimedWindowSeconds. A
// window's share of a run of milliseconds, read once in its try (the first steps' allocations and
// cold caches among them), moved its cost by half between two searches (rolling-balls: home's 53
// and 82 ns), and the ceiling every other search stops at with it.
inline bool timed_whole(double run_s) { return run_s <= kTimedWindowSeconds; }

// A try's window as a timing sees it: the window's steps and its pace (Result::window_pace) as
// shares of the run's engine time, each on the window's clock (Result::window_clock_s).
struct WindowShares {
  long steps = 0;
  std::vector<double> pace;  // at each window_prefix_steps(steps, i)
  double share = 0;          // the whole window's
};
// None where the run did not cover its window.
std::optional<WindowShares> window_shares(const Result& res, long steps);

// The steps of a window a timing runs and their share of the run: the first prefix that held
// kTimedWindowSeconds of the engine's time in its try of `run_s` seconds, else the whole window. A
// window of seconds is timed over a fifth of a second as well as over all of it, at a tenth of
// the cost (on a pile at dt/64: within 5% of the whole window's cost, run after run).
std::pair<long, double> timed_prefix(const WindowShares& w, double run_s);

struct MatchOptions {
  std::string profile = "all";  // as for `run --profile`
  AccuracySpec spec;
  std::vector<std::string> spec_texts;  // the --spec terms over the scene's own, for the reproducing commands
  int max_halvings = 6;         // dt / 2^k for k = 0 .. this
  // Work for one engine and profile's search, in runs of the whole scene at its own step (n x steps
  // ball steps each): a try at dt / 2^k costs 2^k of them, a try that stopped where it missed its
  // share, one a cost limit stopped nothing (run_try).
  double budget_runs = 400;
  // This many times the cost of the cheapest configuration found for our solver's default profile,
  // searched first (0: no ceiling): every try stops once its CPU time passes kClearlyCostlier times
  // it, and an engine whose configuration met past it is reported as over the ceiling, not ranked.
  double ceiling = 0;
  // `match`'s ceiling where our solver is among the engines and none is asked for (the full
  // suite's; its tries stop at 90x): without one, a try at an engine's finest step on a pile of thousands of balls runs
  // for minutes (bullet tuned at dt/64 on a settled pile of 3000: over 8 min), and a search of
  // every engine for hours.
  static constexpr double kDefaultCeiling = 60;
  // This many times the cheapest configuration that met so far for an engine of the same role (ours,
  // external; CPU time while searching), shared by the searches side by side (0: none): every try
  // stops once its CPU time passes kClearlyCostlier times it, and a configuration met past this many
  // times its role's cheapest, timed alone, is reported outpaced, not ranked (mark_outpaced). The
  // question a comparison asks is which engine is cheapest: an engine at several times the cheapest
  // external one's cost need not be searched to its finest step to say that it is not. At 2, the
  // tries of the engine that is cheapest alone stop only where its ratio of CPU time while searching
  // to its cost alone reads kClearlyCostlier x 2 = 3 times another's (it ranged 0.8 - 1.7 over the
  // engines on a pile, the 10^4 gas and a settled 10^4 pile).
  double within = kDefaultWithin;
  static constexpr double kDefaultWithin = 2;
  int repeats = 3;              // timing runs alone of each found configuration's window
  int jobs = 1;                 // searches at once (tries in child processes; needs isolation)
  const TryStore* store = nullptr;  // tries and timings measured before (null: none)
  std::string work_dir;         // run_match's own: where the windows' scene files go
  std::string scene_digest;     // run_match's own: the scene's content, for the store's keys
  bool knobs = true;            // also each engine's sweep knobs
  Isolation isolation{true, 600};
  const EngineEntry* reference = nullptr;            // for spec terms against the reference
  const EngineEntry* converged_reference = nullptr;  // where the reference refuses the scene
  bool quiet = false;
  Shard shard;                  // shards deal out the (engine, profile) searches
};

MatchResult run_match(const Scene& scene, const std::vector<const EngineEntry*>& engines, const MatchOptions& options,
                      const nlohmann::json& context);

// The table: one row per engine and profile, then our solver's ratio to the cheapest external
// engine that met the spec (against `target`, a ratio, where given), then each row's reproducing
// command.
void print_match(const MatchResult& m, std::optional<double> target = std::nullopt);

}  // namespace ballbench::cli

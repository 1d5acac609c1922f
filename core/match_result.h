#pragma once
// The outcome of an equal-accuracy search (match.h runs it): every configuration tried and each
// engine and profile's result, with their JSON and CSV, which the report reads for its
// equal-accuracy tables and work-precision fronts.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_spec.h"
#include "run_status.h"

namespace ballbench {

// One configuration tried: a profile, a knob on top of it (or none) and a step size.
struct MatchTry {
  std::string engine, profile;
  std::string knob;              // "" for the profile as it is
  nlohmann::json value;          // the knob's value
  int halvings = 0;              // dt = scene dt / 2^halvings
  double dt = 0;
  RunStatus status = RunStatus::ok;  // the run's
  std::string error;
  bool met = false;
  std::string why_not;           // the failing terms, or the run's status
  nlohmann::json figures = nlohmann::json::object();  // every spec term's figure
  // Cost per ball per scene step (ns): the engine's own step time (self-timed by an engine in
  // another process), and for such an engine the harness's time with the pipe beside it.
  double cost_ns = 0;
  std::optional<double> cost_pipe_ns;
  double wall_s = 0;             // the run's wall time, harness included (s)
  // Its share of the search's budget, in runs of the scene at its own step: 2^halvings times the
  // fraction of its steps it made (all of them for one that crashed or timed out; none for one a
  // cost limit stopped, where the clock, not its states, decided).
  double work = 0;
  double done = 1;               // the fraction of the scene's duration it ran
  bool stored = false;           // read from the results store (core/try_store.h), not run again
  nlohmann::json settings;       // the engine's effective settings
};

// How a found configuration's cost is measured (core/cli/match.cpp, time_alone), as the match's
// output, its report section and the report's terms say it.
std::string timing_method_text();

// A try's CPU time while searching moves 10-25% with what else runs on the cores (this 2-core VM,
// idle against beside two CPU-bound jobs). A cost this many times a limit is past it under any such
// load: a try stops at this multiple of the match's ceiling (one under the ceiling never does, and
// one between is reported over it whether it stopped or met), and a configuration that met at this
// multiple of the cheapest one is not timed alone.
inline constexpr double kClearlyCostlier = 1.5;

// Of the configurations timed alone, a later one in search order (the profile as it is, then each
// knob in the engine's order) is found instead of an earlier one only when it costs less than this
// fraction of it: configurations of one cost (twice the substeps at twice the step) must not trade
// places with the timing's noise.
inline constexpr double kKnobCostMargin = 0.85;

// Why a search ended without a ranked result: it tried its finest step, it spent its budget, its
// tries (or the configuration it met, timed alone) passed the match's ceiling
// (MatchResult::ceiling_ns) or `within` times the cheapest configuration an engine of its role met
// (outpace_ns: outpaced), or the user interrupted it.
enum class SearchStop { none, finest_step, budget, ceiling, outpaced, interrupt };

// Its word in results files ("finest step", "budget", ...); search_stop_from_text reads it back
// and throws InputError for any other.
const char* search_stop_text(SearchStop s);
SearchStop search_stop_from_text(std::string_view text);

// A configuration of the same engine and profile that met the spec and was timed alone beside the
// one found (index into MatchResult::tries, and its cost as MatchOutcome::cost_ns).
struct MatchAlternative {
  int index = -1;
  double cost_ns = 0;
};

// Each search's outcome: the cheapest configuration that met the spec, or the best one tried.
struct MatchOutcome {
  std::string engine, profile;
  std::string role;      // the engine's (role_name): ours is compared with the external engines
  bool reached = false;
  int found = -1;        // index into MatchResult::tries of the cheapest that met
  int best = -1;         // the try nearest the spec that did not meet it (its worst term's ratio to its bound)
  int tries = 0;
  double finest_dt = 0;  // the finest step tried (s)
  // The found configuration's cost in each timing run alone (ns): its window, from the state it
  // saved there, scaled by the window's share of its whole run; its own run's where none ran.
  std::vector<double> cost_repeats;
  double cost_ns = 0;    // their median
  double work = 0;       // the search's work, in runs of the scene at its own step
  int stored = 0;        // of its tries, those read from the results store
  bool timing_stored = false;  // its cost read from the store (measured alone by an earlier search)
  std::optional<double> cost_pipe_ns;
  SearchStop stop = SearchStop::none;  // why the search ended without a result
  std::string stopped;   // the same, with its figures ("the budget (600 runs at dt, ...)"), or ""
  std::string command;   // the `ballbench run` that reproduces the found (or best) point
  // The other configurations that met the spec and were timed beside the found one, their repeats
  // interleaved with its: the found one is the first in search order whose cost is within the
  // timing's noise of the cheapest of them (match.h), and these are what it was chosen over.
  std::vector<MatchAlternative> also_met;
  // It met the spec, but stopped (the budget, an interrupt) before trying every configuration: a
  // cheaper one may exist, so its cost is an upper bound and it is never ranked.
  bool cut_short() const { return reached && (stop == SearchStop::budget || stop == SearchStop::interrupt); }
  // It met the spec, but its cost timed alone is past the match's ceiling: reported beside the
  // engines whose tries stopped there, not ranked.
  bool over_ceiling() const { return reached && stop == SearchStop::ceiling; }
  // It met the spec, but its cost timed alone is past `within` times the cheapest of its role's
  // (outpace_ns): it cannot be the cheapest, and is reported beside those whose tries stopped there.
  bool outpaced() const { return reached && stop == SearchStop::outpaced; }
  // Met, its search complete and its cost under any ceiling: ranked against the others.
  bool ranked() const { return reached && stop == SearchStop::none; }
  // Its try indices moved by `offset`: its tries placed after `offset` others in one list.
  void shift_tries(int offset);
};

struct MatchResult {
  std::string scene, scene_source, scene_class;
  std::string use_case;  // the scene's (Scene::use_case), for the report's first screen
  std::string scene_digest;  // the scene's content (scene_digest.h); "" in files written before it was recorded
  // Every search of the plan, "engine/profile" in plan order, whichever shard ran it: a merge
  // checks that each is there once.
  std::vector<std::string> searches;
  int n = 0;
  double dt = 0;  // the scene's
  AccuracySpec spec;
  double budget_runs = 0;  // each search's budget, in runs of the scene at dt
  // A try stops once its CPU time passes `ceiling` times the cheapest configuration found for our
  // solver's default profile (0: no ceiling); ceiling_ns is that cost (ns per ball per scene step).
  double ceiling = 0;
  double ceiling_ns = 0;
  // A try stops once its CPU time passes kClearlyCostlier times `within` times the cheapest
  // configuration that met so far for an engine of its role (0: none); outpace_ns is the bound it
  // is reported against.
  double within = 0;
  long run_ball_steps = 0;  // ball steps in one such run: n x the scene's steps
  nlohmann::json context;
  std::string interrupted;
  int shard_index = 1, shard_count = 1;
  std::vector<MatchTry> tries;
  std::vector<MatchOutcome> outcomes;
};

nlohmann::json to_json(const MatchTry& t);
MatchTry match_try_from_json(const nlohmann::json& j);
nlohmann::json to_json(const MatchResult& m);
MatchResult match_from_json(const nlohmann::json& j);
// JSON (the whole result) and CSV (every try), each written atomically.
void write_match_files(const MatchResult& m, const std::string& json_path, const std::string& csv_path);
MatchResult read_match_file(const std::string& path);
// Shards of one match (same scene content, spec, plan, build and shard count, each once, every
// planned search in one of them): one result.
MatchResult merge_match_shards(const std::vector<MatchResult>& shards, const std::vector<std::string>& names);

// How far a figure is from its term's bound: the figure over the bound (the bound over the figure
// for a term that must be at least; for a bound of 0, 0 when met and 1 + the figure when not), so
// at most 1 meets it.
double term_miss(const SpecTermDef& d, double bound, double figure);

// How far a try is from the spec: its worst term's term_miss, so at most 1 meets it; infinite for
// a run that did not end ok or a term it did not measure. A try stopped where it missed
// (RunStatus::missed) is as far as its worst term that only grows over the share of the run it
// made: one that missed sooner is farther.
double miss(const MatchTry& t, const AccuracySpec& spec);

// The try's error along its spec's principal term (principal_term), or its miss where the spec has
// none; none for a run that did not end ok or a figure not measured. Work-precision fronts plot it.
std::optional<double> front_error(const MatchTry& t, const AccuracySpec& spec);

// The cheapest outcome of engines of `role` ("ours", "external") that met the spec, or none.
const MatchOutcome* cheapest_reached(const MatchResult& m, const std::string& role);

// The outcomes of the other engines of `pick`'s role that met the spec at a cost the timing cannot
// tell from `pick`'s: their timing runs' ranges overlap. A pick with such a tie is a pick among
// equal engines (another profile of the pick's own engine is no other choice of engine).
std::vector<const MatchOutcome*> tied_with(const MatchResult& m, const MatchOutcome& pick);

// Of the outcomes of engines of `role` that are not ranked (did not meet the spec, or met it past the
// ceiling), the one whose nearest try came closest (the smallest miss; a configuration met past the
// ceiling, its own), or none: the engine to name where none is ranked.
const MatchOutcome* nearest_unreached(const MatchResult& m, const std::string& role);

// `within` times the cheapest cost timed alone of the outcomes of `role` that met the spec (ranked
// or not: each met at its cost), or none (no such bound, or none met).
std::optional<double> outpace_ns(const MatchResult& m, const std::string& role);

// "2x the cheapest external engine's cost (10439 ns)": what an outpaced search is past, the
// cheapest's cost timed alone where it is known.
std::string outpace_text(double within, const std::string& role, std::optional<double> cheapest_ns);

// Each outcome that met the spec, under the ceiling and past its role's outpace_ns, marked
// outpaced; each search stopped there given the bound's final figure. Run on a whole match (and on
// merged shards): which engines are outpaced depends on the costs found, not on the order in
// which the searches ran.
void mark_outpaced(MatchResult& m);

// Where no external engine met the spec, at least one stopped at the match's ceiling and none ran
// out of budget: the ratio ours is cheaper by at least (the ceiling's cost over ours); none
// otherwise (an external engine met it, or one might have with more work).
std::optional<double> ratio_at_least(const MatchResult& m, const MatchOutcome& ours);

// "dt", "dt/8": the step of a try that halved the scene's step `halvings` times.
std::string step_text(int halvings);

// A spec term's figure as the tables print it: whole numbers whole, others in three figures, "n/a"
// where it was not measured.
std::string figure_text(const nlohmann::json& figure);

// "dt/8, iterations=20": a try's step size and the knob set on top of its profile.
std::string configuration_text(const MatchTry& t);
// A cost in ns as the tables print it: whole numbers from 100 up, three figures below.
std::string cost_text(double ns);
// The found configuration's cost with the spread of its timing runs, "32720 ±2%" (half their range
// over the median); the cost alone where it was timed once.
std::string cost_spread_text(const MatchOutcome& oc);

}  // namespace ballbench

// Searches limited by work, not by the clock: tries that stop where they can no longer meet the
// spec, the same tries whatever the machine is doing and however many run at once, and settled
// scenes written as data (`ballbench settle`).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>

#include <fmt/format.h>

#include "small_pile.h"
#include "input_error.h"
#include "match.h"
#include "registry.h"
#include "runner.h"
#include "scene_loader.h"
#include "scene_writer.h"
#include "spec_verdict.h"
#include "try_store.h"
#include "cli_runner.h"

namespace ballbench {
namespace {

// The thesis's port sinks balls into each other: asked to stop where it misses, its run ends at the
// first sample past the overlap bound, with the figure and the time, and no later.
TEST(StopOnMiss, EndsTheRunWhereAGrowingTermPassesItsBound) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  const AccuracySpec spec = scene_spec(scene);
  RunOptions o;
  const Result whole = run_engine(scene, find_engine("home-seed"), o);
  ASSERT_GT(*spec_figure(SpecTerm::overlap, whole), *spec[SpecTerm::overlap]);
  o.stop_on_miss = &spec;
  const Result r = run_engine(scene, find_engine("home-seed"), o);
  EXPECT_EQ(r.status, RunStatus::missed);
  EXPECT_LT(r.steps_done, r.steps);
  EXPECT_NE(r.error.find("overlap"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find(fmt::format("t = {:g} s", r.steps_done * scene.dt)), std::string::npos) << r.error;
  // Its figure is past the bound at the step it stopped, and was not one step before.
  EXPECT_GT(*spec_figure(SpecTerm::overlap, r), *spec[SpecTerm::overlap]);
  RunOptions before;
  before.steps = r.steps_done - 1;
  EXPECT_LE(*spec_figure(SpecTerm::overlap, run_engine(scene, find_engine("home-seed"), before)),
            *spec[SpecTerm::overlap]);
  // It is judged missed, by its status alone.
  const SpecVerdict v = judge(spec, r);
  EXPECT_FALSE(v.met);
  EXPECT_EQ(v.why_not.rfind("missed: overlap", 0), 0u) << v.why_not;
  // A run that meets the spec is not stopped.
  const Result home = run_engine(scene, find_engine("home"), o);
  EXPECT_EQ(home.status, RunStatus::ok);
  EXPECT_EQ(home.steps_done, home.steps);
}

cli::MatchOptions small_search(const Scene& scene) {
  cli::MatchOptions o;
  o.spec = scene_spec(scene);
  o.max_halvings = 3;
  o.repeats = 1;
  o.quiet = true;
  return o;
}

// What a search tried, leaving out what the clock measured (where a run over cost stopped).
std::vector<std::string> tried(const MatchResult& m) {
  std::vector<std::string> out;
  for (const MatchTry& t : m.tries)
    out.push_back(fmt::format("{}/{} {}={} k={} {} met={} done={}", t.engine, t.profile, t.knob, t.value.dump(),
                              t.halvings, run_status_text(t.status), t.met,
                              t.status == RunStatus::over_cost ? "-" : fmt::format("{:.6f}", t.done)));
  for (const MatchOutcome& oc : m.outcomes)
    out.push_back(fmt::format("{}/{} found={} best={} work={:.6f} stopped={}", oc.engine, oc.profile, oc.found, oc.best,
                              oc.work, oc.stopped));
  return out;
}

// Two searches side by side try exactly what one at a time tries, and find the same. (Knobs left
// out: whether one is cheaper is a timing, and these runs take milliseconds, too short to time.)
TEST(MatchWork, SideBySideSearchesTryWhatOneAtATimeTries) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  cli::MatchOptions o = small_search(scene);
  o.knobs = false;
  // The race (MatchOptions::within) is left out: which tries an outpaced engine runs before it
  // stops depends on when the cheaper one met; what is found does not (below).
  o.within = 0;
  const std::vector<const EngineEntry*> engines{&find_engine("home"), &find_engine("home-seed"), &find_engine("box2d")};
  o.jobs = 1;
  const MatchResult one = cli::run_match(scene, engines, o, {});
  o.jobs = 2;
  const MatchResult two = cli::run_match(scene, engines, o, {});
  EXPECT_EQ(tried(one), tried(two));
  // home-seed misses the overlap at every step: each try but the first (run to its end for the
  // engine's pace) stops early, and its work is its share.
  for (const MatchTry& t : one.tries)
    if (t.engine == "home-seed" && t.halvings > 0) {
      EXPECT_EQ(t.status, RunStatus::missed);
      EXPECT_LT(t.done, 1.0);
      EXPECT_DOUBLE_EQ(t.work, double(1 << t.halvings) * t.done);
    }
  // A found configuration is timed alone over its window: the repeat asked, more for a short
  // window, a positive cost, its fastest repeat.
  for (const MatchOutcome& oc : one.outcomes)
    if (oc.reached) {
      EXPECT_GE(oc.cost_repeats.size(), 1u) << oc.engine;
      EXPECT_LE(oc.cost_repeats.size(), size_t(cli::kTimingRepeatsFactor * o.repeats)) << oc.engine;
      EXPECT_GT(oc.cost_ns, 0);
      EXPECT_EQ(oc.cost_ns, *std::min_element(oc.cost_repeats.begin(), oc.cost_repeats.end())) << oc.engine;
    }
}

// A timing runs the first part of a window that held kTimedWindowSeconds of the engine's time in
// its try, scaled by that part's share of the run; a window that held less, whole.
TEST(MatchWork, ALongWindowIsTimedOverItsFirstPartThatHeldAFifthOfASecondAndAShortRunWhole) {
  cli::WindowShares w;
  w.steps = 1600, w.share = 0.16;
  for (int i = 0; i < kWindowPoints; ++i) w.pace.push_back(0.01 * (i + 1));
  // A run of 10 s: the window's points hold 0.1, 0.2, ... s; the second is the first of 0.2 s.
  ASSERT_DOUBLE_EQ(kTimedWindowSeconds, 0.2);
  const auto [steps, share] = cli::timed_prefix(w, 10.0);
  EXPECT_EQ(steps, window_prefix_steps(1600, 1));
  EXPECT_EQ(steps, 200);
  EXPECT_DOUBLE_EQ(share, 0.02);
  // A run of 1 s: the whole window holds 0.16 s.
  EXPECT_EQ(cli::timed_prefix(w, 1.0), std::make_pair(1600L, 0.16));
  // A run of at most 0.2 s is timed whole, not over a window of it.
  EXPECT_FALSE(cli::timed_whole(1.0));
  EXPECT_TRUE(cli::timed_whole(0.2));
  EXPECT_TRUE(cli::timed_whole(0.001));
}

// The budget counts work: a search that cannot afford its next try stops there, naming it, and a
// larger budget goes on from the same tries.
TEST(MatchWork, TheBudgetIsWorkAndStopsTheSameTries) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  cli::MatchOptions o = small_search(scene);
  o.isolation.enabled = false;
  o.knobs = false;
  o.profile = "stock";
  o.budget_runs = 1.5;  // dt and a try at dt/2 stopped early at most
  const MatchResult small = cli::run_match(scene, {&find_engine("box2d")}, o, {});
  ASSERT_EQ(small.outcomes.size(), 1u);
  const MatchOutcome& oc = small.outcomes[0];
  EXPECT_LE(oc.work, 1.5);
  // box2d misses the overlap at dt (a run of at most 1), so dt/2 (2 runs) is past the budget.
  ASSERT_FALSE(oc.reached);
  EXPECT_NE(oc.stopped.find("the budget (1.5 runs at dt"), std::string::npos) << oc.stopped;
  o.budget_runs = 100;
  const MatchResult large = cli::run_match(scene, {&find_engine("box2d")}, o, {});
  for (size_t i = 0; i < small.tries.size(); ++i) {
    EXPECT_EQ(small.tries[i].halvings, large.tries.at(i).halvings);
    EXPECT_EQ(small.tries[i].met, large.tries[i].met);
  }
  // The first try, the profile as it is at dt, runs to its end though it misses: its engine time
  // along the scene is the pace the later tries are projected with. Those stop where they miss.
  ASSERT_GE(large.tries.size(), 2u);
  EXPECT_EQ(large.tries[0].halvings, 0);
  EXPECT_FALSE(large.tries[0].met);
  EXPECT_EQ(large.tries[0].status, RunStatus::ok) << large.tries[0].why_not;
  EXPECT_DOUBLE_EQ(large.tries[0].work, 1.0);
  EXPECT_TRUE(std::any_of(large.tries.begin() + 1, large.tries.end(),
                          [](const MatchTry& t) { return t.status == RunStatus::missed && t.done < 1; }));
}

// Every configuration that met is a candidate; those within kClearlyCostlier of the cheapest while
// searching are timed alone in turn, and the first in search order within kKnobCostMargin of the
// cheapest of them is found, the others named beside it. They read back from the results file, and
// a merge moves their indices with the tries.
TEST(MatchWork, ConfigurationsThatMetAreTimedInTurnAndTheFirstWithinTheNoiseIsFound) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  cli::MatchOptions o = small_search(scene);
  o.isolation.enabled = false;
  o.profile = "soft";
  o.repeats = 3;
  // Two substeps meet the small pile for less than four cost; whether that try runs within
  // the cost of the first one is a timing, which a machine loaded enough (a sanitized build beside
  // other tests) can turn: what follows is what a search does with it, so it is searched again.
  MatchResult m;
  for (int attempt = 0; attempt < 4 && (m.outcomes.empty() || m.outcomes[0].also_met.empty()); ++attempt)
    m = cli::run_match(scene, {&find_engine("home")}, o, {});
  ASSERT_EQ(m.outcomes.size(), 1u);
  const MatchOutcome& oc = m.outcomes[0];
  ASSERT_TRUE(oc.reached);
  ASSERT_FALSE(oc.also_met.empty()) << "the soft step's substeps meet the small pile too";
  double least = oc.cost_ns;
  for (const MatchAlternative& a : oc.also_met) least = std::min(least, a.cost_ns);
  EXPECT_LE(oc.cost_ns * kKnobCostMargin, least);
  for (const MatchAlternative& a : oc.also_met) {
    const MatchTry& t = m.tries.at(a.index);
    EXPECT_TRUE(t.met);
    EXPECT_EQ(t.engine, "home");
    EXPECT_NE(a.index, oc.found);
    // One earlier in search order was passed over: it costs more than the cheapest over the margin.
    if (a.index < oc.found) {
      EXPECT_GT(a.cost_ns * kKnobCostMargin, least);
    }
  }
  const auto json = std::filesystem::temp_directory_path() / "ballbench-also-met.json";
  write_match_files(m, json.string(), json.string() + ".csv");
  const MatchResult back = read_match_file(json.string());
  std::filesystem::remove(json), std::filesystem::remove(json.string() + ".csv");
  ASSERT_EQ(back.outcomes[0].also_met.size(), oc.also_met.size());
  EXPECT_EQ(back.outcomes[0].also_met[0].index, oc.also_met[0].index);
  EXPECT_DOUBLE_EQ(back.outcomes[0].also_met[0].cost_ns, oc.also_met[0].cost_ns);
  MatchOutcome moved = oc;
  moved.shift_tries(10);
  EXPECT_EQ(moved.found, oc.found + 10);
  EXPECT_EQ(moved.also_met[0].index, oc.also_met[0].index + 10);
}

// The ceiling: our solver's default profile searches first, and every other try stops once its CPU
// time passes the ceiling's multiple of its cost. Far above every engine's cost it changes no try;
// below them it stops each search there, says so, and the ratio reads as a lower bound.
TEST(MatchWork, TheCeilingStopsTriesPastAMultipleOfOurCost) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  cli::MatchOptions o = small_search(scene);
  o.isolation.enabled = false;
  o.knobs = false;
  o.profile = "default,stock";
  const std::vector<const EngineEntry*> engines{&find_engine("box2d"), &find_engine("home")};
  const MatchResult none = cli::run_match(scene, engines, o, {});
  o.ceiling = 1e6;
  const MatchResult high = cli::run_match(scene, engines, o, {});
  // Our solver searched first; the tries and findings otherwise the same.
  ASSERT_FALSE(high.tries.empty());
  EXPECT_EQ(high.outcomes.size(), 2u);
  std::vector<std::string> a = tried(none), b = tried(high);
  std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
  const auto ours = std::find_if(high.outcomes.begin(), high.outcomes.end(),
                                 [](const MatchOutcome& oc) { return oc.engine == "home"; });
  ASSERT_NE(ours, high.outcomes.end());
  ASSERT_TRUE(ours->reached);
  EXPECT_DOUBLE_EQ(high.ceiling_ns, 1e6 * ours->cost_ns);  // the cost shown: its found configuration timed alone

  o.ceiling = 1e-9;  // below any cost: each box2d try stops at its first cost check, or misses first
  const MatchResult low = cli::run_match(scene, engines, o, {});
  bool over = false;
  for (const MatchTry& t : low.tries) {
    if (t.engine != "box2d") continue;
    EXPECT_NE(t.status, RunStatus::ok) << t.why_not;
    if (t.status == RunStatus::over_cost) {
      over = true;
      EXPECT_NE(t.why_not.find("ceiling"), std::string::npos) << t.why_not;
      EXPECT_LE(std::lround(t.done * double(scene.steps() << t.halvings)), kCostCheckSteps);
      EXPECT_EQ(t.work, 0) << "where the clock stopped it is no work the budget counts";
    }
  }
  EXPECT_TRUE(over);
  for (const MatchOutcome& oc : low.outcomes)
    if (oc.engine == "box2d") {
      EXPECT_FALSE(oc.reached);
      EXPECT_EQ(oc.stop, SearchStop::ceiling);
      EXPECT_NE(oc.stopped.find("the ceiling (1e-09x"), std::string::npos) << oc.stopped;
    } else {
      ASSERT_TRUE(oc.reached);
      const auto at_least = ratio_at_least(low, oc);
      ASSERT_TRUE(at_least);
      EXPECT_DOUBLE_EQ(*at_least, low.ceiling_ns / oc.cost_ns);
    }
  // The stop and the ceiling read back from the results file, every try written.
  const auto json = std::filesystem::temp_directory_path() / "ballbench-ceiling.json";
  write_match_files(low, json.string(), json.string() + ".csv");
  const MatchResult back = read_match_file(json.string());
  std::filesystem::remove(json), std::filesystem::remove(json.string() + ".csv");
  EXPECT_EQ(back.tries.size(), low.tries.size());
  EXPECT_EQ(back.ceiling_ns, low.ceiling_ns);
  EXPECT_EQ(back.outcomes[0].stop, low.outcomes[0].stop);

  // A ceiling is a multiple of our solver's cost: without it, one line.
  EXPECT_THROW(cli::run_match(scene, {&find_engine("box2d")}, o, {}), InputError);
}

// The race: searched after our default profile met, another of our profiles that costs more than
// `within` times it stops there (its tries over cost, the row outpaced), and what is found for the
// cheapest is what a search without the bound finds.
TEST(MatchWork, AnEngineOutpacedInTheRaceStopsThereAndTheCheapestIsFoundAsWithoutIt) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  cli::MatchOptions o = small_search(scene);
  o.isolation.enabled = false;  // one search at a time, in plan order: the default profile first
  o.knobs = false;
  o.profile = "default,events";
  const std::vector<const EngineEntry*> engines{&find_engine("home")};
  o.within = 0;
  const MatchResult free = cli::run_match(scene, engines, o, {});
  ASSERT_EQ(free.outcomes.size(), 2u);
  ASSERT_TRUE(free.outcomes[0].ranked());
  ASSERT_TRUE(free.outcomes[1].ranked());
  // The event-driven path steps every contact: on a pile, far costlier than the default's.
  ASSERT_GT(free.tries[free.outcomes[1].found].cost_ns, 3 * free.tries[free.outcomes[0].found].cost_ns);
  o.within = 1;
  const MatchResult raced = cli::run_match(scene, engines, o, {});
  EXPECT_EQ(raced.within, 1);
  ASSERT_TRUE(raced.outcomes[0].ranked());
  EXPECT_EQ(configuration_text(raced.tries[raced.outcomes[0].found]),
            configuration_text(free.tries[free.outcomes[0].found]));
  const MatchOutcome& events = raced.outcomes[1];
  EXPECT_EQ(events.stop, SearchStop::outpaced);
  EXPECT_FALSE(events.reached);
  EXPECT_NE(events.stopped.find("1x the cheapest ours engine's cost"), std::string::npos) << events.stopped;
  bool stopped = false;
  for (const MatchTry& t : raced.tries)
    if (t.profile == "events" && t.status == RunStatus::over_cost) {
      stopped = true;
      EXPECT_NE(t.why_not.find("1.5x the cheapest ours configuration met so far (1.5 x --within 1)"), std::string::npos)
          << t.why_not;
      EXPECT_EQ(t.work, 0);
    }
  EXPECT_TRUE(stopped);
}

// The command's ceiling: 100 by default where our solver's default profile is searched, none where
// it is not (nothing to be a multiple of), `none` asked for by name, and 0 refused.
TEST(MatchWork, TheCommandHasACeilingByDefaultWhereOurSolverIsSearched) {
  const auto dir = std::filesystem::temp_directory_path() / "ballbench-default-ceiling";
  std::filesystem::create_directories(dir);
  const std::string scene = (dir / "small.toml").string();
  std::ofstream(scene) << kSmallPile;
  const auto ceiling = [&](const std::string& args) -> std::optional<double> {
    const std::string json = (dir / "m.json").string();
    std::filesystem::remove(json);
    const auto r = testing::run_cli("match --quiet --scene " + scene + " --max-halvings 0 --no-knobs --repeats 0 " +
                                    "--store '' --json " + json + " " + args);
    if (r.status != 0) {
      ADD_FAILURE() << args << ": " << r.err;
      return std::nullopt;
    }
    std::ifstream in(json);
    return nlohmann::json::parse(in).at("ceiling").get<double>();
  };
  EXPECT_EQ(ceiling("--engine home --profile default"), cli::MatchOptions::kDefaultCeiling);
  EXPECT_EQ(ceiling("--engine box2d --profile stock"), 0);
  EXPECT_EQ(ceiling("--engine home --profile soft"), 0);  // our default profile is not searched
  EXPECT_EQ(ceiling("--engine home --profile default --ceiling none"), 0);
  EXPECT_EQ(ceiling("--engine home --profile default --ceiling 7"), 7);
  const auto zero = testing::run_cli("match --quiet --scene " + scene + " --engine home --ceiling 0");
  EXPECT_EQ(zero.status, 2);
  EXPECT_NE(zero.err.find("--ceiling: must be > 0, got '0'"), std::string::npos) << zero.err;
  // The race's multiple: recorded, `none` for none, and below 1 (the cheapest outpaced by itself) refused.
  const auto within = [&](const std::string& args) -> std::optional<double> {
    const std::string json = (dir / "w.json").string();
    std::filesystem::remove(json);
    const auto r = testing::run_cli("match --quiet --scene " + scene + " --engine home --profile default " +
                                    "--max-halvings 0 --no-knobs --repeats 0 --store '' --json " + json + " " + args);
    if (r.status != 0) return std::nullopt;
    std::ifstream in(json);
    return nlohmann::json::parse(in).at("within").get<double>();
  };
  EXPECT_EQ(within(""), cli::MatchOptions::kDefaultWithin);
  EXPECT_EQ(within("--within none"), 0);
  EXPECT_EQ(within("--within 3"), 3);
  const auto half = testing::run_cli("match --quiet --scene " + scene + " --engine home --within 0.5");
  EXPECT_EQ(half.status, 2);
  EXPECT_NE(half.err.find("--within: must be at least 1, got '0.5'"), std::string::npos) << half.err;
}

// The results store: a search run again reads every try and timing it kept and finds the same; a
// fresh one measures everything again; another spec is another entry.
TEST(MatchWork, TheStoreReusesWhatWasMeasuredAndFreshMeasuresAgain) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  const auto dir = std::filesystem::temp_directory_path() / "ballbench-store-test";
  std::filesystem::remove_all(dir);
  cli::MatchOptions o = small_search(scene);
  o.isolation.enabled = false;
  o.profile = "default";
  const std::vector<const EngineEntry*> engines{&find_engine("home")};
  const TryStore store(dir.string(), false);
  o.store = &store;
  const MatchResult first = cli::run_match(scene, engines, o, {});
  const MatchResult again = cli::run_match(scene, engines, o, {});
  EXPECT_EQ(tried(first), tried(again));
  for (const MatchTry& t : first.tries) EXPECT_FALSE(t.stored);
  for (const MatchTry& t : again.tries) EXPECT_TRUE(t.stored) << t.knob << " k=" << t.halvings;
  ASSERT_TRUE(again.outcomes[0].reached);
  EXPECT_TRUE(again.outcomes[0].timing_stored);
  EXPECT_EQ(again.outcomes[0].cost_ns, first.outcomes[0].cost_ns);
  const TryStore fresh(dir.string(), true);
  o.store = &fresh;
  const MatchResult measured = cli::run_match(scene, engines, o, {});
  for (const MatchTry& t : measured.tries) EXPECT_FALSE(t.stored);
  // Measured again, the profile as it is meets the spec with the same figures (a knob that costs
  // about as much may stop over cost in one run and not in another: CPU time's noise).
  ASSERT_FALSE(measured.tries.empty());
  EXPECT_EQ(measured.tries.front().knob, first.tries.front().knob);
  EXPECT_EQ(measured.tries.front().met, first.tries.front().met);
  EXPECT_EQ(measured.tries.front().figures, first.tries.front().figures);
  o.store = &store;
  o.spec[SpecTerm::overlap] = 0.02;
  const MatchResult other = cli::run_match(scene, engines, o, {});
  EXPECT_FALSE(other.tries.front().stored);
  std::filesystem::remove_all(dir);
}

// A settled scene is data: its file reads back with every ball where the run left it, the source's
// spec stated (allowing overlap would drop the overlap term), and the window asked for.
TEST(Settle, WritesTheFinalStateAsASceneThatReadsBack) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  RunOptions o;
  State last;
  o.last_state = &last;
  ASSERT_EQ(run_engine(scene, find_engine("home"), o).status, RunStatus::ok);
  const SceneSnapshot snap = scene_at_state(scene, last, "small-settled", 0.5);
  const Scene back = parse_scene(snap.text, "settled.toml");
  EXPECT_EQ(back.name, "small-settled");
  EXPECT_EQ(back.n(), scene.n());
  EXPECT_EQ(back.steps(), 50);
  EXPECT_EQ(back.dt, scene.dt);
  EXPECT_EQ(back.gravity, scene.gravity);
  EXPECT_EQ(back.restitution, scene.restitution);
  EXPECT_EQ(scene_spec(back).to_json(), scene_spec(scene).to_json());
  EXPECT_EQ(snap.pushed_in == 0, (back.initial.pos - last.pos).cwiseAbs().maxCoeff() == 0);
  // A ball put back inside the box moves by at most its sink into the wall: home meets the pile
  // spec, overlap <= 1% of the radius (0.1 m).
  EXPECT_LE((back.initial.pos - last.pos).cwiseAbs().maxCoeff(), 0.01 * 0.1);
  EXPECT_EQ(back.initial.vel, last.vel);  // every double as it was
  EXPECT_EQ(back.radius, scene.radius);
}

TEST(Settle, TheCommandWritesAFileThatRunsAndRefusesToOverwriteItsScene) {
  const auto dir = std::filesystem::temp_directory_path() / "ballbench-settle-test";
  std::filesystem::create_directories(dir);
  const std::string scene = (dir / "small.toml").string(), out = (dir / "settled.toml").string();
  std::ofstream(scene) << kSmallPile;
  std::filesystem::remove(out);
  const auto made = testing::run_cli("settle --quiet --scene " + scene + " --out " + out + " --duration 0.2");
  ASSERT_EQ(made.status, 0) << made.err;
  EXPECT_NE(made.out.find("small-pile-settled: 60 balls"), std::string::npos) << made.out;
  const auto ran = testing::run_cli("run --quiet --no-reference --scene " + out + " --engine home");
  EXPECT_EQ(ran.status, 0) << ran.err;
  const auto clash = testing::run_cli("settle --quiet --scene " + scene + " --out " + scene);
  EXPECT_EQ(clash.status, 2);
  EXPECT_NE(clash.err.find("same file as --scene"), std::string::npos) << clash.err;
}

}  // namespace
}  // namespace ballbench

// The report's summary and equal-accuracy sections, from match results made by hand: the ratio of
// ours to the cheapest external engine that met the spec, what did not meet it with its nearest
// miss, links to the sections, and ratios that stay readable below 1.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>

#include "accuracy_section.h"
#include "front_figures.h"
#include "summary_section.h"

namespace ballbench {
namespace {

MatchTry try_of(const std::string& engine, const std::string& profile, int halvings, bool met, double overlap,
                double cost, RunStatus status = RunStatus::ok) {
  MatchTry t;
  t.engine = engine, t.profile = profile, t.halvings = halvings, t.dt = 0.01 / (1 << halvings);
  t.status = status, t.met = met, t.cost_ns = cost;
  t.figures = {{"overlap", status == RunStatus::ok ? nlohmann::json(overlap) : nlohmann::json()},
               {"tunnelling", status == RunStatus::ok ? nlohmann::json(0) : nlohmann::json()}};
  return t;
}

MatchOutcome outcome(const std::string& engine, const std::string& profile, const std::string& role, int found,
                     int best, int tries, double cost) {
  MatchOutcome o;
  o.engine = engine, o.profile = profile, o.role = role, o.reached = found >= 0, o.found = found, o.best = best;
  o.tries = tries, o.cost_ns = cost, o.finest_dt = 0.01 / 64;
  return o;
}

// A pile: ours meets the spec at dt for 900 ns; chipmunk at dt/64 for 45 000 ns; box2d never
// (0.034 at dt/64); the thesis port diverges at every step.
MatchResult pile() {
  MatchResult m;
  m.scene = "pile", m.scene_class = "pile", m.n = 500, m.dt = 0.01;
  m.spec[SpecTerm::overlap] = 0.01;
  m.spec[SpecTerm::tunnelling] = 0;
  m.tries = {try_of("home", "default", 0, true, 0.007, 900),
             try_of("chipmunk", "stock", 5, false, 0.02, 20000),
             try_of("chipmunk", "stock", 6, true, 0.008, 45000),
             try_of("box2d", "stock", 6, false, 0.034, 80000),
             try_of("home-seed", "default", 6, false, 0, 100, RunStatus::diverged)};
  m.outcomes = {outcome("home", "default", "ours", 0, -1, 1, 900), outcome("chipmunk", "stock", "external", 2, 1, 7, 45000),
                outcome("box2d", "stock", "external", -1, 3, 7, 0), outcome("home-seed", "default", "thesis", -1, 4, 7, 0)};
  return m;
}

TEST(AccuracySection, TheSummaryAnswersWithThePickAndTheRatioInWords) {
  ReportInputs in;
  in.matches = {pile()};
  in.matches[0].use_case = "a pile at rest";
  const std::string md = summary_section(in, {});
  EXPECT_NE(md.find("| [a pile at rest](#equal-accuracy-pile), 500 balls | overlap ≤ 1%, no tunnelling | **chipmunk** "
                    "as shipped, dt/64 | 45000 | **home**, dt | 900 | **50x cheaper** |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("dt: the scene's own step (0.01 s in each)"), std::string::npos) << md;

  // No external engine met it: the row names the nearest miss (chipmunk's 0.02 at dt/32 is nearer
  // 0.01 than box2d's 0.034), why the search stopped, and calls the ratio undecided.
  MatchResult undecided = pile();
  for (MatchOutcome& oc : undecided.outcomes)
    if (oc.role == role_name(EngineRole::external)) oc.reached = false, oc.found = -1;
  for (MatchOutcome& oc : undecided.outcomes)
    if (oc.engine == "chipmunk") oc.stop = SearchStop::budget;
  in.matches = {undecided};
  const std::string md2 = summary_section(in, {});
  EXPECT_NE(md2.find("| none within the budget (nearest: chipmunk/stock) | n/a | **home**, dt | 900 | undecided: no "
                     "external engine met it |"),
            std::string::npos)
      << md2;
}

// Two external engines whose timing runs overlap are a tie: the summary names both, the cheaper
// first with its configuration (the other's is on the scene's page); ranges apart are no tie.
TEST(AccuracySection, ThePickNamesAnEngineItCannotBeToldFrom) {
  MatchResult m = pile();
  m.tries[3] = try_of("box2d", "stock", 6, true, 0.009, 46000);
  m.outcomes[1].cost_repeats = {44000, 45000, 47000};
  m.outcomes[2] = outcome("box2d", "stock", "external", 3, 3, 7, 46000);
  m.outcomes[2].cost_repeats = {46000, 46500, 48000};
  ReportInputs in;
  in.matches = {m};
  const std::string md = summary_section(in, {});
  EXPECT_NE(md.find("| **chipmunk** as shipped, dt/64; [tied](pages/terms.md#cost-step-and-search) with **box2d** as "
                    "shipped | 45000 ±3% |"),
            std::string::npos)
      << md;
  ASSERT_EQ(tied_with(m, m.outcomes[1]).size(), 1u);
  // Two profiles of one engine tied with the pick: the engine named once.
  MatchResult both = m;
  both.tries.push_back(try_of("box2d", "tuned", 6, true, 0.009, 46200));
  both.outcomes.push_back(outcome("box2d", "tuned", "external", int(both.tries.size()) - 1, -1, 7, 46200));
  both.outcomes.back().cost_repeats = {46200, 46500, 47000};
  in.matches = {both};
  const std::string once = summary_section(in, {});
  EXPECT_NE(once.find("with **box2d** as shipped |"), std::string::npos) << once;
  m.outcomes[2].cost_repeats = {47500, 48000, 49000};
  EXPECT_TRUE(tied_with(m, m.outcomes[1]).empty());
  EXPECT_TRUE(tied_with(m, m.outcomes[0]).empty());  // ours: no other of its role met it
  // Another profile of the pick's own engine at the same cost is no other engine to pick.
  m.outcomes[2] = outcome("chipmunk", "tuned", "external", 3, 3, 7, 46000);
  m.outcomes[2].cost_repeats = {44000, 45000, 47000};
  EXPECT_TRUE(tied_with(m, m.outcomes[1]).empty());
}

TEST(AccuracySection, OneBallIsOneBall) {
  MatchResult one = pile();
  one.n = 1;
  const std::string md = accuracy_section(ReportInputs{}, one, {});
  EXPECT_NE(md.find("\n1 ball, class `pile`"), std::string::npos) << md;
  EXPECT_NE(accuracy_section(ReportInputs{}, pile(), {}).find("\n500 balls, class `pile`"), std::string::npos);
}

TEST(AccuracySection, TheSectionRanksWhatMetByCostAndSaysWhatDidNot) {
  const std::string md = accuracy_section(ReportInputs{}, pile(), {});
  EXPECT_NE(md.find("## Equal accuracy: `pile`"), std::string::npos);
  EXPECT_NE(md.find("| home-seed | no: diverged at every step down to dt/64 |"), std::string::npos) << md;
  const auto home = md.find("| home | yes | dt | 900 |"), chip = md.find("| chipmunk/stock | yes | dt/64 | 45000 |"),
             box2d = md.find("| box2d/stock | no: overlap 0.034 at dt/64 | finest: dt/64 | n/a |");
  ASSERT_NE(home, std::string::npos) << md;
  ASSERT_NE(chip, std::string::npos) << md;
  ASSERT_NE(box2d, std::string::npos) << md;
  EXPECT_LT(home, chip);
  EXPECT_LT(chip, box2d);
  EXPECT_NE(md.find("**50x cheaper** than the cheapest external engine that meets the spec (chipmunk/stock"),
            std::string::npos)
      << md;
}

// A configuration met at a cost past the ceiling is over it: shown with its cost, not ranked, and
// named as the nearest where no external engine is ranked; ours then reads "over" the ceiling.
TEST(AccuracySection, AConfigurationMetPastTheCeilingIsOverItNotRanked) {
  MatchResult m = pile();
  m.ceiling = 40, m.ceiling_ns = 36000;  // chipmunk's 45 000 ns is past it
  m.outcomes[1].stop = SearchStop::ceiling;
  m.outcomes[2].stop = SearchStop::ceiling;  // box2d's tries stopped there
  ASSERT_TRUE(m.outcomes[1].over_ceiling());
  EXPECT_FALSE(m.outcomes[1].ranked());
  EXPECT_EQ(cheapest_reached(m, "external"), nullptr);
  EXPECT_EQ(nearest_unreached(m, "external"), &m.outcomes[1]);
  ASSERT_TRUE(ratio_at_least(m, m.outcomes[0]));
  EXPECT_DOUBLE_EQ(*ratio_at_least(m, m.outcomes[0]), 40);
  EXPECT_EQ(verdict_of(m, m.outcomes[1]), MatchVerdict::over_ceiling);
  const std::string md = accuracy_section(ReportInputs{}, m, {});
  const auto chip = md.find("| chipmunk/stock | yes, past the ceiling (36000 ns): not ranked | dt/64 | 45000 |");
  ASSERT_NE(chip, std::string::npos) << md;
  EXPECT_LT(md.find("| home | yes | dt | 900 |"), chip);
  ReportInputs in;
  in.matches = {m};
  const std::string summary = summary_section(in, {});
  EXPECT_NE(summary.find("none within 40x our cost (nearest: chipmunk/stock, met at 45000 ns)"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("over 40x"), std::string::npos) << summary;
}

// An engine past `within` times the cheapest of its role is outpaced: decided from the costs found
// (not from which search ran first), not ranked, its row saying past what; the pick and the ratio
// are the same as without the bound. Merged shards are judged against the cheapest of them all.
TEST(AccuracySection, AnEnginePastAMultipleOfItsRolesCheapestIsOutpacedNotRanked) {
  MatchResult m = pile();
  m.tries.push_back(try_of("box2d3", "stock", 3, true, 0.008, 12000));
  m.outcomes.push_back(outcome("box2d3", "stock", "external", 5, -1, 4, 12000));
  m.outcomes[2].stop = SearchStop::outpaced;  // box2d's tries stopped in the race
  m.within = 2;
  ASSERT_TRUE(outpace_ns(m, "external"));
  EXPECT_DOUBLE_EQ(*outpace_ns(m, "external"), 24000);
  EXPECT_DOUBLE_EQ(*outpace_ns(m, "ours"), 1800);
  EXPECT_FALSE(outpace_ns(m, "reference"));  // none of that role met
  mark_outpaced(m);
  EXPECT_TRUE(m.outcomes[1].outpaced());  // chipmunk's 45 000 ns is past 2 x 12 000
  EXPECT_FALSE(m.outcomes[1].ranked());
  EXPECT_EQ(m.outcomes[1].stopped, "2x the cheapest external engine's cost (12000 ns), met at 45000 ns");
  EXPECT_EQ(m.outcomes[2].stopped, "2x the cheapest external engine's cost (12000 ns)");
  EXPECT_TRUE(m.outcomes[0].ranked());
  EXPECT_TRUE(m.outcomes[4].ranked());
  EXPECT_EQ(cheapest_reached(m, "external"), &m.outcomes[4]);
  EXPECT_EQ(verdict_of(m, m.outcomes[1]), MatchVerdict::outpaced);
  const std::string md = accuracy_section(ReportInputs{}, m, {});
  EXPECT_NE(md.find("| chipmunk/stock | yes, past 2x the cheapest external engine's cost (12000 ns): not ranked | "
                    "dt/64 | 45000 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| box2d/stock | no: overlap 0.034 at dt/64, past 2x the cheapest external engine's cost (12000 "
                    "ns) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("within 2x the cheapest of its kind (ours, external): a try stopped once its CPU time passed 3x"),
            std::string::npos)
      << md;
  // Without the bound, every engine that met is ranked.
  MatchResult none = pile();
  none.within = 0;
  mark_outpaced(none);
  EXPECT_TRUE(none.outcomes[1].ranked());
  // Through the results file, and merged: the other shard's cheaper engine outpaces this one's.
  const auto json = std::filesystem::temp_directory_path() / fmt::format("ballbench-outpaced-{}.json", getpid());
  write_match_files(m, json.string(), json.string() + ".csv");
  const MatchResult back = read_match_file(json.string());
  std::filesystem::remove(json), std::filesystem::remove(json.string() + ".csv");
  EXPECT_EQ(back.within, 2);
  EXPECT_EQ(back.outcomes[1].stop, SearchStop::outpaced);
  MatchResult a = pile(), b = pile();
  a.within = b.within = 2, a.shard_count = b.shard_count = 2, b.shard_index = 2;
  a.searches = b.searches = {"home/default", "chipmunk/stock", "box2d/stock", "home-seed/default", "box2d3/stock"};
  a.outcomes.erase(a.outcomes.begin() + 2, a.outcomes.end());  // home, chipmunk
  b.outcomes.erase(b.outcomes.begin(), b.outcomes.begin() + 2);  // box2d, home-seed, and box2d3:
  b.tries.push_back(try_of("box2d3", "stock", 3, true, 0.008, 12000));
  b.outcomes.push_back(outcome("box2d3", "stock", "external", 5, -1, 4, 12000));
  mark_outpaced(a), mark_outpaced(b);
  EXPECT_TRUE(a.outcomes[1].ranked());  // alone in its shard
  const MatchResult merged = merge_match_shards({a, b}, {"a.json", "b.json"});
  ASSERT_EQ(merged.outcomes.size(), 5u);
  EXPECT_TRUE(merged.outcomes[1].outpaced()) << merged.outcomes[1].stopped;
}

// The x of each point a front's data file holds (its blocks: the profile's line, the tries that met,
// those that did not), in order.
std::vector<double> front_xs(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<double> xs;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    double x = 0;
    if (line != "NaN NaN" && fields >> x) xs.push_back(x);
  }
  return xs;
}

// On an axis of the worst term over its bound, a try that met a count bounded at 0 (no tunnelling)
// lies where its other terms put it: a pile's 0.007 overlap at 0.7, not on the spec's line at 1; a
// spec of that count alone puts what met it at 0.001; a count it missed stays 1 + the count.
TEST(AccuracySection, FrontsPlaceWhatMetACountOfZeroByItsOtherTerms) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ballbench_fronts." + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path here = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  MatchResult box = pile();
  box.scene = "box", box.scene_class = "gas";
  box.spec = {};
  box.spec[SpecTerm::tunnelling] = 0;
  box.tries[1].figures["tunnelling"] = 3;
  // A profile whose only tries that ran ok set a knob: no line, its blocks still in their places.
  MatchResult knobbed = pile();
  knobbed.scene = "knobbed";
  for (MatchTry& t : knobbed.tries)
    if (t.engine == "chipmunk") t.knob = "iterations", t.value = 5;
  ReportInputs in;
  in.matches = {pile(), box, knobbed};
  const std::vector<Figure> figures = front_figures(in);
  std::filesystem::current_path(here);
  EXPECT_EQ(figures.size(), 4u);
  // Every series file has its three blocks (the line, what met, what did not), none empty: gnuplot
  // counts no leading blank lines, so an empty block would shift the others.
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".dat" || name.find("picks") != std::string::npos) continue;
    std::ifstream in_file(e.path());
    const std::string text((std::istreambuf_iterator<char>(in_file)), std::istreambuf_iterator<char>());
    EXPECT_FALSE(text.starts_with("\n")) << name;
    EXPECT_EQ(text.find("\n\n\n\n"), std::string::npos) << name;
  }
  EXPECT_EQ(front_xs(dir / "knobbed-fronts-chipmunk-stock.dat"), (std::vector<double>{0.8, 2})) << "met, then not";
  EXPECT_EQ(front_xs(dir / "pile-fronts-home.dat"), (std::vector<double>{0.7, 0.7})) << "line, then met";
  EXPECT_EQ(front_xs(dir / "pile-fronts-chipmunk-stock.dat"), (std::vector<double>{2, 0.8, 0.8, 2}));
  EXPECT_EQ(front_xs(dir / "box-fronts-home.dat"), (std::vector<double>{0.001, 0.001}));
  EXPECT_EQ(front_xs(dir / "box-fronts-chipmunk-stock.dat"), (std::vector<double>{4, 0.001, 0.001, 4}));
  // The scene's own figure of a spec of counts alone: the same axis.
  EXPECT_EQ(front_xs(dir / "box-front-chipmunk-stock.dat"), (std::vector<double>{4, 0.001, 0.001, 4}));
  std::filesystem::remove_all(dir);
}

TEST(AccuracySection, RatiosReadBelowOne) {
  EXPECT_EQ(ratio_text(48.1), "48x");
  EXPECT_EQ(ratio_text(2.14), "2.1x");
  EXPECT_EQ(ratio_text(0.5), "0.50x");
  EXPECT_EQ(ratio_text(1.0 / 330), "1/330x");
  EXPECT_EQ(ratio_text(0), "n/a");
  EXPECT_EQ(accuracy_anchor("seed-box"), "equal-accuracy-seed-box");
}

}  // namespace
}  // namespace ballbench

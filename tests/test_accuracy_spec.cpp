// The accuracy spec: scene classes and their defaults, the [accuracy] table and --spec texts,
// judging a run against a spec, `home`'s method chosen from the spec, and `ballbench match`.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <fmt/format.h>

#include "small_pile.h"
#include "accuracy_spec.h"
#include "cli_runner.h"
#include "input_error.h"
#include "match.h"
#include "metrics/meter_set.h"
#include "registry.h"
#include "result.h"
#include "runner.h"
#include "scene_loader.h"
#include "solver/home_method.h"
#include "spec_option.h"
#include "spec_verdict.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;

// A small pile: 60 balls dropped into a narrow box, settling for two seconds.
TEST(SceneClass, FollowsGravityBoxAndRolling) {
  EXPECT_EQ(scene_class(load_scene("pile")), SceneClass::pile);
  EXPECT_EQ(scene_class(load_scene("seed-bowl")), SceneClass::pile);
  EXPECT_EQ(scene_class(load_scene("gas")), SceneClass::gas);
  EXPECT_EQ(scene_class(load_scene("seed-box")), SceneClass::gas);
  EXPECT_EQ(scene_class(load_scene("slide-to-roll")), SceneClass::rolling);
  EXPECT_EQ(scene_class(load_scene("projectile")), SceneClass::free);
}

TEST(ClassSpec, PileBoundsOverlapTunnellingAndRest) {
  const Scene pile = load_scene("pile");
  const AccuracySpec s = scene_spec(pile);
  EXPECT_EQ(s[SpecTerm::overlap], 0.01);
  EXPECT_EQ(s[SpecTerm::tunnelling], 0);
  // 1% of sqrt(|g| r) with g = 9.81 and r = 0.25.
  ASSERT_TRUE(s[SpecTerm::rest_speed]);
  EXPECT_NEAR(*s[SpecTerm::rest_speed], 0.01 * std::sqrt(9.81 * 0.25), 1e-12);
  EXPECT_FALSE(s[SpecTerm::energy_drift]);
  EXPECT_FALSE(s.needs_reference());
}

TEST(ClassSpec, ElasticGasToRoundOffAndAnOverlappingPlacementUnbounded) {
  const AccuracySpec gas = scene_spec(load_scene("gas"));
  EXPECT_EQ(gas[SpecTerm::energy_drift], 1e-9);
  EXPECT_EQ(gas[SpecTerm::overlap], 0.01);
  // seed-box starts overlapping (allow_overlap) and loses energy (restitution 0.99).
  const AccuracySpec box = scene_spec(load_scene("seed-box"));
  EXPECT_FALSE(box[SpecTerm::overlap]);
  EXPECT_FALSE(box[SpecTerm::energy_drift]);
  EXPECT_EQ(box[SpecTerm::tunnelling], 0);
  EXPECT_EQ(scene_spec(load_scene("slide-to-roll"))[SpecTerm::rolling], 0.005);
}

TEST(SceneAccuracyTable, ReplacesAndDropsTermsOverTheClass) {
  const Scene s = parse_scene(std::string(kSmallPile) + "[accuracy]\noverlap = 0.002\nrest_speed = false\n"
                                                             "horizon = 0.5\n",
                                   "small.toml");
  const AccuracySpec spec = scene_spec(s);
  EXPECT_EQ(spec[SpecTerm::overlap], 0.002);
  EXPECT_FALSE(spec[SpecTerm::rest_speed]);
  EXPECT_EQ(spec[SpecTerm::horizon], 0.5);
  EXPECT_EQ(spec[SpecTerm::tunnelling], 0);  // kept from the class
  EXPECT_TRUE(spec.needs_reference());
}

TEST(SceneAccuracyTable, BadTermsAreOneLineNamingFileLineAndField) {
  const auto error = [](const std::string& table) {
    try {
      parse_scene(std::string(kSmallPile) + "[accuracy]\n" + table, "small.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("overlapp = 0.01\n"), "small.toml:16: accuracy.overlapp: unknown key, did you mean 'overlap'?");
  EXPECT_EQ(error("overlap = -0.01\n"), "small.toml:16: accuracy.overlap: must be a finite number >= 0, got -0.01");
  EXPECT_EQ(error("tunnelling = 0.5\n"),
            "small.toml:16: accuracy.tunnelling: must be a finite number >= 0 and whole, got 0.5");
  EXPECT_EQ(error("overlap = \"small\"\n"),
            "small.toml:16: accuracy.overlap: expected a number (or false to drop it), got a string");
}

TEST(SpecTexts, SetAndDropTermsAndRefuseWhatIsNotOne) {
  AccuracySpec s = scene_spec(load_scene("pile"));
  apply_spec_texts(s, {"overlap=0.005", "rest_speed=none", "sticking=3"}, "--spec");
  EXPECT_EQ(s[SpecTerm::overlap], 0.005);
  EXPECT_FALSE(s[SpecTerm::rest_speed]);
  EXPECT_EQ(s[SpecTerm::sticking], 3);
  EXPECT_THROW(apply_spec_texts(s, {"overlap"}, "--spec"), InputError);
  EXPECT_THROW(apply_spec_texts(s, {"depth=0.1"}, "--spec"), InputError);
  EXPECT_THROW(apply_spec_texts(s, {"overlap=0.1x"}, "--spec"), InputError);
  EXPECT_THROW(apply_spec_texts(s, {"overlap=nan"}, "--spec"), InputError);
  EXPECT_THROW(apply_spec_texts(s, {"tunnelling=1.5"}, "--spec"), InputError);
  // Numbers are decimal and whole (std::stod would read 0x10 as 16), and a term is given once.
  for (const char* bad : {"overlap=0x10", "overlap= 0.1", "overlap=", "overlap=+0.1"}) {
    try {
      apply_spec_texts(s, {bad}, "--spec");
      ADD_FAILURE() << bad << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is not a decimal number"), std::string::npos) << e.what();
    }
  }
  try {
    apply_spec_texts(s, {"overlap=0.01", "overlap=0.02"}, "--spec");
    ADD_FAILURE() << "a term given twice was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--spec overlap=0.02: overlap is given twice");
  }
  AccuracySpec e = scene_spec(load_scene("pile"));
  apply_spec_texts(e, {"overlap=1e-3"}, "--spec");
  EXPECT_EQ(e[SpecTerm::overlap], 1e-3);
}

Result ok_run() {
  Result r;
  r.status = RunStatus::ok;
  r.steps_done = 10;
  r.dt = 0.01;
  r.metrics = resting_values();  // every metric a run measures, nothing happening
  return r;
}

TEST(Judge, MeetsOnlyWhenEveryBoundTermIsWithinIt) {
  AccuracySpec spec;
  spec[SpecTerm::overlap] = 0.01;
  spec[SpecTerm::tunnelling] = 0;
  spec[SpecTerm::rest_speed] = 0.001;
  Result r = ok_run();
  r.metrics.set(Metric::penetration_max, 0.5);  // the placement's, not judged
  r.metrics.set(Metric::penetration_after_start, 0.008);
  r.metrics.set(Metric::jitter, 1e-4);
  SpecVerdict v = judge(spec, r);
  EXPECT_TRUE(v.met) << v.why_not;
  EXPECT_EQ(v.figures["overlap"], 0.008);

  r.metrics.set(Metric::penetration_after_start, 0.02);
  r.metrics.set(Metric::tunnelling_pair, 1);
  v = judge(spec, r);
  EXPECT_FALSE(v.met);
  EXPECT_EQ(v.why_not, "overlap 0.02 > 0.01; tunnelling 1 > 0");

  r = ok_run();
  r.metrics.set(Metric::jitter, nullptr);  // a term the run did not measure fails, never passes
  v = judge(spec, r);
  EXPECT_FALSE(v.met);
  EXPECT_EQ(v.why_not, "rest_speed not measured");
  EXPECT_TRUE(v.figures["rest_speed"].is_null());

  r = ok_run();
  r.metrics.set(Metric::jitter, 0);
  r.status = RunStatus::diverged;
  r.error = "a ball left the container";
  EXPECT_FALSE(judge(spec, r).met);
}

TEST(Judge, HorizonIsAtLeastAndTheWholeRunWhereNeverExceeded) {
  AccuracySpec spec;
  spec[SpecTerm::horizon] = 0.05;
  Result r = ok_run();
  EXPECT_EQ(judge(spec, r).why_not, "horizon not measured");  // no reference ran
  r.reference.available = true;
  r.reference.horizon = 0.03;
  EXPECT_EQ(judge(spec, r).why_not, "horizon 0.03 < 0.05");
  r.reference.horizon.reset();  // never left the tolerance: all 10 steps of 0.01 s
  EXPECT_TRUE(judge(spec, r).met);
  EXPECT_DOUBLE_EQ(spec_figure(SpecTerm::horizon, r).value(), 0.1);
}

TEST(HomeMethod, EventsWithoutAPileAndAStifferSoftStepForATighterOverlap) {
  EXPECT_FALSE(choose_home_method(load_scene("gas"), 0.01, 0.01).soft);
  EXPECT_FALSE(choose_home_method(load_scene("projectile"), 0.01, 0.01).soft);
  const Scene pile = load_scene("pile");
  // 500 balls of r = 0.25 in a box 12 m wide: 500 pi 0.0625 / (0.82 x 12) = 9.98 m, / (sqrt 3 x 0.25).
  EXPECT_NEAR(settled_layers(pile), 500 * M_PI * 0.0625 / (0.82 * 12) / (std::sqrt(3.0) * 0.25), 1e-9);
  const auto hertz = [](const std::string& scene, double overlap) {
    const HomeMethod m = choose_home_method(load_scene(scene), 0.01, overlap);
    EXPECT_TRUE(m.soft) << scene;
    // The push-out uses at most a quarter of the substep rate, substeps / dt.
    EXPECT_GE(m.substeps / 0.01 / 4, m.contact_hertz) << scene;
    EXPECT_LT((m.substeps - 1) / 0.01 / 4, m.contact_hertz) << scene;
    return m.contact_hertz;
  };
  // A deep pile's weight binds: sag ~ 1 / f^2, half the overlap takes sqrt(2) times the frequency.
  EXPECT_NEAR(hertz("pile-10k", 0.005) / hertz("pile-10k", 0.01), std::sqrt(2.0), 1e-9);
  // A shallow heap's landings bind: their overlap ~ 1 / f, half of it takes twice the frequency.
  EXPECT_NEAR(hertz("smooth-pile", 0.005) / hertz("smooth-pile", 0.01), 2.0, 1e-9);
  EXPECT_NEAR(hertz("smooth-pile", 0.01), kLandingRate / 0.01 / (2 * M_PI), 1e-9);
}

// What the default profile builds for a spec meets it, on the pile and bowl scenes small enough to
// run here, from 5% to 0.5% of the radius (the built-in piles of 10^4 balls: PERFORMANCE.md). The
// overlap with no tunnelling: the frictionless heap is still spreading at its end, whatever the
// solver, so rest is not what this asks.
TEST(HomeMethod, TheDefaultProfileMeetsTheOverlapItWasBuiltFor) {
  for (const std::string name : {"pile", "rough-pile", "smooth-pile", "seed-bowl"})
    for (const double overlap : {0.05, 0.02, 0.01, 0.005}) {
      Scene scene = load_scene(name);
      const AccuracySpec spec = cli::ask_scene_for(scene, {fmt::format("overlap={}", overlap), "rest_speed=none"});
      const Result r = run_engine(scene, find_engine("home"), {});
      const SpecVerdict v = judge(spec, r);
      EXPECT_TRUE(v.met) << name << " at " << overlap << ": " << v.why_not;
    }
}

TEST(HomeMethod, TheDefaultProfileRecordsTheMethodItChose) {
  const EngineEntry& home = find_engine("home");
  const auto settings = [&](const std::string& scene, const nlohmann::json& set) {
    return home.create(load_scene(scene), "default", set)->settings();
  };
  EXPECT_EQ(settings("gas", {})["resting"], "events");
  const auto pile = settings("pile", {});
  EXPECT_EQ(pile["resting"], "soft");
  EXPECT_EQ(pile["overlap"], 0.01);  // the scene's spec
  EXPECT_EQ(pile["substeps"], choose_home_method(load_scene("pile"), 0.01, 0.01).substeps);
  // A setting given explicitly wins over the derived one.
  EXPECT_EQ(settings("pile", {{"substeps", 5}})["substeps"], 5);
  EXPECT_EQ(home.create(load_scene("pile"), "events", {})->settings()["resting"], "events");
}

// The search on a small pile: home meets the class spec, the thesis port (no resting contact, balls
// sink into each other) never does; a found point re-run by itself meets the spec again.
TEST(Match, FindsAPointThatReproducesAndSaysNotReachedWithTheBestTried) {
  const Scene scene = parse_scene(kSmallPile, "small-pile.toml");
  cli::MatchOptions o;
  o.spec = scene_spec(scene);
  o.max_halvings = 1;
  o.repeats = 1;
  o.knobs = false;
  o.quiet = true;
  o.isolation.enabled = false;
  const MatchResult m = cli::run_match(scene, {&find_engine("home"), &find_engine("home-seed")}, o, {});
  ASSERT_EQ(m.outcomes.size(), 4u);  // home: default, events, soft; home-seed
  const MatchOutcome& home = m.outcomes[0];
  ASSERT_TRUE(home.reached) << m.tries.at(std::max(0, home.best)).why_not;
  const MatchTry& found = m.tries[home.found];
  EXPECT_TRUE(found.met);
  EXPECT_EQ(found.halvings, 0);
  // Its window, timed alone: milliseconds, so repeated past the one asked (until the repeats' warm
  // passes hold kTimedSeconds), within what is allowed.
  EXPECT_GT(home.cost_repeats.size(), size_t(o.repeats));
  EXPECT_LE(home.cost_repeats.size(), size_t(cli::kTimingRepeatsFactor * o.repeats));
  EXPECT_NE(home.command.find("--profile default --dt 0.01 --no-reference"), std::string::npos) << home.command;
  Scene again = scene;
  again.dt = found.dt;
  RunOptions ro;
  ro.profile = found.profile;
  EXPECT_TRUE(judge(o.spec, run_engine(again, find_engine("home"), ro)).met);

  const MatchOutcome& seed = m.outcomes[3];
  EXPECT_EQ(seed.engine, "home-seed");
  EXPECT_FALSE(seed.reached);
  EXPECT_EQ(seed.found, -1);
  ASSERT_GE(seed.best, 0);
  EXPECT_FALSE(m.tries[seed.best].met);
  EXPECT_FALSE(m.tries[seed.best].why_not.empty());
  EXPECT_EQ(seed.tries, 2);  // dt and dt/2
  EXPECT_DOUBLE_EQ(seed.finest_dt, 0.005);

  // The JSON holds every try and reads back to the same outcomes.
  const MatchResult back = match_from_json(to_json(m));
  EXPECT_EQ(back.tries.size(), m.tries.size());
  EXPECT_EQ(back.outcomes[3].best, seed.best);
  EXPECT_EQ(back.spec.to_json(), m.spec.to_json());
}

// A knob that changes nothing on this scene (home's overlap, on the event-driven path a gas takes)
// gives the profile's own trajectory: it is tried once and never found, however its timing falls.
TEST(Match, AKnobThatChangesNothingIsNeverTheFinding) {
  const Scene scene = load_scene("two-ball-1");
  cli::MatchOptions o;
  o.spec = scene_spec(scene);
  o.profile = "default";
  o.max_halvings = 0;
  o.repeats = 0;
  o.quiet = true;
  o.isolation.enabled = false;
  const MatchResult m = cli::run_match(scene, {&find_engine("home")}, o, {});
  ASSERT_EQ(m.outcomes.size(), 1u);
  ASSERT_TRUE(m.outcomes[0].reached);
  EXPECT_EQ(m.tries[m.outcomes[0].found].knob, "");
  int knob_tries = 0;
  for (const MatchTry& t : m.tries) knob_tries += !t.knob.empty();
  EXPECT_EQ(knob_tries, 3);  // overlap = 0.005, 0.0025, 0.001: each once
}

// `--spec` asks the scene for an accuracy: home's default profile builds itself for it (a stiffer
// spring, more substeps), and match's reproducing lines carry it so `run` builds the same.
TEST(MatchCli, TheSpecAskedForIsWhatHomeBuildsForAndWhatTheCommandsCarry) {
  Scene pile = load_scene("pile");
  const auto home_settings = [&] { return find_engine("home").create(pile, "default", {})->settings(); };
  const auto by_default = home_settings();
  EXPECT_DOUBLE_EQ(cli::ask_scene_for(pile, {"overlap=0.005"})[SpecTerm::overlap].value(), 0.005);
  const auto asked = home_settings();
  EXPECT_DOUBLE_EQ(asked["overlap"].get<double>(), 0.005);
  EXPECT_GT(asked["substeps"].get<int>(), by_default["substeps"].get<int>());
  EXPECT_THROW(cli::ask_scene_for(pile, {"overlap=none", "tunnelling=none", "rest_speed=none"}), InputError);

  const fs::path dir = fs::temp_directory_path() / ("ballbench-match-spec." + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string scene = (dir / "small-pile.toml").string();
  std::ofstream(scene) << kSmallPile;
  const auto r = run_cli("match --scene " + scene + " --engine home --profile default --max-halvings 0 --no-knobs "
                         "--quiet --spec overlap=0.005 --json " + (dir / "m.json").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const MatchResult m = read_match_file((dir / "m.json").string());
  ASSERT_EQ(m.outcomes.size(), 1u);
  EXPECT_NE(m.outcomes[0].command.find(" --spec overlap=0.005"), std::string::npos) << m.outcomes[0].command;
  const auto bad = run_cli("run --scene pile --engine home --steps 1 --spec overlap=-1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--spec overlap=-1"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}

TEST(MatchCli, WritesJsonAndCsvShardsMergeAndBadSpecsAreOneLine) {
  const fs::path dir = fs::temp_directory_path() / "ballbench-match-cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = (dir / "small-pile.toml").string();
  std::ofstream(scene) << kSmallPile;
  const std::string base = "match --scene " + scene + " --engine home --profile all --max-halvings 0 --quiet ";
  for (int i = 1; i <= 2; ++i) {
    const auto r = run_cli(base + fmt::format("--shard {}/2 --json {}/m{}.json", i, dir.string(), i));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const auto merged = run_cli(fmt::format("merge {0}/m1.json {0}/m2.json --out {0}/m.json", dir.string()));
  ASSERT_EQ(merged.status, 0) << merged.err;
  const MatchResult m = read_match_file((dir / "m.json").string());
  EXPECT_EQ(m.outcomes.size(), 3u);
  EXPECT_EQ(m.shard_count, 1);
  std::ifstream csv(dir / "m.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("engine,profile,knob,value,halvings,dt,status,met,cost_ns,cost_pipe_ns,wall_s,work,done,overlap,", 0), 0u);
  EXPECT_EQ(m.searches, (std::vector<std::string>{"home/default", "home/events", "home/soft"}));
  // A shard that lost a search, or of another build, is refused in one line; nothing is written.
  const auto edited = [&](const std::string& name, const std::string& key, const nlohmann::json& value) {
    nlohmann::json j = nlohmann::json::parse(testing::slurp((dir / "m2.json").string()));
    if (key == "outcomes") j["outcomes"] = value;
    else j["context"][key] = value;
    std::ofstream(dir / name) << j.dump(2);
    return (dir / name).string();
  };
  for (const auto& [shard, want] : std::vector<std::pair<std::string, std::string>>{
           {edited("gap.json", "outcomes", nlohmann::json::array()), "no shard holds the planned search home/"},
           {edited("built.json", "build", "0123456789abcdef"), "was made by build 0123456789abcdef"}}) {
    const auto o = run_cli(fmt::format("merge {0}/m1.json {1} --out {0}/m3.json", dir.string(), shard));
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find(want), std::string::npos) << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    EXPECT_FALSE(fs::exists(dir / "m3.json"));
  }

  const auto bad = run_cli("match --scene pile --engine home --spec overlapp=0.01 --quiet");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--spec overlapp=0.01: expected KEY=VALUE with KEY one of overlap"), std::string::npos)
      << bad.err;
  fs::remove_all(dir);
}

// A search that met the spec but ran out of budget before trying every configuration is marked cut
// short, with why, and never ranked: its cost is only an upper bound.
TEST(MatchCli, ASearchCutShortByItsBudgetIsMarkedAndNotRanked) {
  const fs::path dir = fs::temp_directory_path() / "ballbench-match-cut-short";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto r = run_cli("match --scene seed-box --engine home --profile default --budget 1.5 --store '' --quiet --json " +
                         (dir / "m.json").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("home               cut short    dt"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("home: cut short: it met the spec, but its search stopped at the budget (1.5 runs at dt"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("home: not compared: its search was cut short"), std::string::npos) << r.out;
  const MatchResult m = read_match_file((dir / "m.json").string());
  ASSERT_EQ(m.outcomes.size(), 1u);
  EXPECT_TRUE(m.outcomes[0].cut_short());
  EXPECT_EQ(cheapest_reached(m, role_name(EngineRole::ours)), nullptr);
  fs::remove_all(dir);
}

// An interrupted match keeps a row for every search of its plan: one the interrupt cut short (or
// that never started) says so and is never ranked.
TEST(MatchCli, AnInterruptedMatchMarksEverySearchItCutShort) {
  const fs::path dir = fs::temp_directory_path() / "ballbench-match-interrupted";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cmd = "timeout --preserve-status -s INT 5 " + std::string(BALLBENCH_CLI) +
                          " match --scene pile --engine home,box2d --profile all --jobs 1 --store '' --json " +
                          (dir / "m.json").string() + " >" + (dir / "out").string() + " 2>" + (dir / "err").string();
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 130) << testing::slurp((dir / "err").string());
  const MatchResult m = read_match_file((dir / "m.json").string());
  EXPECT_EQ(m.interrupted, "SIGINT");
  ASSERT_EQ(m.outcomes.size(), m.searches.size());
  ASSERT_EQ(m.searches.size(), 5u);
  int cut = 0;
  for (const MatchOutcome& oc : m.outcomes)
    if (oc.stop == SearchStop::interrupt) {
      ++cut;
      EXPECT_TRUE(!oc.reached || oc.cut_short()) << oc.engine << "/" << oc.profile;
      EXPECT_NE(cheapest_reached(m, oc.role), &oc) << oc.engine << "/" << oc.profile;
    }
  EXPECT_GE(cut, 1);
  const std::string out = testing::slurp((dir / "out").string());
  EXPECT_NE(out.find("interrupted before it started"), std::string::npos) << out;
  fs::remove_all(dir);
}

// A match killed before it removed its working folder leaves it; the next match removes folders of
// processes that are gone, keeps a live one's, and leaves none of its own.
TEST(MatchCli, TheNextMatchRemovesTheWorkingFolderOfADeadOne) {
  const fs::path tmp = fs::temp_directory_path() / ("bb_workdirs." + std::to_string(::getpid()));
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  const fs::path gone = tmp / fmt::format("ballbench-match.{}.AbC123", dead);
  const fs::path live = tmp / fmt::format("ballbench-match.{}.XyZ789", ::getpid());
  for (const fs::path& d : {gone, live}) {
    fs::create_directories(d);
    std::ofstream(d / "window.toml") << "left";
  }
  const std::string kept_tmpdir = std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "";
  ::setenv("TMPDIR", tmp.c_str(), 1);  // the command's temporary folder: this test's own
  const auto r = run_cli("match --scene seed-box --engine home --profile default --max-halvings 0 --store '' --quiet "
                         "--json " + (tmp / "m.json").string());
  if (kept_tmpdir.empty()) ::unsetenv("TMPDIR");
  else ::setenv("TMPDIR", kept_tmpdir.c_str(), 1);
  ASSERT_EQ(r.status, 0) << r.err;
  std::set<std::string> left;
  for (const auto& e : fs::directory_iterator(tmp)) left.insert(e.path().filename().string());
  // The dead one's gone, the live one's kept, and the match left none of its own.
  EXPECT_EQ(left, (std::set<std::string>{live.filename().string(), "m.json", "m.csv"}));
  EXPECT_TRUE(fs::exists(live / "window.toml"));
  fs::remove_all(tmp);
}

// The ratio line against a target: met, short by how much, undecided without an external point.
TEST(MatchCli, TheRatioLineSaysWhetherTheTargetWasMet) {
  MatchResult m;
  m.scene = "pile", m.n = 500, m.dt = 0.01;
  m.spec[SpecTerm::overlap] = 0.01;
  for (const char* engine : {"home", "chipmunk"}) {
    MatchTry t;
    t.engine = engine, t.profile = "default", t.dt = 0.01, t.met = true;
    t.figures = {{"overlap", 0.005}};
    m.tries.push_back(t);
  }
  MatchOutcome ours, theirs;
  ours.engine = "home", ours.profile = "default", ours.role = role_name(EngineRole::ours), ours.reached = true;
  ours.found = 0, ours.cost_ns = 100;
  theirs.engine = "chipmunk", theirs.profile = "default", theirs.role = role_name(EngineRole::external);
  theirs.reached = true, theirs.found = 1, theirs.cost_ns = 500;
  m.outcomes = {ours, theirs};
  const auto printed = [&](std::optional<double> target) {
    ::testing::internal::CaptureStdout();
    cli::print_match(m, target);
    return ::testing::internal::GetCapturedStdout();
  };
  EXPECT_NE(printed(4).find("5.0x cheaper than the cheapest external engine that met the spec"), std::string::npos)
      << printed(4);
  EXPECT_NE(printed(4).find("500 ns) (target 4x: met)"), std::string::npos)
      << printed(4);
  EXPECT_NE(printed(10).find("(target 10x: not met, 2.0x short)"), std::string::npos) << printed(10);
  EXPECT_EQ(printed(std::nullopt).find("target"), std::string::npos);
  m.outcomes[1].reached = false, m.outcomes[1].found = -1, m.outcomes[1].best = 1;
  EXPECT_NE(printed(10).find("no external engine met the spec (target 10x: undecided within the budget)"),
            std::string::npos)
      << printed(10);
}

// A scene whose balls start at rest without gravity has no energy to drift from: a spec bounding
// the drift, its class's default included, is refused in one line naming the term and its fix.
TEST(MatchCli, ASpecTheSceneCannotMeasureIsRefusedWithItsFix) {
  const fs::path dir = fs::temp_directory_path() / ("ballbench-still." + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string scene = (dir / "still.toml").string();
  std::ofstream(scene) << "dt = 0.01\nduration = 0.1\n[container]\nmin = [-5.0, -5.0]\nmax = [5.0, 5.0]\n"
                          "[[ball]]\npos = [0.0, 0.0]\nvel = [0.0, 0.0]\nradius = 0.5\n"
                          "[[ball]]\npos = [2.0, 0.0]\nvel = [0.0, 0.0]\nradius = 0.5\n";
  const auto r = run_cli("match --scene " + scene + " --engine home --quiet --spec energy_drift=1e-3 --json " +
                         (dir / "m.json").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--spec energy_drift: still starts with no energy (E0 = 0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("energy_drift=none"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "m.json"));
  // Without the term it runs.
  const auto ok = run_cli("match --scene " + scene + " --engine home --profile default --max-halvings 0 --no-knobs "
                          "--quiet --spec energy_drift=none,overlap=0.01 --json " + (dir / "m.json").string());
  EXPECT_EQ(ok.status, 0) << ok.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ballbench

namespace ballbench {
// The step benchmark's label and the scaling page that reads it back share the verdict's words.
TEST(SpecVerdict, AVerdictLineReadsBackItsDetail) {
  EXPECT_EQ(verdict_line(false, "overlap 0.031 > 0.02"), "not met: overlap 0.031 > 0.02");
  EXPECT_EQ(verdict_detail(verdict_line(false, "overlap 0.031 > 0.02")), "overlap 0.031 > 0.02");
  EXPECT_EQ(verdict_detail(verdict_line(true, "overlap 0.004 (<= 0.01)")), "overlap 0.004 (<= 0.01)");
  EXPECT_EQ(verdict_detail("diverged"), "diverged");
}
}  // namespace ballbench

// The report's sections read as the issue asks: each scene's table has the columns that mean
// something on it (the rest in its appendix), "best" marks only where a ranking means something,
// what was not measured is null in the JSON and "n/a" in the report, ratios below 0.1 read as
// inverses, a sleeping pile gets no ratio, settings are a link, and a merged or partial report
// says so. From hand-made results: no engine runs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bench_results.h"
#include "metrics/meter_set.h"
#include "made_run.h"
#include "report_text.h"
#include "report_writer.h"
#include "result.h"

namespace ballbench {
namespace {

SceneFeatures features(bool walls, bool gravity, bool elastic) {
  SceneFeatures f;
  f.walls = walls, f.gravity = gravity, f.elastic = elastic, f.frictionless = true;
  return f;
}

Result run(std::string engine, std::string scene, const SceneFeatures& f, double ns) {
  Result r = made_run(std::move(engine), std::move(scene));
  r.scene_features = f;
  r.ns_per_ball_step = ns, r.ns_per_step = 20 * ns;
  r.metrics.set(Metric::energy_initial, 10), r.metrics.set(Metric::energy_final, 5), r.metrics.set(Metric::energy_max_rel_drift, 0.5);
  r.metrics.set(Metric::momentum_max_abs_drift, 3);
  r.metrics.set(Metric::samples, 101);
  return r;
}

// The text of the section that starts with `heading`, up to the next heading.
std::string section(const std::string& md, const std::string& heading) {
  const size_t at = md.find(heading);
  if (at == std::string::npos) return "";
  const size_t end = md.find("\n#", at + heading.size());
  return md.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// The header lines of `text`'s tables, joined (a wide table is split into several).
std::string header(const std::string& text) {
  std::string out;
  for (size_t at = text.find("\n| engine |"); at != std::string::npos; at = text.find("\n| engine |", at + 1))
    out += text.substr(at + 1, text.find('\n', at + 1) - at - 1);
  return out;
}

ReportInputs inputs(std::vector<Result> results) {
  ReportInputs in;
  in.run = nlohmann::json::object();
  in.results = std::move(results);
  return in;
}

TEST(ReportSections, AScenesTableHasTheColumnsThatMeanSomethingOnItAndTheRestInItsAppendix) {
  const SceneFeatures pile = features(true, true, false), gas = features(false, false, true);
  const auto pages = render_report(inputs({run("a", "pile", pile, 10), run("b", "pile", pile, 20),
                                           run("a", "gas", gas, 10), run("b", "gas", gas, 20)}));
  const std::string pile_page = page_text(pages, "scenes/pile.md"), gas_page = page_text(pages, "scenes/gas.md");
  const std::string pile_table = header(section(pile_page, "## Every engine"));
  const std::string gas_table = header(section(gas_page, "## Every engine"));
  // Walls and gravity: no momentum; restitution below 1: the energy left, not a drift.
  EXPECT_EQ(pile_table.find("momentum drift"), std::string::npos) << pile_table;
  EXPECT_EQ(pile_table.find("energy drift"), std::string::npos) << pile_table;
  EXPECT_NE(pile_table.find("E final / E0"), std::string::npos) << pile_table;
  EXPECT_NE(pile_table.find("penetration after start"), std::string::npos) << pile_table;
  EXPECT_EQ(pile_table.find("penetration max"), std::string::npos) << pile_table;
  // Open space, no gravity, elastic: momentum and the energy drift are the engine's.
  EXPECT_NE(gas_table.find("momentum drift"), std::string::npos) << gas_table;
  EXPECT_NE(gas_table.find("energy drift"), std::string::npos) << gas_table;
  EXPECT_EQ(gas_table.find("E final / E0"), std::string::npos) << gas_table;
  // The pile's other columns below its table, on its page.
  const std::string appendix = pile_page.substr(pile_page.find("### The other columns"));
  EXPECT_NE(header(appendix).find("momentum drift"), std::string::npos) << appendix;
  EXPECT_NE(header(appendix).find("penetration max"), std::string::npos) << appendix;
  // The energy a restitution below 1 loses is physics, not drift; a gas's drift is the engine's.
  EXPECT_EQ(pile_page.find("energy drifted"), std::string::npos);
  EXPECT_NE(gas_page.find("energy drifted by up to 50%"), std::string::npos);
}

TEST(ReportSections, AChaoticSceneRanksByTheHorizonNotTheFinalError) {
  const SceneFeatures box = features(true, false, true);
  std::vector<Result> runs = {run("exact", "box", box, 50), run("a", "box", box, 10), run("b", "box", box, 20)};
  for (Result& r : runs) {
    r.reference.available = true;
    r.reference.reference = "exact";
  }
  runs[1].reference.pos_rms_final = 6.0, runs[1].reference.horizon = 1.96;
  runs[2].reference.pos_rms_final = 4.4, runs[2].reference.horizon = 0.05;
  const std::string md = page_text(render_report(inputs(runs)), "scenes/box.md");
  const std::string scene = section(md, "## Every engine");
  EXPECT_NE(header(scene).find("horizon (s)"), std::string::npos) << scene;
  EXPECT_EQ(header(scene).find("pos error"), std::string::npos) << scene;
  EXPECT_NE(scene.find("**1.96**"), std::string::npos) << scene;  // the later horizon
  EXPECT_NE(scene.find("Chaotic"), std::string::npos) << scene;
  // The final error is among the other columns, where nothing is marked best.
  const std::string appendix = md.substr(md.find("### The other columns"));
  EXPECT_NE(header(appendix).find("pos error"), std::string::npos) << appendix;
  EXPECT_EQ(appendix.find("**"), std::string::npos) << appendix;

  // Where an engine stays with the reference the scene is not chaotic: the final error ranks.
  runs[1].reference.horizon.reset();
  const std::string calm = section(page_text(render_report(inputs(runs)), "scenes/box.md"), "## Every engine");
  EXPECT_NE(header(calm).find("pos error"), std::string::npos) << calm;
  EXPECT_NE(calm.find("**4.4**"), std::string::npos) << calm;
}

TEST(ReportSections, BestIsMarkedOnlyWhereARankingMeansSomething) {
  const SceneFeatures bowl = features(true, true, false);
  Result fast_but_broken = run("seed", "bowl", bowl, 1);
  fast_but_broken.metrics.set(Metric::tunnelling_pair, 360);
  Result diverged = run("wild", "bowl", bowl, 0.5);
  diverged.status = RunStatus::diverged, diverged.diverged_step = 40, diverged.steps_done = 40;
  Result refused = run("lazy", "bowl", bowl, 0);
  refused.status = RunStatus::unsupported, refused.steps_done = 0, refused.error = "no walls";
  const std::string scene = page_text(
      render_report(inputs({fast_but_broken, diverged, refused, run("a", "bowl", bowl, 10), run("b", "bowl", bowl, 20)})),
      "scenes/bowl.md");
  // No cost at the scene's own step (the engines reach different accuracies there): no run is
  // "fastest", least of all one that tunnels or diverged.
  EXPECT_EQ(scene.find("ns/ball-step"), std::string::npos) << scene;
  EXPECT_EQ(scene.find("ns per ball-step"), std::string::npos) << scene;
  // Wall tunnelling and sticking are 0 in every ok run: no best among equals; the pair tunnelling
  // ranks the runs that did not tunnel above the one that did.
  EXPECT_NE(scene.find("| a | default | ok | 0.5 | 0 | **0** | 0 | 0 |"), std::string::npos) << scene;
  // The refused run has no figures: n/a, never a dash or a zero, and never bold.
  const size_t row = scene.find("| lazy |");
  ASSERT_NE(row, std::string::npos) << scene;
  const std::string line = scene.substr(row, scene.find('\n', row) - row);
  EXPECT_NE(line.find("| unsupported | n/a |"), std::string::npos) << line;
  EXPECT_EQ(line.find("| - |"), std::string::npos) << line;
  EXPECT_EQ(line.find("| 0 |"), std::string::npos) << line;
  EXPECT_NE(scene.find("- **lazy**: unsupported: no walls."), std::string::npos) << scene;
}

TEST(ReportSections, ThePlacementsOverlapIsSaidApartFromTheEnginesPenetration) {
  const SceneFeatures box = features(true, false, true);
  std::vector<Result> runs = {run("a", "box", box, 10), run("b", "box", box, 20)};
  for (Result& r : runs) r.metrics.set(Metric::penetration_initial, 0.472), r.metrics.set(Metric::penetration_max, 0.472);
  runs[0].metrics.set(Metric::penetration_after_start, 0.01), runs[1].metrics.set(Metric::penetration_after_start, 0.2);
  const std::string scene = section(page_text(render_report(inputs(runs)), "scenes/box.md"), "## Every engine");
  EXPECT_NE(scene.find("overlapping by up to 0.472 of a radius (every engine, `penetration.initial`)"),
            std::string::npos)
      << scene;
  EXPECT_NE(scene.find("**0.01**"), std::string::npos) << scene;
  EXPECT_EQ(header(scene).find("initial overlap"), std::string::npos) << scene;
}

TEST(ReportSections, SettingsAreALinkToTheResultsFileNotInlineJson) {
  Result r = run("a", "box", features(true, false, true), 10);
  r.settings = {{"secret_knob", 42}};
  ReportInputs in = inputs({r, run("b", "box", features(true, false, true), 20)});
  in.result_files["box"] = "results/box.json";
  const std::string md = all_pages(render_report(in));
  // Linked from the engines page, one folder down.
  EXPECT_NE(page_text(render_report(in), "pages/engines.md").find("[results/box.json](../results/box.json)"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("secret_knob"), std::string::npos);
}

// A run that made no step stores null, not 0, for what it did not measure; the horizon's null
// says which of its meanings it has.
TEST(ReportSections, WhatWasNotMeasuredIsNullInTheJson) {
  Result refused = run("lazy", "box", features(true, false, true), 0);
  refused.status = RunStatus::unsupported, refused.steps_done = 0;
  const nlohmann::json j = to_json(refused);
  for (const char* key : {"/ns_per_step", "/ns_per_ball_step", "/engine_s", "/tunnelling/wall", "/tunnelling/pair",
                          "/sticking/pair", "/penetration/max", "/energy/final"})
    EXPECT_TRUE(j.at(nlohmann::json::json_pointer(key)).is_null()) << key << ": " << j.at(nlohmann::json::json_pointer(key));
  EXPECT_FALSE(j.contains("error_vs_reference"));
  const Result back = result_from_json(j);
  EXPECT_FALSE(back.measured());
  EXPECT_EQ(back.status, RunStatus::unsupported);
  EXPECT_TRUE(back.scene_features && back.scene_features->walls && !back.scene_features->gravity);

  Result measured = run("a", "box", features(true, false, true), 10);
  measured.reference.available = true, measured.reference.reference = "exact";
  EXPECT_EQ(to_json(measured)["error_vs_reference"]["horizon_status"], "within");
  EXPECT_TRUE(to_json(measured)["error_vs_reference"]["horizon"].is_null());
  measured.reference.horizon = 0.3;
  EXPECT_EQ(to_json(measured)["error_vs_reference"]["horizon_status"], "exceeded");
  EXPECT_EQ(to_json(measured)["ns_per_ball_step"], 10.0);
}

TEST(ReportSections, ASleepingPileGetsNoRateAndTheScalingRanksNoEngine) {
  BenchResults b;
  const auto row = [](std::string engine, std::string profile, double ns, double steps_per_s) {
    BenchRow r;
    r.engine = std::move(engine), r.profile = std::move(profile), r.scene = "settled", r.n = 1000;
    r.ns_per_ball_step = ns, r.steps_per_s = steps_per_s;
    return r;
  };
  b.rows = {row("mine", "default", 330, 3), row("theirs", "stock", 1, 1000), row("mine", "soft-sleep", 1e-4, 1e7),
            row("theirs", "stock-sleep", 0.5, 2000)};
  ReportInputs in = inputs({});
  in.bench = b;
  in.roles = {{"mine", EngineRole::ours}};
  const std::string md = all_pages(render_report(in));
  // At the scene's own step, each engine at whatever accuracy that gives: no ratio between them.
  EXPECT_EQ(md.find(" against the fastest"), std::string::npos) << md;
  EXPECT_EQ(md.find("0.0x"), std::string::npos) << md;
  // Asleep: no rate.
  EXPECT_EQ(md.find("10000000.0 steps per second"), std::string::npos) << md;
  EXPECT_NE(md.find("`mine/soft-sleep`: its balls sleep"), std::string::npos) << md;
  // A thousand balls: the rate, but no memory per ball (fixed costs would dominate it).
  EXPECT_NE(md.find("`mine` at 1000 balls: 3.0 steps per second."), std::string::npos) << md;
}

// The budget a benchmark stops at is the one its binary ran under, read from its JSON's context
// (bench/bench_main.cpp writes it); a file without it says no figure rather than a stale one.
TEST(ReportSections, TheScalingStatesTheBudgetItsBenchmarksRanUnder) {
  BenchResults b;
  BenchRow r;
  r.engine = "mine", r.profile = "default", r.scene = "gas", r.n = 100, r.ns_per_ball_step = 50;
  b.rows = {r};
  b.context = {{"budget_s", "5"}};
  ReportInputs in = inputs({});
  in.bench = b;
  in.roles = {{"mine", EngineRole::ours}};
  EXPECT_NE(all_pages(render_report(in)).find("past its budget (5 s here) stops"), std::string::npos);
  in.bench->context = nlohmann::json::object();
  const std::string md = all_pages(render_report(in));
  EXPECT_NE(md.find("past its budget stops"), std::string::npos) << md;
  EXPECT_EQ(md.find(" s here)"), std::string::npos) << md;
}

TEST(ReportSections, AMergedReportShowsEveryShardsMachineAndWhatWasLeftOut) {
  ReportInputs in = inputs({});
  in.run = nlohmann::json::parse(R"({
    "suite": "quick", "merge": {"command": "ballbench merge a b --out m", "date": "2026-12-04 00:30 UTC"},
    "shards": [
      {"cpu": "Xeon A", "cores": 2, "command": "ballbench report --shard 1/2 --no-bench", "date": "d1",
       "shard": {"index": 1, "count": 2}, "ran": ["table:seed-box", "calibration"],
       "left_out": ["the scaling and harness overhead sections: --no-bench"]},
      {"cpu": "Epyc B", "cores": 64, "command": "ballbench report --shard 2/2 --no-bench", "date": "d2",
       "shard": {"index": 2, "count": 2}, "ran": ["table:seed-bowl"],
       "left_out": ["the scaling and harness overhead sections: --no-bench"]}]})");
  const std::string md = all_pages(render_report(in));
  for (const char* want : {"This report: `ballbench merge a b --out m`", "| | shard 1/2 | shard 2/2 |",
                           "| cpu | Xeon A | Epyc B |", "| cores | 2 | 64 |",
                           "| parts | table:seed-box, calibration | table:seed-bowl |",
                           "| command | `ballbench report --shard 1/2 --no-bench` | `ballbench report --shard 2/2 --no-bench` |",
                           "**Left out of this report**"})
    EXPECT_NE(md.find(want), std::string::npos) << want << "\n" << md;
  // Said once, though both shards left it out.
  const std::string line = "- the scaling and harness overhead sections: --no-bench\n";
  EXPECT_EQ(md.find(line), md.rfind(line)) << md;
}

}  // namespace
}  // namespace ballbench

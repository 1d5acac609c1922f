// What is declared once: a run's status and its text (core/run_status.h), and each engine's
// settings table (core/engine_settings.h), from which reading, refusals, settings() and
// `ballbench list --settings` come.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli_runner.h"
#include "engine_settings.h"
#include "input_error.h"
#include "registry.h"
#include "result.h"
#include "run_status.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

TEST(RunStatusText, EveryStatusReadsBackFromItsTextAndTimedOutKeepsItsSpace) {
  for (RunStatus s : {RunStatus::ok, RunStatus::diverged, RunStatus::failed, RunStatus::unsupported,
                      RunStatus::interrupted, RunStatus::crashed, RunStatus::timed_out})
    EXPECT_EQ(run_status_from_text(run_status_text(s)), s) << run_status_text(s);
  EXPECT_STREQ(run_status_text(RunStatus::timed_out), "timed out");
  EXPECT_THROW(run_status_from_text("timed_out"), InputError);
}

TEST(RunStatusText, DivergedIsDerivedFromTheStatusAndWrittenAsBefore) {
  Result r;
  r.status = RunStatus::diverged, r.diverged_step = 7;
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["status"], "diverged");
  EXPECT_EQ(j["diverged"], true);
  EXPECT_EQ(j["diverged_step"], 7);
  const Result back = result_from_json(j);
  EXPECT_TRUE(back.diverged());
  EXPECT_EQ(back.diverged_step, 7);
  r.status = RunStatus::timed_out;
  EXPECT_EQ(to_json(r)["status"], "timed out");
  EXPECT_EQ(to_json(r)["diverged"], false);
  EXPECT_EQ(result_from_json(to_json(r)).status, RunStatus::timed_out);
}

struct Knobs {
  enum class Mode { fast, exact } mode = Mode::fast;
  int sweeps = 4;
  double gap = 0.5;
  bool flag = false;
};

const SettingsTable<Knobs>& knobs_table() {
  using S = Knobs;
  static const SettingsTable<S> table(
      "toy", {setting("sweeps", &S::sweeps, at_least(1), "count", "sweeps per step"),
              setting("gap", &S::gap, above(0, "m"), "m", "gap that counts as touching"),
              setting("flag", &S::flag, any_value, "", "a flag"),
              choice("mode", &S::mode, {{S::Mode::fast, "fast"}, {S::Mode::exact, "exact"}}, "how")});
  return table;
}

std::string refusal(const nlohmann::json& overrides) {
  Knobs k;
  try {
    knobs_table().read(overrides, k);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SettingsTable, ReadsWritesAndRefusesFromOneRowPerSetting) {
  Knobs k;
  knobs_table().read({{"sweeps", 9}, {"mode", "exact"}, {"flag", true}}, k);
  EXPECT_EQ(k.sweeps, 9);
  EXPECT_EQ(k.mode, Knobs::Mode::exact);
  EXPECT_TRUE(k.flag);
  EXPECT_EQ(knobs_table().json(k),
            (nlohmann::json{{"sweeps", 9}, {"gap", 0.5}, {"flag", true}, {"mode", "exact"}}));
  EXPECT_EQ(refusal({{"sweeps", 0}}), "settings.toy.sweeps: must be >= 1");
  EXPECT_EQ(refusal({{"gap", 0.0}}), "settings.toy.gap: must be > 0 (m)");
  EXPECT_EQ(refusal({{"mode", "slow"}}), "settings.toy.mode: 'slow' is not one of: fast, exact");
  EXPECT_NE(refusal({{"sweep", 2}}).find("settings.toy.sweep: unknown setting, did you mean 'sweeps'?"),
            std::string::npos);
  const auto rows = knobs_table().describe();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].name, "sweeps");
  EXPECT_EQ(rows[0].default_value, 4);
  EXPECT_EQ(rows[0].range, ">= 1");
  EXPECT_EQ(rows[3].range, "one of: fast, exact");
}

TEST(SettingsTable, ListSettingsPrintsAnEnginesRows) {
  const auto o = testing::run_cli("list --settings home");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("substeps"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("one of: auto, soft, events"), std::string::npos) << o.out;
}

// An engine's settings() holds its rows' keys, and beside them only what is not a setting.
TEST(SettingsTable, EachEnginesSettingsHoldItsRowsKeys) {
  const Scene scene = load_scene("seed-box");
  for (const char* name : {"home", "exact", "home-seed", "box2d", "chipmunk", "ode", "bullet"}) {
    const EngineEntry& e = find_engine(name);
    const nlohmann::json j = e.create(scene, e.info.profiles.front(), nlohmann::json::object())->settings();
    ASSERT_FALSE(e.info.settings.empty()) << name;
    size_t rows = 0;
    for (const SettingInfo& s : e.info.settings) rows += j.contains(s.name);
    EXPECT_EQ(rows, e.info.settings.size()) << name;
    for (const auto& [key, value] : j.items()) {
      const bool row = std::any_of(e.info.settings.begin(), e.info.settings.end(),
                                   [&](const SettingInfo& s) { return s.name == key; });
      EXPECT_TRUE(row || key == "derived" || key == "compile_time") << name << ": " << key;
    }
  }
}

}  // namespace
}  // namespace ballbench

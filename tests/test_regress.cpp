// `ballbench regress` fails, naming the metric, when the solvers no longer give the baseline: here
// a baseline made by this build is perturbed on purpose (one number changed in a copy), and a
// solver setting is changed with --set. The committed baseline itself is checked by the ctest
// `regress` (so these tests stay meaningful while a solver changes and its baseline is stale).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace {

using ballbench::testing::expect_one_line_error;
using ballbench::testing::Scratch;
using ballbench::testing::slurp;

using Outcome = ballbench::testing::CliOutcome;

Outcome regress(const std::string& args) { return ballbench::testing::run_cli("regress " + args); }

// A baseline from this build, made once for the tests below and removed when the process ends.
const std::string& fresh_baseline_path() {
  struct Baseline {
    std::string path;
    ~Baseline() {
      std::error_code ec;
      std::filesystem::remove(path, ec);
    }
  };
  static const Baseline baseline = [] {
    const std::string p =
        (std::filesystem::temp_directory_path() / ("bb_fresh_baseline." + std::to_string(::getpid()) + ".json")).string();
    std::filesystem::remove(p);
    const Outcome o = regress("--update --baseline " + p);
    if (o.status != 0) throw std::runtime_error("regress --update failed: " + o.err);
    return Baseline{p};
  }();
  return baseline.path;
}

nlohmann::json fresh_baseline() {
  std::ifstream in(fresh_baseline_path());
  return nlohmann::json::parse(in);
}

nlohmann::json& find_run(nlohmann::json& baseline, const std::string& scene, const std::string& engine) {
  for (auto& r : baseline["runs"])
    if (r["scene"] == scene && r["engine"] == engine) return r;
  throw std::runtime_error("no run " + scene + " " + engine + " in the baseline");
}

// One test, so the baseline it compares with is made once (three regress runs in all: they take
// a while under the sanitizers).
TEST(Regress, FailsNamingWhatChanged) {
  nlohmann::json baseline = fresh_baseline();

  // A perturbed copy of the baseline: one number moved by 1e-6 relative, a thousand times its
  // tolerance. Exactly that difference is reported: the rest of this build's baseline matches.
  {
    nlohmann::json copy = baseline;
    nlohmann::json& run = find_run(copy, "seed-bowl", "home");
    const double now = run["metrics"]["energy.final"].get<double>();
    const double perturbed = now * (1 + 1e-6);
    run["metrics"]["energy.final"] = perturbed;
    const std::string path =
        (std::filesystem::temp_directory_path() / ("bb_perturbed_baseline." + std::to_string(::getpid()) + ".json")).string();
    std::ofstream(path) << copy.dump(2);
    const Outcome o = regress("--baseline " + path);
    EXPECT_EQ(o.status, 1) << o.out << o.err;
    const std::string line = "regressed: seed-bowl home energy.final: baseline " + nlohmann::json(perturbed).dump() +
                             ", now " + nlohmann::json(now).dump() + " (tolerance: rel 1e-09, abs 1e-12)\n";
    EXPECT_NE(o.out.find(line), std::string::npos) << "expected: " << line << "got:\n" << o.out;
    EXPECT_EQ(o.out.find("regressed:"), o.out.rfind("regressed:")) << "more than that one difference:\n" << o.out;
    std::filesystem::remove(path);
  }

  // A solver constant changed (through --set, as a changed default would): named by the setting.
  {
    const auto& settings = find_run(baseline, "seed-bowl", "home")["settings"];
    ASSERT_TRUE(settings.contains("contact_iterations"));
    const int was = settings["contact_iterations"].get<int>();
    const Outcome o =
        regress("--baseline " + fresh_baseline_path() + " --set home.contact_iterations=" + std::to_string(was + 1));
    EXPECT_EQ(o.status, 1) << o.out << o.err;
    EXPECT_NE(o.out.find("seed-bowl home settings.contact_iterations: baseline " + std::to_string(was) + ", now " +
                         std::to_string(was + 1)),
              std::string::npos)
        << o.out;
  }
}

TEST(Regress, UpdateWithASettingIsContradictory) {
  const Outcome o = regress("--update --set home.contact_iterations=3 --baseline /tmp/bb_never.json");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("excludes"), std::string::npos) << o.err;
  EXPECT_FALSE(std::filesystem::exists("/tmp/bb_never.json"));
}

TEST(Regress, AMissingBaselineIsOneLine) {
  const Outcome o = regress("--baseline /nonexistent/baseline.json");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("/nonexistent/baseline.json: cannot read the baseline"), std::string::npos) << o.err;
  EXPECT_EQ(o.err.find('\n'), o.err.size() - 1) << o.err;
  // A folder, and an --update that could not be written, are one line before anything runs.
  const std::string folder = std::filesystem::temp_directory_path().string();
  for (const std::string& args : {"--baseline " + folder, std::string("--update --baseline /proc/bb_baseline.json")}) {
    const Outcome bad = regress(args);
    EXPECT_EQ(bad.status, 2) << args << ": " << bad.err;
    EXPECT_EQ(bad.err.find('\n'), bad.err.size() - 1) << args << ": " << bad.err;
    EXPECT_EQ(bad.err.find("regress: ran"), std::string::npos) << args << ": " << bad.err;
  }
}

TEST(Regress, ABaselineThatIsNotOneIsOneLine) {
  const std::string path = (std::filesystem::temp_directory_path() / "bb_bad_baseline.json").string();
  std::ofstream(path) << "{\"runs\": 3}";
  const Outcome o = regress("--baseline " + path);
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("not a regress baseline"), std::string::npos) << o.err;
}

// A baseline the comparison would read wrongly is refused before anything runs: a metric the suite
// does not compute (never compared), a run listed twice (compared once).
TEST(Regress, ABaselineWithAnUncomputedMetricOrARunTwiceIsRefused) {
  const auto dir = std::filesystem::temp_directory_path();
  nlohmann::json unknown = fresh_baseline();
  unknown["runs"][0]["metrics"]["energy.finale"] = 1.0;
  const std::string p1 = (dir / "bb_baseline_unknown.json").string();
  std::ofstream(p1) << unknown.dump();
  const Outcome o1 = regress("--baseline " + p1);
  EXPECT_EQ(o1.status, 2);
  EXPECT_NE(o1.err.find("metric 'energy.finale' is not one the suite computes"), std::string::npos) << o1.err;
  EXPECT_NE(o1.err.find("energy.final"), std::string::npos) << o1.err;  // the suggestion
  EXPECT_EQ(o1.err.find("regress: ran"), std::string::npos) << "ran before refusing: " << o1.err;
  nlohmann::json twice = fresh_baseline();
  twice["runs"].push_back(twice["runs"][0]);
  const std::string p2 = (dir / "bb_baseline_twice.json").string();
  std::ofstream(p2) << twice.dump();
  const Outcome o2 = regress("--baseline " + p2);
  EXPECT_EQ(o2.status, 2);
  EXPECT_NE(o2.err.find("is listed twice"), std::string::npos) << o2.err;
  std::filesystem::remove(p1), std::filesystem::remove(p2);
}

// A setting the engine does not have (or refuses) would fail every run, each a "regressed" line
// that never names it: refused before anything runs, naming the key and the engine's settings.
TEST(Regress, AnUnknownSettingIsOneLineBeforeAnyRun) {
  const Outcome o = regress("--set home.nosuch=4");
  expect_one_line_error(o, "settings.home.nosuch: unknown setting (known: contact_iterations, ");
  EXPECT_EQ(o.out.find("regressed"), std::string::npos) << o.out;
  expect_one_line_error(regress("--set home.contact_iteration=4"),
                        "settings.home.contact_iteration: unknown setting, did you mean 'contact_iterations'?");
  expect_one_line_error(regress("--set exact.nosuch=4"), "settings.exact.nosuch: unknown setting");
  expect_one_line_error(regress("--set home.substeps=0"), "settings.home.substeps: must be");
}

// The committed baseline, for the tests that change one field of a copy: every refusal comes before
// anything runs, so its numbers need not be this build's.
nlohmann::json committed_baseline() {
  std::ifstream in(std::string(BALLBENCH_REGRESS_DIR) + "/baseline.json");
  return nlohmann::json::parse(in);
}

// The committed baseline with `change` made, refused in one line holding `says`.
void expect_refused(const Scratch& s, const std::function<void(nlohmann::json&)>& change, const std::string& says) {
  nlohmann::json baseline = committed_baseline();
  change(baseline);
  const std::string path = s / "baseline.json";
  std::ofstream(path) << baseline.dump();
  const Outcome o = regress("--baseline " + path);
  expect_one_line_error(o, path + ": " + says);
  EXPECT_EQ(o.err.find("regress: ran"), std::string::npos) << "ran before refusing: " << o.err;
}

// The baseline's format is the one this build reads and --update writes.
TEST(Regress, ABaselineOfAnotherFormatIsRefused) {
  const Scratch s("bb_regress_format");
  EXPECT_EQ(committed_baseline().value("format_version", nlohmann::json()), 1);
  EXPECT_EQ(fresh_baseline().value("format_version", nlohmann::json()), 1);
  const std::string expected = ", expected 1 (the baseline format this ballbench reads and `regress --update` writes)";
  for (const auto& [value, got] : std::vector<std::pair<nlohmann::json, std::string>>{
           {99, "99"}, {"1", "\"1\""}, {1.5, "1.5"}, {nullptr, "null"}})
    expect_refused(s, [&](nlohmann::json& b) { b["format_version"] = value; }, "format_version: got " + got + expected);
  expect_refused(s, [](nlohmann::json& b) { b.erase("format_version"); }, "format_version: missing" + expected);
  // Another format is named before whatever else it holds.
  expect_refused(s, [](nlohmann::json& b) { b = {{"format_version", 2}, {"records", 3}}; }, "format_version: got 2");
}

// A field of another type than --update writes is named by its path before anything runs (else it
// would be compared as a difference, or read as a run of another name).
TEST(Regress, ABaselineFieldOfAnotherTypeIsNamed) {
  const Scratch s("bb_regress_types");
  const std::vector<std::pair<std::function<void(nlohmann::json&)>, std::string>> cases = {
      {[](nlohmann::json& b) { b["runs"][0]["metrics"]["energy.final"] = "3000"; },
       "runs[0].metrics.energy.final: expected a number, got a string"},
      {[](nlohmann::json& b) { b["runs"][2]["metrics"]["steps_done"] = {{"value", 3}}; },
       "runs[2].metrics.steps_done: expected a number, got an object"},
      {[](nlohmann::json& b) { b["runs"][1]["scene"] = 5; }, "runs[1].scene: expected a string, got a number"},
      {[](nlohmann::json& b) { b["runs"][1]["engine"] = nullptr; }, "runs[1].engine: expected a string, got null"},
      {[](nlohmann::json& b) { b["runs"][3]["settings"] = nlohmann::json::array(); },
       "runs[3].settings: expected an object, got an array"},
      {[](nlohmann::json& b) { b["runs"][0]["checksum"]["final"] = 7; },
       "runs[0].checksum.final: expected a string, got a number"},
      {[](nlohmann::json& b) { b["runs"][0]["metrics"] = "none"; }, "runs[0].metrics: expected an object, got a string"},
      {[](nlohmann::json& b) { b["tolerances"]["energy.final"]["rel"] = "1e-9"; },
       "tolerances.energy.final.rel: expected a number, got a string"},
      {[](nlohmann::json& b) { b["tolerances"]["energy.final"] = 0.1; },
       "tolerances.energy.final: expected an object, got a number"},
  };
  for (const auto& [change, says] : cases) expect_refused(s, change, says);
}

// A tolerance no plausible change could exceed passes anything: refused with its bound. rel: below
// 1 (at 1 a value may vanish or double and pass); abs: below the largest |value| of its metric in
// the baseline (or at most the catalog's own floor).
TEST(Regress, AToleranceThatCannotFailIsRefused) {
  const Scratch s("bb_regress_tolerances");
  const auto set = [](const std::string& key, const char* part, double value) {
    return [=](nlohmann::json& b) { b["tolerances"][key][part] = value; };
  };
  expect_refused(s, set("energy.final", "rel", 1e300),
                 "tolerances.energy.final.rel: 1e+300 cannot fail: at 1 or above a value may vanish or double and pass "
                 "(expected below 1)");
  expect_refused(s, set("energy.final", "rel", 1), "tolerances.energy.final.rel: 1 cannot fail");
  double largest = 0;
  const nlohmann::json committed = committed_baseline();
  for (const auto& run : committed["runs"])
    if (const nlohmann::json v = run["metrics"].value("energy.final", nlohmann::json()); v.is_number())
      largest = std::max(largest, std::abs(v.get<double>()));
  expect_refused(s, set("energy.final", "abs", 1e300),
                 fmt::format("tolerances.energy.final.abs: 1e+300 cannot fail: at or above the largest |energy.final| in "
                             "the baseline ({}), every run's value may vanish or double and pass (expected below {})",
                             largest, largest));
  expect_refused(s, set("energy.final", "abs", largest), "tolerances.energy.final.abs: ");
  // Never a value in any run (null throughout): only the default floor, 0 for an exact one.
  expect_refused(s, set("diverged_step", "abs", 1),
                 "tolerances.diverged_step.abs: 1: no run in the baseline has a |diverged_step| above the default 0 to "
                 "show it can fail (expected at most 0)");
  // Below the bounds they are taken: the suite runs (and compares; the committed baseline may be
  // another build's, so its verdict is not asserted here).
  nlohmann::json loose = committed_baseline();
  loose["tolerances"]["energy.final"] = {{"rel", 0.5}, {"abs", largest / 2}};
  std::ofstream(s / "loose.json") << loose.dump();
  const Outcome o = regress("--quiet --baseline " + s / "loose.json");
  EXPECT_NE(o.status, 2) << o.err;
  EXPECT_EQ(o.err.find("cannot fail"), std::string::npos) << o.err;
}

}  // namespace

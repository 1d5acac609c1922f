// `ballbench regress` fails, naming the metric, when the solvers no longer give the baseline: here
// a baseline made by this build is perturbed on purpose (one number changed in a copy), and a
// solver setting is changed with --set. The committed baseline itself is checked by the ctest
// `regress` (so these tests stay meaningful while a solver changes and its baseline is stale).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace {

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

}  // namespace

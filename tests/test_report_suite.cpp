// The report's suites are data (scenarios/suites/report.toml): the shipped file reads, every scene
// it names is a built-in scene, and a bad suites file is one line naming the file, line and field.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "input_error.h"
#include "report_suite.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

TEST(ReportSuite, TheShippedSuitesRead) {
  const ReportSuite quick = load_report_suite("quick"), full = load_report_suite("full");
  EXPECT_EQ(quick.name, "quick");
  EXPECT_FALSE(quick.scenes.empty());
  EXPECT_FALSE(quick.match_scenes.empty());
  EXPECT_FALSE(quick.bench_filters.empty());
  EXPECT_FALSE(quick.costly_engines);
  EXPECT_TRUE(full.costly_engines);
  // The complete evidence holds every part of the quick one.
  for (const auto& s : quick.scenes) EXPECT_NE(std::find(full.scenes.begin(), full.scenes.end(), s), full.scenes.end()) << s;
  for (const auto& s : quick.match_scenes)
    EXPECT_NE(std::find(full.match_scenes.begin(), full.match_scenes.end(), s), full.match_scenes.end()) << s;
}

class BadSuite : public ::testing::Test {
 protected:
  std::string error_of(const std::string& text, const std::string& suite = "quick") {
    const fs::path p = fs::temp_directory_path() / ("bb_suite." + std::to_string(::getpid()) + ".toml");
    std::ofstream(p) << text;
    try {
      load_report_suite(suite, p.string());
    } catch (const InputError& e) {
      fs::remove(p);
      return e.what();
    }
    fs::remove(p);
    return "";
  }
};

TEST_F(BadSuite, EachProblemIsOneLineNamingTheField) {
  EXPECT_NE(error_of("[quick]\nscenes = [\"seed-box\"]\nmatch_scenes = [\"seed-boxx\"]\n")
                .find(":3: quick.match_scenes[0]: 'seed-boxx' is not a built-in scene, did you mean 'seed-box'?"),
            std::string::npos);
  EXPECT_NE(error_of("[quick]\nscenez = []\n").find(":2: quick.scenez: unknown key"), std::string::npos);
  EXPECT_NE(error_of("[quick]\nmatch_budget = -1\n").find("quick.match_budget: must be above 0, got -1"),
            std::string::npos);
  EXPECT_NE(error_of("[quick]\nscenes = [\"pile\"]\nunreferenced = [\"seed-box\"]\n")
                .find("quick.unreferenced: 'seed-box' is not one of the suite's scenes"),
            std::string::npos);
  EXPECT_NE(error_of("[quick]\nscenes = \"seed-box\"\n").find("quick.scenes: expected an array of strings, got a string"),
            std::string::npos);
  EXPECT_NE(error_of("[quick]\n", "nightly").find("no suite [nightly] (suites: quick)"), std::string::npos);
  EXPECT_NE(error_of("[quick\n").find(".toml:1: "), std::string::npos);
}

}  // namespace
}  // namespace ballbench

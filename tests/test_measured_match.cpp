// A search too costly for a suite (most of an hour at 10^4 balls), measured before and carried into
// the report (the suite's measured_matches): read against the suites file's folder and shown with its
// own date and build, apart from the report's (test_report_resume.cpp runs a report that carries one).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "data_file.h"
#include "input_error.h"
#include "report_suite.h"
#include "report_writer.h"
#include "summary_section.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

// A search of `scene` by `build`: ours meets the spec at dt for 1 000 ns, chipmunk at dt/8 for
// 20 000.
MatchResult search_of(const std::string& scene, int n, const std::string& build, const std::string& digest) {
  MatchResult m;
  m.scene = scene, m.scene_class = "pile", m.n = n, m.dt = 0.01, m.scene_digest = digest;
  m.use_case = "a pile at rest";
  m.spec[SpecTerm::overlap] = 0.01;
  m.budget_runs = 2000, m.ceiling = 60, m.ceiling_ns = 60000;
  m.context = {{"build", build}, {"date", "2026-12-07T16:16:26Z"}};
  MatchTry ours, theirs;
  ours.engine = "home", ours.profile = "default", ours.met = true, ours.cost_ns = 1000, ours.dt = 0.01;
  theirs.engine = "chipmunk", theirs.profile = "stock", theirs.met = true, theirs.cost_ns = 20000, theirs.halvings = 3;
  theirs.dt = 0.01 / 8;
  ours.figures = theirs.figures = {{"overlap", 0.005}};
  m.tries = {ours, theirs};
  MatchOutcome a, b;
  a.engine = "home", a.profile = "default", a.role = "ours", a.reached = true, a.found = 0, a.cost_ns = 1000;
  b.engine = "chipmunk", b.profile = "stock", b.role = "external", b.reached = true, b.found = 1, b.cost_ns = 20000;
  m.outcomes = {a, b};
  return m;
}

class MeasuredMatch : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / fmt::format("bb_measured.{}", ::getpid());
  void SetUp() override { fs::create_directories(dir / "suites"), fs::create_directories(dir / "measured"); }
  void TearDown() override { fs::remove_all(dir); }

  std::string write_search(const MatchResult& m, const std::string& name) {
    const std::string path = (dir / "measured" / name).string();
    write_match_files(m, path, path + ".csv");
    return path;
  }
  // The suite `[quick]` of a suites file in dir/suites with these lines.
  ReportSuite suite(const std::string& lines) {
    const fs::path p = dir / "suites" / "report.toml";
    std::ofstream(p) << "[quick]\n" << lines;
    return load_report_suite("quick", p.string());
  }
  std::string error_of(const std::string& lines) {
    try {
      suite(lines);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(MeasuredMatch, IsReadAgainstTheSuitesFilesFolderAndEachProblemIsOneLine) {
  write_search(search_of("pile", 500, "b1", "d"), "match-pile.json");
  const ReportSuite s = suite("measured_matches = [\"../measured/match-pile.json\"]\n");
  ASSERT_EQ(s.measured_matches.size(), 1u);
  EXPECT_EQ(s.measured_matches[0].scene, "pile");
  EXPECT_TRUE(fs::equivalent(s.measured_matches[0].path, dir / "measured" / "match-pile.json"));

  EXPECT_NE(error_of("measured_matches = [\"../measured/none.json\"]\n").find("quick.measured_matches[0]: "),
            std::string::npos);
  EXPECT_NE(error_of("match_scenes = [\"pile\"]\nmeasured_matches = [\"../measured/match-pile.json\"]\n")
                .find("the suite searches 'pile' itself (match_scenes)"),
            std::string::npos);
  EXPECT_NE(error_of("measured_matches = [\"../measured/match-pile.json\", \"../measured/match-pile.json\"]\n")
                .find("quick.measured_matches[1]: ") ,
            std::string::npos);
  MatchResult cut = search_of("pile", 500, "b1", "d");
  cut.interrupted = "SIGINT";
  write_search(cut, "cut.json");
  EXPECT_NE(error_of("measured_matches = [\"../measured/cut.json\"]\n").find("interrupted by SIGINT; carry a whole search"),
            std::string::npos);
  write_search(search_of("no-such-scene", 500, "b1", "d"), "other.json");
  EXPECT_NE(error_of("measured_matches = [\"../measured/other.json\"]\n").find("'no-such-scene' is not a built-in scene"),
            std::string::npos);
}

// A results folder holds this report's build and a measured search of another: it reads, and the
// summary says which row is measured on its own, when and by which build, apart from the report's.
TEST_F(MeasuredMatch, IsShownWithItsOwnDateAndBuildApartFromTheReports) {
  const fs::path results = dir / "results";
  fs::create_directories(results);
  write_file_atomically((results / "run.json").string(), R"({"build": "this", "date": "2026-12-08"})", "run");
  write_match_files(search_of("pile", 500, "this", "p"), (results / "match-pile.json").string(),
                    (results / "match-pile.csv").string());
  MatchResult big = search_of("pile-10k-settled", 10000, "earlier", "q");
  big.use_case = "a pile of 10^4 balls at rest";
  write_match_files(big, (results / "measured-pile-10k-settled.json").string(), (dir / "big.csv").string());
  const ReportInputs in = read_report_inputs(results.string());
  ASSERT_EQ(in.matches.size(), 2u);
  EXPECT_TRUE(in.measured.contains("pile-10k-settled"));
  const std::string md = summary_section(in, {});
  EXPECT_NE(md.find("| [a pile of 10^4 balls at rest](#equal-accuracy-pile-10k-settled), 10000 balls, carried (below) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("The carried row, `pile-10k-settled` (measured 2026-12-07 by build earlier, each search's budget 2000 "
                    "runs of the scene at dt, ceiling 60x our cost), is a search too costly for this suite"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("by build this."), std::string::npos) << md;  // the report's own, alone
  EXPECT_NE(md.find("The other equal-accuracy searches at 10^4 balls are the full suite's"), std::string::npos) << md;

  // The same scene searched by this report too: two answers for one row, refused.
  write_match_files(big, (results / "match-pile-10k-settled.json").string(), (dir / "big.csv").string());
  EXPECT_THROW(read_report_inputs(results.string()), InputError);
}

}  // namespace
}  // namespace ballbench

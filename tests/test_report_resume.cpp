// `ballbench report` resumes where it stopped: a scene whose results file already holds every run
// the report makes of it (every engine x profile, the scene's full step count) is reused, not run
// again, unless --fresh. Results files are written whole (tmp + rename), so one that reads back is
// complete. The report runs the built-in scenes: here $BALLBENCH_SCENARIOS points them at tiny
// stand-ins, so a whole report takes a moment.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include "match_result.h"
#include "page_links.h"
#include "result.h"
#include "viewer_page.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

// The engines these reports compare: one of each role (the thesis's port, ours, the reference) and
// two external engines to rank. The reports' parts are what these tests check; each engine's rows
// have tests of their own, and the committed report runs every engine.
constexpr const char* kEngines = "home-seed,home,exact,box2d,chipmunk";

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// REPORT.md and every page of the report in `dir`, joined: what a reader can reach from it.
std::string report_text(const fs::path& dir) {
  std::string text = slurp(dir / "REPORT.md");
  std::vector<fs::path> pages;
  for (const char* folder : {"scenes", "pages"})
    if (fs::exists(dir / folder))
      for (const auto& e : fs::directory_iterator(dir / folder)) pages.push_back(e.path());
  std::sort(pages.begin(), pages.end());
  for (const auto& p : pages) text += slurp(p);
  return text;
}

// Every link of the report's pages that leads nowhere: a file that is not there, or an anchor that
// its page has no heading for.
std::vector<std::string> broken_links(const fs::path& dir) {
  std::vector<fs::path> pages = {dir / "REPORT.md"};
  for (const char* folder : {"scenes", "pages"})
    if (fs::exists(dir / folder))
      for (const auto& e : fs::directory_iterator(dir / folder)) pages.push_back(e.path());
  std::vector<std::string> broken;
  for (const fs::path& page : pages) {
    const std::string text = slurp(page);
    for (size_t open = text.find("]("); open != std::string::npos; open = text.find("](", open + 2)) {
      const std::string target = text.substr(open + 2, text.find(')', open + 2) - open - 2);
      if (target.find("://") != std::string::npos) continue;
      const size_t hash = target.find('#');
      const fs::path file = hash == 0 ? page : (page.parent_path() / target.substr(0, hash)).lexically_normal();
      // A link out of the report's folder is into the source tree (scenarios/README.md), not here.
      if (file.lexically_relative(dir.lexically_normal()).string().starts_with("..")) continue;
      if (!fs::exists(file)) {
        broken.push_back(page.filename().string() + ": " + target);
        continue;
      }
      if (hash == std::string::npos || file.extension() != ".md") continue;
      const auto anchors = page_anchors(slurp(file));
      if (std::find(anchors.begin(), anchors.end(), target.substr(hash + 1)) == anchors.end())
        broken.push_back(page.filename().string() + ": " + target);
    }
  }
  return broken;
}

class ReportResume : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("bb_report_resume." + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "scenarios");
    std::ofstream(root_ / "scenarios" / "seed-box.toml") << R"(name = "seed-box"
dt = 0.01
duration = 0.2
animated = true
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[random]
count = 3
radius = 0.1
vel_max = [2.0, 2.0]
)";
    std::ofstream(root_ / "scenarios" / "seed-bowl.toml") << R"(name = "seed-bowl"
dt = 0.01
duration = 0.2
gravity = [0.0, -10.0]
animated = true
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[random]
count = 3
radius = 0.1
)";
    // The friction scenes, tiny too: one ball sliding, one dropped spinning, three rough ones.
    std::ofstream(root_ / "scenarios" / "slide-to-roll.toml") << R"(name = "slide-to-roll"
dt = 0.01
duration = 0.2
gravity = [0.0, -9.81]
restitution = 0.0
friction = 0.5
[container]
min = [0.0, 0.0]
max = [2.0, 1.0]
[[ball]]
pos = [0.5, 0.1]
vel = [1.0, 0.0]
radius = 0.1
[metrics]
rolling = true
)";
    std::ofstream(root_ / "scenarios" / "spin-drop.toml") << R"(name = "spin-drop"
dt = 0.01
duration = 0.3
gravity = [0.0, -9.81]
restitution = 0.0
friction = 0.2
[container]
min = [0.0, 0.0]
max = [2.0, 1.0]
[[ball]]
pos = [0.5, 0.3]
vel = [1.0, 0.0]
spin = 10.0
radius = 0.1
[metrics]
rolling = true
)";
    // The heaps: four balls in a stack that falls over, with friction and without.
    for (const auto& [name, friction] : {std::pair{"rough-pile", "0.5"}, std::pair{"smooth-pile", "0.0"}})
      std::ofstream(root_ / "scenarios" / (std::string(name) + ".toml")) << "name = \"" << name << R"("
dt = 0.01
duration = 0.3
gravity = [0.0, -9.81]
restitution = 0.2
friction = )" << friction << R"(
ball = [{ pos = [0.0, 0.1], radius = 0.1 }, { pos = [0.21, 0.1], radius = 0.1 }, { pos = [0.1, 0.3], radius = 0.1 },
        { pos = [0.12, 0.5], radius = 0.1 }]
[container]
min = [-1.0, 0.0]
max = [1.0, 1.0]
[metrics]
angle_of_repose = true
)";
    std::ofstream(root_ / "scenarios" / "rough-box.toml") << R"(name = "rough-box"
dt = 0.01
duration = 0.2
gravity = [0.0, -10.0]
friction = 0.3
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[random]
count = 3
radius = 0.1
spin_max = 5.0
)";
    // The suites over the stand-ins: the shipped file's parts (test_report_suite.cpp reads that
    // one), with the equal-accuracy searches on the two seed scenes.
    fs::create_directories(root_ / "scenarios" / "suites");
    std::ofstream(root_ / "scenarios" / "suites" / "report.toml") << R"([quick]
scenes = ["seed-box", "seed-bowl", "slide-to-roll", "spin-drop", "rough-box", "rough-pile", "smooth-pile"]
unreferenced = ["rough-pile", "smooth-pile"]
seeds = 3
match_scenes = ["seed-box", "seed-bowl"]
match_budget = 100
sweep_scenes = ["seed-box"]
stress_scenes = ["seed-box"]
stress_levels = 5
timeout_s = 120

[full]
scenes = ["seed-box", "seed-bowl", "bullet", "newtons-cradle", "mass-ratio", "crowd", "gas", "pile", "slide-to-roll",
          "spin-drop", "rough-box", "rough-pile", "smooth-pile"]
unreferenced = ["rough-pile", "smooth-pile"]
seeds = 10
match_scenes = ["seed-box", "pile"]
match_budget = 100
sweep_scenes = ["seed-box", "seed-bowl"]
stress_scenes = ["seed-box", "seed-bowl"]
stress_levels = 6
timeout_s = 600
costly_engines = true
)";
  }
  void TearDown() override { fs::remove_all(root_); }

  // Runs `ballbench report --out OUT ARGS`; returns the exit status, stderr in err_.
  int report(const std::string& args = "") {
    return command(std::string("report --no-bench --engine ") + kEngines + " --out " + out().string() + " " + args);
  }
  // Runs `ballbench ARGS` on the stand-in scenes; returns the exit status, stderr in err_.
  // BALLBENCH_ENGINES empty: the built-in engines only, as each run of an engine in another process
  // starts that process (test_process_engine.cpp covers those).
  int command(const std::string& args) {
    const std::string cmd = "BALLBENCH_ENGINES= BALLBENCH_SCENARIOS=" + (root_ / "scenarios").string() + " " +
                            BALLBENCH_CLI + " " + args + " >/dev/null 2>" + (root_ / "err.txt").string();
    const int rc = std::system(cmd.c_str());
    err_ = slurp(root_ / "err.txt");
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
  }
  fs::path out() const { return root_ / "out"; }
  fs::path results(const char* scene) const { return out() / "results" / (std::string(scene) + ".json"); }
  bool reused(const char* scene) const { return err_.find("reusing " + results(scene).string()) != std::string::npos; }
  bool ran(const char* scene) const { return err_.find(std::string("ran ") + scene + "\n") != std::string::npos; }

  fs::path root_;
  std::string err_;
};

TEST_F(ReportResume, ReusesCompleteResultsAndRunsTheRest) {
  ASSERT_EQ(report(), 0) << err_;
  EXPECT_TRUE(ran("seed-box") && ran("seed-bowl")) << err_;
  ASSERT_TRUE(fs::exists(out() / "REPORT.md"));
  // The quick suite's other parts: a sweep and a stability frontier, each with its figure.
  const std::string md = report_text(out()), front = slurp(out() / "REPORT.md");
  EXPECT_EQ(broken_links(out()), std::vector<std::string>{});
  for (const char* want : {"## Work against precision: `seed-box`", "figures/seed-box-work-precision.png",
                           "## Stability frontier: `seed-box`", "figures/seed-box-frontier.png",
                           "## Restitution calibration", "| ball-wall 0.1 | ball-wall 1 | ball-wall 10 | ball-ball 0.1 |",
                           // the reference delivers what is asked, at every speed and on both contacts
                           "| exact | 0.500 | 0.500 | 0.500 | 0.500 | 0.500 | 0.500 |",
                           "| exact | 0.900 | 0.900 | 0.900 | 0.900 | 0.900 | 0.900 |",
                           // the seed scenes over three placements, with intervals
                           "Over 3 random placements", "| exact | 3 |",
                           // the friction section: rolling against the closed forms, engines without friction
                           // refusing with the reason, and both heaps' angles side by side
                           "# Friction", "### `slide-to-roll`: rolling against the closed form",
                           "### `spin-drop`: rolling against the closed form",
                           "| home-seed | unsupported: home-seed cannot run scene 'spin-drop'",
                           "| engine | `rough-pile` (deg) | `smooth-pile` (deg) |"})
    EXPECT_NE(md.find(want), std::string::npos) << want;
  EXPECT_TRUE(fs::exists(out() / "figures" / "seed-box-work-precision.png"));
  // The answer first, on its own page: the use cases, each linked to its scene's page, which holds
  // the equal-accuracy section with its front; every try's CSV beside.
  for (const char* want : {"| use case |", "](scenes/seed-box.md#equal-accuracy-seed-box), ",
                           "figures/fronts.png", "[Terms](pages/terms.md)"})
    EXPECT_NE(front.find(want), std::string::npos) << want;
  EXPECT_EQ(front.find("## Every engine"), std::string::npos) << "the scene tables are on the scenes' pages";
  for (const char* want : {"## Equal accuracy: `seed-box`", "## Equal accuracy: `seed-bowl`", "figures/seed-bowl-front.png"})
    EXPECT_NE(md.find(want), std::string::npos) << want;
  for (const char* file : {"figures/seed-box-front.png", "figures/fronts.png", "results/match-seed-bowl.csv"})
    EXPECT_TRUE(fs::exists(out() / file)) << file;
  // The seed scenes in motion: an animated GIF each (one graphic control block per frame), under 2 MB.
  for (const char* scene : {"seed-box", "seed-bowl"}) {
    const std::string gif = slurp(out() / "figures" / (std::string(scene) + "-animation.gif"));
    EXPECT_EQ(gif.rfind("GIF89a", 0), 0u) << scene;
    size_t frames = 0;
    for (size_t at = gif.find("\x21\xf9\x04"); at != std::string::npos; at = gif.find("\x21\xf9\x04", at + 1)) ++frames;
    EXPECT_GE(frames, 10u) << scene;
    EXPECT_LT(gif.size(), 2u << 20) << scene;
    EXPECT_NE(md.find("figures/" + std::string(scene) + "-animation.gif"), std::string::npos) << scene;
    // And in the viewer (tests/test_viewer.cpp loads one in a browser), linked under its table.
    const fs::path viewer = out() / "figures" / (std::string(scene) + "-viewer.html");
    ASSERT_TRUE(fs::exists(viewer)) << scene;
    EXPECT_LT(static_cast<double>(fs::file_size(viewer)), kViewerPageBytes) << scene;
    EXPECT_NE(slurp(viewer).find("\"scene\":\"" + std::string(scene) + "\""), std::string::npos) << scene;
    EXPECT_NE(md.find("**Trajectory viewer**: [figures/" + std::string(scene) + "-viewer.html](../figures/"), std::string::npos)
        << scene;
  }
  EXPECT_TRUE(fs::exists(out() / "results" / "sweep-seed-box.csv"));
  EXPECT_EQ(md.find("## Scaling"), std::string::npos);  // --no-bench, and the report says so
  EXPECT_NE(md.find("**Left out of this report**:\n\n- the scaling and harness overhead sections"), std::string::npos);

  // As if the report had stopped during seed-bowl: its file is not there yet.
  fs::remove(results("seed-bowl"));
  const std::string box_before = slurp(results("seed-box"));
  ASSERT_EQ(report(), 0) << err_;
  EXPECT_TRUE(reused("seed-box")) << err_;
  EXPECT_FALSE(ran("seed-box")) << err_;
  EXPECT_TRUE(ran("seed-bowl")) << err_;
  EXPECT_EQ(slurp(results("seed-box")), box_before);  // not rewritten

  // A file missing one run is incomplete: run again.
  auto runs = read_results_file(results("seed-bowl").string());
  runs.pop_back();
  write_results_file(results("seed-bowl").string(), runs);
  ASSERT_EQ(report(), 0) << err_;
  EXPECT_TRUE(reused("seed-box")) << err_;
  EXPECT_TRUE(ran("seed-bowl")) << err_;

  // --fresh runs everything.
  ASSERT_EQ(report("--fresh"), 0) << err_;
  EXPECT_TRUE(ran("seed-box") && ran("seed-bowl")) << err_;
  EXPECT_FALSE(reused("seed-box")) << err_;
}

TEST_F(ReportResume, FullRunsEveryPartOfTheCompleteEvidence) {
  // Tiny stand-ins for the full suite's other scenes.
  for (const char* name : {"bullet", "newtons-cradle", "mass-ratio", "crowd", "gas", "pile"})
    fs::copy_file(root_ / "scenarios" / "seed-box.toml", root_ / "scenarios" / (std::string(name) + ".toml"));
  for (const char* name : {"bullet", "newtons-cradle", "mass-ratio", "crowd", "gas", "pile"}) {
    std::string text = slurp(root_ / "scenarios" / (std::string(name) + ".toml"));
    text.replace(text.find("seed-box"), 8, name);
    text.erase(text.find("animated = true\n"), 16);  // only the thesis's scenes are animated
    std::ofstream(root_ / "scenarios" / (std::string(name) + ".toml")) << text;
  }
  // Two placements of each scene instead of the full suite's ten: the parts are what is checked.
  ASSERT_EQ(report("--full --seeds 2"), 0) << err_;
  const std::string md = report_text(out());
  EXPECT_TRUE(fs::exists(out() / "scenes" / "pile.md"));
  for (const char* want : {"# `pile`", "## Work against precision: `seed-bowl`", "## Stability frontier: `seed-bowl`",
                           "Over 2 random placements"})
    EXPECT_NE(md.find(want), std::string::npos) << want;
  EXPECT_NE(slurp(out() / "results" / "run.json").find("\"suite\": \"full\""), std::string::npos);
  // A quick report afresh leaves none of the full one's parts behind.
  ASSERT_EQ(report("--fresh"), 0) << err_;
  EXPECT_FALSE(fs::exists(results("pile")));
  EXPECT_FALSE(fs::exists(out() / "results" / "sweep-seed-bowl.json"));
  EXPECT_FALSE(fs::exists(out() / "scenes" / "pile.md")) << "nor its pages";
}

TEST_F(ReportResume, AResultsFileOfAnotherSceneIsNotReused) {
  ASSERT_EQ(report(), 0) << err_;
  // The scene changed since (more steps): its old results no longer describe it.
  std::string text = slurp(root_ / "scenarios" / "seed-box.toml");
  text.replace(text.find("duration = 0.2"), 14, "duration = 0.3");
  std::ofstream(root_ / "scenarios" / "seed-box.toml") << text;
  ASSERT_EQ(report(), 0) << err_;
  EXPECT_TRUE(ran("seed-box")) << err_;
  EXPECT_TRUE(reused("seed-bowl")) << err_;
  // Nor do results of another number of placements.
  ASSERT_EQ(report("--seeds 2"), 0) << err_;
  EXPECT_TRUE(ran("seed-box") && ran("seed-bowl")) << err_;
  // Nor results of the scene's other contents with the same steps and balls (another restitution):
  // its table and its search run again, the other scene's are reused.
  text = slurp(root_ / "scenarios" / "seed-box.toml");
  text.replace(text.find("dt = 0.01"), 9, "dt = 0.01\nrestitution = 0.9");
  std::ofstream(root_ / "scenarios" / "seed-box.toml") << text;
  ASSERT_EQ(report("--seeds 2"), 0) << err_;
  EXPECT_TRUE(ran("seed-box") && reused("seed-bowl")) << err_;
  const std::string match_box = (out() / "results" / "match-seed-box.json").string();
  EXPECT_NE(err_.find("not reusing " + match_box + ": made of other contents of the scene"), std::string::npos) << err_;
  // Nor parts made for another list of engines: a report of `home` alone ranks no other engine.
  ASSERT_EQ(command("report --no-bench --engine home,exact --seeds 2 --out " + out().string()), 0) << err_;
  EXPECT_TRUE(ran("seed-box") && ran("seed-bowl")) << err_;
  EXPECT_NE(err_.find("not reusing " + match_box + ": made for another list of engines"), std::string::npos) << err_;
  for (const auto& o : read_match_file(match_box).outcomes) EXPECT_TRUE(o.engine == "home" || o.engine == "exact") << o.engine;
}

// A search measured before (the suite's measured_matches) is carried into the report as it was,
// with its page and its own build, while its scene is the one it searched; a search of another
// content of the scene is refused, with the command that measures it again.
TEST_F(ReportResume, ASearchMeasuredBeforeIsCarriedWhileItsSceneIsTheSame) {
  const fs::path measured = root_ / "measured" / "match-rough-box.json";
  fs::create_directories(measured.parent_path());
  ASSERT_EQ(command("match --scene rough-box --engine home,chipmunk --budget 20 --max-halvings 2 --store '' --json " +
                    measured.string()),
            0)
      << err_;
  std::ofstream(root_ / "suites.toml") << R"([quick]
scenes = ["seed-box"]
measured_matches = ["measured/match-rough-box.json"]
)";
  const std::string args = "--suites " + (root_ / "suites.toml").string();
  ASSERT_EQ(report(args), 0) << err_;
  EXPECT_EQ(slurp(out() / "results" / "measured-rough-box.json"), slurp(measured));
  EXPECT_EQ(broken_links(out()), std::vector<std::string>{});
  EXPECT_NE(slurp(out() / "REPORT.md").find("(scenes/rough-box.md#equal-accuracy-rough-box), 3 balls, carried (below)"),
            std::string::npos)
      << slurp(out() / "REPORT.md");
  EXPECT_NE(slurp(out() / "scenes" / "rough-box.md").find("carried into this report as it was"), std::string::npos);

  std::string text = slurp(root_ / "scenarios" / "rough-box.toml");
  text.replace(text.find("duration = 0.2"), 14, "duration = 0.3");
  std::ofstream(root_ / "scenarios" / "rough-box.toml") << text;
  EXPECT_EQ(report(args), 2);
  EXPECT_NE(err_.find(measured.string() + ": searched another content of scene rough-box"), std::string::npos) << err_;
}

// A report run as two shards (on two machines, say), merged: every part's result file and a
// REPORT.md with every section of the quick suite; a shard alone renders nothing, and a merge with
// a shard missing is refused.
TEST_F(ReportResume, TwoShardsMergedMakeTheWholeReport) {
  const fs::path one = root_ / "shard1", two = root_ / "shard2", merged = root_ / "merged";
  for (const auto& [dir, which] : {std::pair{one, "1/2"}, std::pair{two, "2/2"}}) {
    ASSERT_EQ(command(std::string("report --quiet --no-bench --engine ") + kEngines + " --seeds 2 --out " + dir.string() +
                      " --shard " + which),
              0)
        << err_;
    EXPECT_EQ(err_, "") << which;  // --quiet: no progress
    EXPECT_FALSE(fs::exists(dir / "REPORT.md")) << which;
  }
  EXPECT_EQ(command("merge --out " + merged.string() + " " + one.string()), 2);
  EXPECT_NE(err_.find("merge: shard 2/2 is missing"), std::string::npos) << err_;
  ASSERT_EQ(command("merge --out " + merged.string() + " " + two.string() + " " + one.string()), 0) << err_;
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(merged / "results")) files.insert(e.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"calibration.json", "conform.json", "run.json", "seed-box.json", "seed-bowl.json",
                                          "slide-to-roll.json", "spin-drop.json", "rough-box.json", "rough-pile.json",
                                          "smooth-pile.json", "stress-seed-box.json",
                                          "sweep-seed-box.csv", "sweep-seed-box.json", "match-seed-box.json",
                                          "match-seed-box.csv", "match-seed-bowl.json", "match-seed-bowl.csv"}));
  const std::string md = report_text(merged);
  EXPECT_EQ(broken_links(merged), std::vector<std::string>{});
  for (const char* want : {"# `seed-box`", "# `seed-bowl`", "## Work against precision: `seed-box`",
                           "## Stability frontier: `seed-box`", "## Restitution calibration"})
    EXPECT_NE(md.find(want), std::string::npos) << want;
  EXPECT_NE(slurp(merged / "results" / "run.json").find("\"shards\""), std::string::npos);
  // The merge and each shard's machine, parts and command, and what every shard left out.
  for (const char* want : {"This report: `", " merge --out ", "| | shard 2/2 | shard 1/2 |", "| cpu |", "| parts | ",
                           "--shard 2/2` |", "**Left out of this report**"})
    EXPECT_NE(md.find(want), std::string::npos) << want;
}

}  // namespace
}  // namespace ballbench

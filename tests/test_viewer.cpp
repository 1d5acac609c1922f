// Events recorded where and when, and the trajectory viewer: its page size, `ballbench view`'s
// errors, and the page loaded in headless Chromium (skipped where Chromium is absent).
#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "input_error.h"
#include "metrics/meter_set.h"
#include "palette.h"
#include "registry.h"
#include "result.h"
#include "run_engines.h"
#include "runner.h"
#include "scene_loader.h"
#include "viewer_page.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;
using testing::slurp;

// A folder of its own per test process, removed at the end.
struct TempDir {
  fs::path path = fs::temp_directory_path() / ("ballbench_viewer." + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

TEST(Events, RoundTripThroughTheResultsJson) {
  Result r;
  r.engine = "e", r.engine_version = "1", r.scene = "s";
  r.events = {{EventKind::TunnelWall, 3, 0.03, 7, -1, 5.0, 1.25},
              {EventKind::TunnelPair, 4, 0.04, 1, 2, -0.5, 0.125},
              {EventKind::StickWall, 10, 0.1, 0, -1, 4.9, -3.0},
              {EventKind::StickPair, 11, 0.11, 3, 9, 0.0, 0.0}};
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j.at("events").at(1).at("kind"), "tunnel-pair");
  EXPECT_FALSE(j.at("events").at(0).contains("j"));  // a wall event has no partner
  // Through text, as a results file holds it.
  const Result back = result_from_json(nlohmann::json::parse(j.dump()));
  EXPECT_EQ(back.events, r.events);
  nlohmann::json bad = j;
  bad["events"][0]["kind"] = "tunnel-floor";
  EXPECT_THROW(result_from_json(bad), InputError);
}

// A ball fast enough to cross the right wall (x = 5) in one step, and two balls that swap places
// in one step, under an engine without continuous collision detection (Chipmunk2D): each is
// caught in the step it happens, where it happens.
TEST(Events, AFastBallThroughAWallAndAPairPassingThroughAreRecordedWhereAndWhen) {
  const Scene scene = parse_scene(R"(
name = "fast"
dt = 0.01
duration = 0.03
gravity = [0.0, 0.0]
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [4.0, 1.0]
vel = [130.0, 0.0]
radius = 0.25
mass = 1.0
[[ball]]
pos = [-0.6, -2.0]
vel = [120.0, 0.0]
radius = 0.25
mass = 1.0
[[ball]]
pos = [0.6, -2.0]
vel = [-120.0, 0.0]
radius = 0.25
mass = 1.0
)",
                                  "fast.toml");
  const Result r = run_engine(scene, find_engine("chipmunk"), {});
  ASSERT_EQ(r.metrics.count(Metric::tunnelling_wall), 1) << r.status << " " << r.error;
  ASSERT_EQ(r.metrics.count(Metric::tunnelling_pair), 1);
  ASSERT_EQ(r.events.size(), 2u);
  const Event& wall = r.events[0];
  EXPECT_EQ(wall.kind, EventKind::TunnelWall);
  EXPECT_EQ(wall.step, 1);
  EXPECT_DOUBLE_EQ(wall.t, 0.01);
  EXPECT_EQ(wall.i, 0);
  EXPECT_NEAR(wall.x, 5.0, 1e-9);  // where its straight step crosses the wall
  EXPECT_NEAR(wall.y, 1.0, 1e-9);
  const Event& pair = r.events[1];
  EXPECT_EQ(pair.kind, EventKind::TunnelPair);
  EXPECT_EQ(pair.step, 1);
  EXPECT_EQ(pair.i, 1);
  EXPECT_EQ(pair.j, 2);
  EXPECT_NEAR(pair.x, 0.0, 1e-9);  // they met halfway
  EXPECT_NEAR(pair.y, -2.0, 1e-9);
}

State two_balls_at(double x0, double x1) {
  State s;
  s.resize(2);
  s.pos << x0, 0.0, x1, 0.0;
  s.vel.setZero();
  return s;
}

TEST(Events, AStuckPairIsRecordedWhenCountedAndOnlyTheFirstAreKept) {
  const Scene scene = parse_scene(R"(
dt = 0.01
duration = 1.0
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[[ball]]
pos = [-2.0, 0.0]
radius = 0.25
[[ball]]
pos = [2.0, 0.0]
radius = 0.25
)",
                                  "two.toml");
  MetricsConfig config;
  MeterSet m(scene, config);
  // Overlapping by 0.1 m (20% of the radius sum), not moving: counted at the sample after
  // stuck_samples of them (the first sample is the initial state, step 0).
  State s = two_balls_at(-0.2, 0.2);
  m.sample(s);
  for (int k = 1; k <= config.stuck_samples + 2; ++k) {
    State next = s;
    next.t = k * 0.01;
    m.motion(s, next);
    m.sample(next);
    s = next;
  }
  ASSERT_EQ(m.values().count(Metric::sticking_pair), 1);
  ASSERT_EQ(m.events().size(), 1u);
  EXPECT_EQ(m.events()[0].kind, EventKind::StickPair);
  EXPECT_EQ(m.events()[0].step, config.stuck_samples);
  EXPECT_DOUBLE_EQ(m.events()[0].x, 0.0);
  EXPECT_EQ(m.events()[0].i, 0);
  EXPECT_EQ(m.events()[0].j, 1);

  // A pair swapping places every step: every pass counts, the first kEventsKept are recorded.
  MeterSet swaps(scene, config);
  State a = two_balls_at(-1.0, 1.0);
  const long steps = static_cast<long>(kEventsKept) + 50;
  for (long k = 1; k <= steps; ++k) {
    State b = two_balls_at(k % 2 ? 1.0 : -1.0, k % 2 ? -1.0 : 1.0);
    b.t = k * 0.01;
    swaps.motion(a, b);
    a = b;
  }
  EXPECT_EQ(swaps.values().count(Metric::tunnelling_pair), steps);  // the count stays the total
  ASSERT_EQ(swaps.events().size(), kEventsKept);
  EXPECT_EQ(swaps.events().back().step, static_cast<long>(kEventsKept));
}

// The report's seed scenes take as many frames as a page of every run holds: a page of every
// engine and profile on the 72-ball bowl over its full 3000 steps, each run with as many events as
// are kept, stays within the bound. The frames are a real run's (the runner's spacing).
TEST(ViewerPage, AReportPageOfEveryRunStaysUnderItsBound) {
  const Scene scene = load_scene("seed-bowl");
  const int runs = static_cast<int>(cli::run_count(parse_engine_list("all"), "all"));
  RunOptions options;
  options.frames = viewer_frames(scene, runs);
  options.reference = nullptr;
  Result run = run_engine(scene, find_engine("home"), options);
  ASSERT_EQ(run.status, RunStatus::ok) << run.error;
  ASSERT_GE(run.series.frames.size(), 80u);  // the GIF's frames and more
  // The longest numbers a box of [-5, 5]^2 puts on the page, in every event's place.
  for (auto& frame : run.series.frames)
    for (auto& p : frame) p = {-5.4999, -5.4999};
  for (size_t k = 0; k < kEventsKept; ++k)
    run.events.push_back({EventKind::TunnelPair, 2999, 29.99, 71, 70, -4.9999, -4.9999});
  std::vector<Result> all(runs, run);
  std::vector<const Result*> shown;
  for (int k = 0; k < runs; ++k) {
    all[k].engine = "engine-" + std::to_string(k);
    shown.push_back(&all[k]);
  }
  const std::string page = viewer_page(shown);
  EXPECT_LT(static_cast<double>(page.size()), kViewerPageBytes) << runs << " runs, " << run.series.frames.size() << " frames";
  EXPECT_GT(static_cast<double>(page.size()), 0.5 * kViewerPageBytes) << "the budget is there to be used";
}

TEST(ViewerPage, EscapesWhatWouldEndItsScriptElement) {
  Result r;
  r.scene = "s", r.n = 1, r.engine = "e", r.status = RunStatus::failed, r.error = "</script><b>";
  r.series.frames = {{{0.0, 0.0}}};
  r.series.frame_t = {0.0};
  const std::string page = viewer_page({&r});
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  EXPECT_NE(page.find("\\u003c/script>\\u003cb>"), std::string::npos);
}

// The first line of stderr, and that it is the only one.
std::string one_line(const std::string& err) {
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  return err.substr(0, err.find('\n'));
}

TEST(ViewCli, BadInputIsOneLineAndAnError) {
  TempDir dir;
  const std::string d = dir.path.string();
  auto missing = run_cli("view " + d + "/none.json");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(one_line(missing.err).find("none.json"), std::string::npos);
  std::ofstream(d + "/text.json") << "not json";
  auto text = run_cli("view " + d + "/text.json");
  EXPECT_EQ(text.status, 2);
  EXPECT_NE(one_line(text.err).find("text.json"), std::string::npos);
  std::ofstream(d + "/other.json") << R"({"hello": 1})";
  auto other = run_cli("view " + d + "/other.json");
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(one_line(other.err).find("other.json"), std::string::npos);

  // Without --frames: what to do instead.
  ASSERT_EQ(run_cli("run --scene seed-box --engine home --steps 20 --no-reference --quiet --json " + d + "/plain.json").status, 0);
  auto plain = run_cli("view " + d + "/plain.json");
  EXPECT_EQ(plain.status, 2);
  EXPECT_NE(one_line(plain.err).find("--frames"), std::string::npos) << plain.err;

  // Runs of two scenes in one file.
  ASSERT_EQ(run_cli("run --scene seed-bowl --engine home --steps 20 --frames 5 --no-reference --quiet --json " + d +
                    "/bowl.json").status, 0);
  auto box = read_results_file(d + "/plain.json"), bowl = read_results_file(d + "/bowl.json");
  box.insert(box.end(), bowl.begin(), bowl.end());
  write_results_file(d + "/mixed.json", box);
  auto mixed = run_cli("view " + d + "/mixed.json");
  EXPECT_EQ(mixed.status, 2);
  EXPECT_NE(one_line(mixed.err).find("different scenes"), std::string::npos) << mixed.err;
  EXPECT_FALSE(fs::exists(d + "/mixed.html"));
}

// Where Debian's chromium is, or "".
std::string chromium() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (::access(p, X_OK) == 0) return p;
  return "";
}

// The page's hidden <pre id="state"> after Chromium loaded `url` headless and ran its script.
nlohmann::json page_state(const std::string& browser, const std::string& url, const fs::path& dir) {
  const fs::path dom = dir / "dom.html";
  // Its own profile folder: ctest runs tests in parallel, and a profile is locked by its browser.
  const std::string cmd = "timeout 60 " + browser + " --headless --no-sandbox --disable-gpu --user-data-dir=" +
                          (dir / "profile").string() + " --virtual-time-budget=10000 --dump-dom '" + url + "' >" +
                          dom.string() + " 2>/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::string html = slurp(dom.string());
  // Hidden: a reader never sees it.
  const std::string open = "<pre id=\"state\" hidden=\"\">";
  const size_t at = html.find(open), end = html.find("</pre>", at);
  if (at == std::string::npos || end == std::string::npos) {
    ADD_FAILURE() << "no hidden state element in what Chromium drew:\n" << html.substr(0, 2000);
    return {};
  }
  std::string text = html.substr(at + open.size(), end - at - open.size());
  // Text content as serialised HTML: the three entities it may hold.
  for (const auto& [entity, c] : {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
    for (size_t p = text.find(entity); p != std::string::npos; p = text.find(entity, p + 1)) text.replace(p, std::string(entity).size(), c);
  return nlohmann::json::parse(text);
}

// Chromium driven through its DevTools pipe (--remote-debugging-pipe: commands in on descriptor 3,
// replies and events out on 4, each a JSON text ended by a NUL), for what a URL fragment cannot do:
// press a key, as a person does, with the browser's own handling of it.
class DevTools {
 public:
  DevTools(const std::string& browser, const fs::path& profile) {
    int to[2], from[2];
    if (::pipe(to) != 0 || ::pipe(from) != 0) return;
    const std::string profile_arg = "--user-data-dir=" + profile.string();
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(to[0], 3), ::dup2(from[1], 4);
      for (int fd : {to[0], to[1], from[0], from[1]})
        if (fd > 4) ::close(fd);
      if (std::FILE* null = std::freopen("/dev/null", "w", stderr)) (void)null;
      ::execl(browser.c_str(), browser.c_str(), "--headless", "--no-sandbox", "--disable-gpu", profile_arg.c_str(),
              "--remote-debugging-pipe", "about:blank", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(to[0]), ::close(from[1]);
    out_ = to[1], in_ = from[0];
  }
  ~DevTools() {
    if (out_ >= 0) ::close(out_);
    if (in_ >= 0) ::close(in_);
    if (pid_ > 0) ::kill(pid_, SIGTERM), ::waitpid(pid_, nullptr, 0);
  }

  // The result of `method`, or null (and a test failure) on an error or after 30 s of silence.
  nlohmann::json call(const std::string& method, const nlohmann::json& params, const std::string& session = "") {
    nlohmann::json message = {{"id", ++id_}, {"method", method}, {"params", params}};
    if (!session.empty()) message["sessionId"] = session;
    const std::string text = message.dump() + '\0';
    if (out_ < 0 || ::write(out_, text.data(), text.size()) != static_cast<ssize_t>(text.size())) {
      ADD_FAILURE() << "cannot write to Chromium's pipe";
      return {};
    }
    for (;;) {
      nlohmann::json reply = next();
      if (reply.is_null()) return {};
      if (reply.value("id", -1) != id_) {
        events_.push_back(std::move(reply));
        continue;
      }
      if (reply.contains("error")) {
        ADD_FAILURE() << method << ": " << reply.at("error").dump();
        return {};
      }
      return reply.at("result");
    }
  }

  // Waits for the event `method` (one that came while waiting for a reply counts).
  bool wait_for(const std::string& method) {
    for (;;) {
      for (auto e = events_.begin(); e != events_.end(); ++e)
        if (e->value("method", "") == method) return events_.erase(e), true;
      nlohmann::json event = next();
      if (event.is_null()) return false;
      events_.push_back(std::move(event));
    }
  }

 private:
  nlohmann::json next() {
    for (;;) {
      if (const size_t end = buffer_.find('\0'); end != std::string::npos) {
        const std::string text = buffer_.substr(0, end);
        buffer_.erase(0, end + 1);
        return nlohmann::json::parse(text);
      }
      pollfd p{in_, POLLIN, 0};
      char chunk[65536];
      const ssize_t got = in_ >= 0 && ::poll(&p, 1, 30000) == 1 ? ::read(in_, chunk, sizeof chunk) : -1;
      if (got <= 0) {
        ADD_FAILURE() << "Chromium's pipe closed or stayed silent for 30 s";
        return {};
      }
      buffer_.append(chunk, static_cast<size_t>(got));
    }
  }

  pid_t pid_ = -1;
  int out_ = -1, in_ = -1, id_ = 0;
  std::string buffer_;
  std::deque<nlohmann::json> events_;
};

// The colour viewer.html draws the inside of the box with.
const std::vector<int> kInside = {0xff, 0xff, 0xff};

// "#rrggbb" as {r, g, b}.
std::vector<int> rgb(const std::string& colour) {
  const long v = std::stol(colour.substr(1), nullptr, 16);
  return {static_cast<int>(v >> 16 & 0xff), static_cast<int>(v >> 8 & 0xff), static_cast<int>(v & 0xff)};
}

// What a panel's title says of its run's events: the count over the whole run, and how many the
// page lists when it keeps fewer.
std::string event_note(const Result& r) {
  const long counted = r.metrics.count(Metric::tunnelling_wall) + r.metrics.count(Metric::tunnelling_pair) + r.metrics.count(Metric::sticking_wall) + r.metrics.count(Metric::sticking_pair);
  std::string note = std::to_string(counted) + (counted == 1 ? " event" : " events");
  if (static_cast<long>(r.events.size()) < counted) note += ", " + std::to_string(r.events.size()) + " listed";
  return note;
}

// What a panel's title says of a run that stopped: its status and when (stop_time).
std::string stopped_note(const Result& r) {
  return fmt::format("{} at t = {:.2f} s", run_status_text(r.status), stop_time(r));
}

TEST(ViewerBrowser, ShowsTheFrameAskedForWithEachRunsBallsWhereTheRunPutThem) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "chromium not found: the viewer's browser test needs Debian's chromium (scripts/lib.sh installs it)";
  TempDir dir;
  const std::string json = (dir.path / "run.json").string(), page = (dir.path / "run.html").string();
  // home-seed, the thesis's algorithm, sticks and tunnels on seed-box early on: events to click.
  ASSERT_EQ(run_cli("run --scene seed-box --engine home-seed,home --steps 300 --frames 150 --no-reference --quiet --json " +
                    json).status, 1);  // home-seed diverges (a ball leaves the box)
  const auto view = run_cli("view " + json + " --out " + page);
  ASSERT_EQ(view.status, 0) << view.err;
  const std::vector<Result> runs = read_results_file(json);
  ASSERT_EQ(runs.size(), 2u);
  ASSERT_GT(runs[0].series.frames.size(), 40u);
  // The page names no path of the machine that made it (the scene's file is in the source tree).
  const std::string html = slurp(page);
  for (const std::string& path : {std::string(BALLBENCH_SOURCE_DIR), dir.path.string()})
    EXPECT_EQ(html.find(path), std::string::npos) << path;
  EXPECT_NE(runs[0].scene_source.find('/'), std::string::npos) << "a path to leave out: " << runs[0].scene_source;

  const int k = 37;  // not the frame a page opens at (0)
  const nlohmann::json state = page_state(browser, "file://" + page + "#frame=" + std::to_string(k), dir.path);
  ASSERT_FALSE(state.is_null());
  EXPECT_EQ(state.at("frame"), k);
  EXPECT_NEAR(state.at("t").get<double>(), runs[1].series.frame_t[k], 1e-12);
  EXPECT_NE(state.at("title").get<std::string>().find("seed-box"), std::string::npos) << state.at("title");
  EXPECT_EQ(state.at("engines"), nlohmann::json({"home-seed", "home"}));
  ASSERT_EQ(state.at("panels").size(), 2u);
  for (size_t p = 0; p < runs.size(); ++p) {
    const nlohmann::json& panel = state.at("panels").at(p);
    const Result& r = runs[p];
    const size_t held = std::min<size_t>(k, r.series.frames.size() - 1);
    EXPECT_EQ(panel.at("frame"), held) << r.engine;
    // Ball 0 is drawn where this run's frame puts it, in its engine's colour (the figures' and GIFs').
    const auto& ball0 = panel.at("ball0");
    EXPECT_NEAR(ball0.at("x").get<double>(), r.series.frames[held][0][0], 1e-9) << r.engine;
    EXPECT_NEAR(ball0.at("y").get<double>(), r.series.frames[held][0][1], 1e-9) << r.engine;
    EXPECT_EQ(ball0.at("rgb").get<std::vector<int>>(), rgb(run_style(r.engine, r.profile).colour)) << r.engine;
    // The title counts the run's events, not the ones listed; a run that stopped says so instead.
    EXPECT_EQ(panel.at("note"), held == static_cast<size_t>(k) ? event_note(r) : stopped_note(r)) << r.engine;
    // Events are marked once they have happened, not before.
    const long happened = std::count_if(r.events.begin(), r.events.end(),
                                        [&](const Event& e) { return e.t <= runs[1].series.frame_t[k]; });
    EXPECT_EQ(panel.at("marks"), happened) << r.engine;
    if (p == 0) {
      EXPECT_LT(happened, static_cast<long>(r.events.size())) << "events still to come, not drawn yet";
    }
    // A point no ball of that frame covers shows the inside of the box.
    ASSERT_TRUE(panel.contains("empty")) << r.engine;
    const auto& empty = panel.at("empty");
    const double ex = empty.at("x"), ey = empty.at("y");
    for (size_t b = 0; b < r.series.frames[held].size(); ++b)
      EXPECT_GT(std::hypot(r.series.frames[held][b][0] - ex, r.series.frames[held][b][1] - ey), r.series.radius[b])
          << r.engine << " ball " << b;
    EXPECT_EQ(empty.at("rgb").get<std::vector<int>>(), kInside) << r.engine;
  }

  // Past the step home-seed diverged at, its panel holds its last frame and says when it stopped: the
  // step it diverged at, not its last frame's time (frames are every few steps).
  ASSERT_EQ(runs[0].status, RunStatus::diverged);
  const size_t late = runs[1].series.frames.size() - 1;
  ASSERT_LT(runs[0].series.frames.size(), late);
  const nlohmann::json stopped = page_state(browser, "file://" + page + "#frame=" + std::to_string(late), dir.path);
  ASSERT_FALSE(stopped.is_null());
  EXPECT_EQ(stopped.at("panels").at(0).at("frame"), runs[0].series.frames.size() - 1);
  EXPECT_EQ(stopped.at("panels").at(0).at("note"), stopped_note(runs[0]));
  EXPECT_EQ(stopped_note(runs[0]), fmt::format("diverged at t = {:.2f} s", runs[0].diverged_step * runs[0].dt));
  EXPECT_NE(runs[0].series.frame_t.back(), runs[0].diverged_step * runs[0].dt) << "a frame at the step itself proves nothing";

  // Clicking an event (the fragment's event=I selects the list's I-th, in time order) jumps to the
  // frame nearest its time.
  ASSERT_FALSE(runs[0].events.empty());
  const Event& first = runs[0].events.front();  // home-seed's, and home has none: the list's first
  ASSERT_TRUE(runs[1].events.empty());
  const nlohmann::json picked = page_state(browser, "file://" + page + "#event=0", dir.path);
  ASSERT_FALSE(picked.is_null());
  EXPECT_EQ(picked.at("selected"), 0);
  const auto& t = runs[1].series.frame_t;
  size_t nearest = 0;
  for (size_t f = 0; f < t.size(); ++f)
    if (std::abs(t[f] - first.t) < std::abs(t[nearest] - first.t)) nearest = f;
  EXPECT_EQ(picked.at("frame"), nearest);
}

// The arrow keys step one frame each, with the slider focused (where the slider's own stepping
// would add a second) and without.
TEST(ViewerBrowser, AnArrowKeyStepsOneFrame) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "chromium not found: the viewer's browser test needs Debian's chromium (scripts/lib.sh installs it)";
  TempDir dir;
  const std::string json = (dir.path / "run.json").string(), page = (dir.path / "run.html").string();
  ASSERT_EQ(run_cli("run --scene seed-box --engine home --steps 100 --frames 50 --no-reference --quiet --json " + json).status, 0);
  ASSERT_EQ(run_cli("view " + json + " --out " + page).status, 0);
  DevTools chrome(browser, dir.path / "devtools-profile");
  const nlohmann::json target = chrome.call("Target.createTarget", {{"url", "about:blank"}});
  ASSERT_FALSE(target.is_null());
  const nlohmann::json attached = chrome.call("Target.attachToTarget", {{"targetId", target.at("targetId")}, {"flatten", true}});
  ASSERT_FALSE(attached.is_null());
  const std::string session = attached.at("sessionId");
  chrome.call("Page.enable", nlohmann::json::object(), session);
  chrome.call("Page.navigate", {{"url", "file://" + page + "#frame=10"}}, session);
  ASSERT_TRUE(chrome.wait_for("Page.loadEventFired"));
  auto evaluate = [&](const std::string& expression) {
    const nlohmann::json r = chrome.call("Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}}, session);
    return r.is_null() ? nlohmann::json() : r.at("result").value("value", nlohmann::json());
  };
  auto press = [&](const std::string& key, int code) {
    for (const char* type : {"rawKeyDown", "keyUp"})
      chrome.call("Input.dispatchKeyEvent", {{"type", type}, {"key", key}, {"code", key}, {"windowsVirtualKeyCode", code}}, session);
  };
  auto frame = [&]() {
    const nlohmann::json text = evaluate("document.getElementById('state').textContent");
    return text.is_string() ? nlohmann::json::parse(text.get<std::string>()).at("frame").get<int>() : -1;
  };
  ASSERT_EQ(frame(), 10);
  ASSERT_EQ(evaluate("document.getElementById('scrub').focus(); document.activeElement.id"), "scrub");
  for (int k = 0; k < 3; ++k) press("ArrowRight", 39);
  EXPECT_EQ(frame(), 13) << "three presses on the focused slider";
  press("ArrowLeft", 37);
  EXPECT_EQ(frame(), 12);
  ASSERT_EQ(evaluate("document.activeElement.blur(); document.activeElement.tagName"), "BODY");
  press("ArrowRight", 39);
  EXPECT_EQ(frame(), 13) << "a press with nothing focused";
}

}  // namespace
}  // namespace ballbench

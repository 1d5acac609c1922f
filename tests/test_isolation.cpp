// Engine runs in child processes (core/isolated_run.h, run_all in core/cli/run_engines.h): a
// segfault, abort or hang in one engine marks that row and the rest of the comparison completes;
// a run that blows up numerically stops at the step it diverged, keeping the metrics before it.
// The misbehaving engines exist only in this file, never in the product's registry.
#include <gtest/gtest.h>

#include <time.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "core_affinity.h"
#include "input_error.h"
#include "interrupt.h"
#include "isolated_run.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"

namespace ballbench {
namespace {

enum class Misbehaviour { None, Segfault, Abort, Hang, Spin, Throw, Exit3, NonFinite, EnergyGrowth, NonFiniteSpin, DropsSpin, Slow, Busy, Cold };

// Balls in free flight, mirrored at the walls (no ball-ball collisions), misbehaving at step `at`.
class TestEngine : public Engine {
 public:
  TestEngine(const Scene& s, Misbehaviour m, long at) : state_(s.initial), box_(s.container), m_(m), at_(at) {
    if (m_ == Misbehaviour::Cold) ++cold_worlds();
  }
  // A JIT's engine: its first `at` / 2 steps in this process cost ten times the last ones, the next
  // `at` / 2 five times.
  static long& cold_steps() {
    static long k = 0;
    return k;
  }
  static int& cold_worlds() {
    static int k = 0;
    return k;
  }
  void step(double dt) override {
    ++k_;
    if (k_ == at_) misbehave();
    if (m_ == Misbehaviour::EnergyGrowth && k_ >= at_) state_.vel *= 2.0;  // kinetic energy x4 per step
    if (m_ == Misbehaviour::Slow) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (m_ == Misbehaviour::Busy && k_ >= at_) spend_cpu(0.06);
    if (m_ == Misbehaviour::Cold) spend_cpu(++cold_steps() <= at_ / 2 ? 2e-3 : cold_steps() <= at_ ? 1e-3 : 2e-4);
    state_.pos += dt * state_.vel;
    state_.t += dt;
    if (box_.kind != ContainerKind::Box) return;
    for (int i = 0; i < state_.n(); ++i)
      for (int a = 0; a < 2; ++a)
        for (double& x = state_.pos(i, a); x < box_.min(a) || x > box_.max(a);) {
          x = x < box_.min(a) ? 2 * box_.min(a) - x : 2 * box_.max(a) - x;
          state_.vel(i, a) = -state_.vel(i, a);
        }
  }
  void read(State& out) const override { out = state_; }
  nlohmann::json settings() const override { return nlohmann::json::object(); }

 private:
  void misbehave() {
    switch (m_) {
      case Misbehaviour::Segfault:
        // As an engine built without sanitizers would die: the sanitizers' own SIGSEGV handler
        // (in the sanitize build) would otherwise turn the signal into exit status 1.
        std::signal(SIGSEGV, SIG_DFL);
        std::raise(SIGSEGV);
        break;
      case Misbehaviour::Abort: std::abort();
      case Misbehaviour::Hang:
        for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
      case Misbehaviour::Spin:  // a step that computes for ever
        for (volatile unsigned long i = 0;;) i = i + 1;
      case Misbehaviour::Throw: throw std::runtime_error("the test engine gave up");
      case Misbehaviour::Exit3: std::_Exit(3);
      case Misbehaviour::NonFinite: state_.pos(0, 0) = std::numeric_limits<double>::quiet_NaN(); break;
      case Misbehaviour::NonFiniteSpin: state_.w(0) = std::numeric_limits<double>::infinity(); break;
      case Misbehaviour::DropsSpin: state_.w.resize(0), state_.angle.resize(0); break;
      default: break;
    }
  }
  // Computes until this thread has spent `seconds` of CPU.
  static void spend_cpu(double seconds) {
    const auto cpu = [] {
      timespec t{};
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
      return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
    };
    for (const double end = cpu() + seconds; cpu() < end;) {
    }
  }
  State state_;
  Container box_;
  Misbehaviour m_;
  long at_, k_ = 0;
};

EngineEntry test_engine(const std::string& name, Misbehaviour m, long at = 5) {
  EngineEntry e;
  e.info.name = name;
  e.info.version = "test";
  e.create = [m, at](const Scene& s, const std::string&, const nlohmann::json&) {
    return std::make_unique<TestEngine>(s, m, at);
  };
  return e;
}

const Scene& box() {
  static const Scene s = load_scene("seed-box");
  return s;
}

RunOptions steps(long n) {
  RunOptions o;
  o.steps = n;
  return o;
}

Result isolated(const EngineEntry& e, double timeout_s = 30, long n = 50) {
  return run_engine_isolated(box(), e, steps(n), {timeout_s, ""});
}

TEST(Isolation, ASegfaultIsACrashNamingTheSignal) {
  const Result r = isolated(test_engine("segv", Misbehaviour::Segfault));
  EXPECT_EQ(r.status, RunStatus::crashed);
  EXPECT_NE(r.error.find("SIGSEGV"), std::string::npos) << r.error;
  EXPECT_EQ(r.engine, "segv");
  EXPECT_EQ(r.steps, 50);
  // The steps it made are named, and why steps_done reads 0: their figures died with the child.
  EXPECT_EQ(r.steps_done, 0);
  EXPECT_NE(r.error.find("after step 4 of 50 (the figures of those steps lost with it)"), std::string::npos) << r.error;
}

TEST(Isolation, AnAbortIsACrashNamingTheSignal) {
  const Result r = isolated(test_engine("abort", Misbehaviour::Abort));
  EXPECT_EQ(r.status, RunStatus::crashed);
  EXPECT_NE(r.error.find("SIGABRT"), std::string::npos) << r.error;
}

TEST(Isolation, AnExitWithoutAResultIsACrash) {
  const Result r = isolated(test_engine("exit", Misbehaviour::Exit3));
  EXPECT_EQ(r.status, RunStatus::crashed);
  EXPECT_NE(r.error.find("exited with status 3"), std::string::npos) << r.error;
}

TEST(Isolation, AHangTimesOutAtTheLimit) {
  const Result r = isolated(test_engine("hang", Misbehaviour::Hang), 1.0);
  EXPECT_EQ(r.status, RunStatus::timed_out);
  EXPECT_NE(r.error.find("time limit of 1 s"), std::string::npos) << r.error;
}

// Steps of 60 ms of CPU each under a cost limit of 0.1 s stop over cost after the step that passed
// it (its engine time checked after any step of 50 ms or more), not at the 64th step.
TEST(CostLimit, IsCheckedAfterASlowStep) {
  RunOptions o = steps(50);
  o.cost_limit = RunOptions::CostLimit{0.1, "the cost of a cheaper configuration"};
  const Result r = run_engine(box(), test_engine("busy", Misbehaviour::Busy, 1), o);
  EXPECT_EQ(r.status, RunStatus::over_cost) << r.error;
  EXPECT_GE(r.steps_done, 2);
  EXPECT_LE(r.steps_done, 4) << r.error;  // 0.1 s passed by the second step, a third for the CPU clock's share
}

// A run records its pace: its engine's step time (CPU time, as its cost) at each 1/32 of its steps,
// rising to the whole run's.
TEST(CostPace, ARunRecordsItsEngineTimeAlongItsSteps) {
  RunOptions o = steps(20);
  o.record_pace = true;
  const Result r = run_engine(box(), test_engine("busy", Misbehaviour::Busy, 1), o);
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  ASSERT_EQ(r.pace.size(), size_t(kPacePoints));
  EXPECT_TRUE(std::is_sorted(r.pace.begin(), r.pace.end()));
  ASSERT_TRUE(r.engine_cpu_s);
  // Up to one step of 20 apart: the first is timed before any step is known to be long, on the wall
  // clock in the pace and at the run's share of CPU in the cost, which a loaded core sets apart.
  EXPECT_NEAR(r.pace.back(), *r.engine_cpu_s, 0.05 * *r.engine_cpu_s);
  const double half = r.pace[kPacePoints / 2 - 1] / r.pace.back();  // steps of equal work: about half
  EXPECT_GT(half, 0.3);
  EXPECT_LT(half, 0.7);
  const auto pace = CostPace::from_points(r.pace);
  ASSERT_TRUE(pace);
  EXPECT_NEAR(pace->project(1.0, 0.5), 1.0 / half, 1e-9);
}

// A run's cost is the CPU its engine spent, on a loaded core as on an idle one: each step of the busy
// engine spends 0.06 s of CPU, and beside a job busy on the same core the run's wall time doubles
// while its CPU time stays. (One share of CPU over wall for the whole run read such steps low: the
// harness's work between them is where a loaded core's time slices end.)
TEST(CostPace, ARunOnALoadedCoreCostsTheCPUItsStepsSpent) {
  const std::vector<int> cores = allowed_cores();
  ASSERT_FALSE(cores.empty());
  const CorePin pin(cores.front());
  const pid_t busy = ::fork();
  ASSERT_GE(busy, 0);
  if (busy == 0) {  // the other job, on the same core (the affinity is inherited), until killed
    volatile unsigned long spin = 0;
    for (;;) spin = spin + 1;
  }
  const Result r = run_engine(box(), test_engine("busy", Misbehaviour::Busy, 1), steps(16));
  ::kill(busy, SIGKILL);
  ::waitpid(busy, nullptr, 0);
  ASSERT_EQ(r.status, RunStatus::ok) << r.error;
  ASSERT_TRUE(r.engine_cpu_s);
  if (r.engine_s < 1.5 * 16 * 0.06) GTEST_SKIP() << "the other job did not share the core (wall " << r.engine_s << " s)";
  // 10%: the first step is timed before any step is known to be long (its wall time times the
  // run's share, up to one step off: 1/16), and each later one holds a CPU clock read (1.3 us).
  EXPECT_NEAR(*r.engine_cpu_s, 16 * 0.06, 0.1 * 16 * 0.06) << "wall " << r.engine_s << " s";
}

// A timing's passes run the scene again on new worlds in one process until the engine is warm: an
// engine whose passes of 50 steps cost 10, 5, then 1 (as box2d3's seed-box window took 41, 20, 10 and
// 10 ms in one process) is timed at its warm cost, the last pass's and the mean of the warm passes
// (those from the first that gained nothing: none of the cold ones); one pass times it cold.
TEST(RunPasses, ATimingRunsUntilTheEngineIsWarmAndReadsItsWarmPasses) {
  const EngineEntry cold = test_engine("cold", Misbehaviour::Cold, 100);
  RunOptions o = steps(50);
  o.passes = 8;
  TestEngine::cold_steps() = 0, TestEngine::cold_worlds() = 0;
  const Result warm = run_engine(box(), cold, o);
  ASSERT_EQ(warm.status, RunStatus::ok) << warm.error;
  EXPECT_GE(TestEngine::cold_worlds(), 4);  // 10, 5, 1, then passes of 1 that gain nothing
  EXPECT_LE(TestEngine::cold_worlds(), 8);
  // Half the warm cost either way: the cold passes cost 5 and 10 times it, so any of them kept fails.
  EXPECT_NEAR(warm.cost_s(), 50 * 2e-4, 0.5 * 50 * 2e-4);
  ASSERT_TRUE(warm.warm);
  // Never the three cold passes; the fourth may read as warming still under a sanitizer's noise.
  EXPECT_GE(warm.warm->count, 1);
  EXPECT_LE(warm.warm->count, TestEngine::cold_worlds() - 3);
  EXPECT_NEAR(warm.warm->cost_s, 50 * 2e-4, 0.5 * 50 * 2e-4);
  // The warm passes' wall time beside their CPU time (the pipe figure a timing reads): a step of 0.2 ms
  // is on the CPU clock, which a one-thread engine's wall time is never below; half, for a warm pass
  // whose CPU time a descheduling between two clock reads put above its wall time.
  EXPECT_GE(warm.warm->engine_s, 0.5 * warm.warm->cost_s);
  TestEngine::cold_steps() = 0;
  const Result first = run_engine(box(), cold, steps(50));
  EXPECT_GT(first.cost_s(), 5 * warm.cost_s());
  EXPECT_FALSE(first.warm);
}

// A window's pace is the engine's time from the window's start to each sixteenth of it, growing to
// the window's whole time, beside the whole run's on the same clock; a window of fewer steps than
// points gives the points that share a step one time.
TEST(RunWindow, RecordsTheEnginesTimeAtEachSixteenthOfTheWindow) {
  for (const long window_steps : {32L, 5L}) {
    RunOptions o = steps(50);
    o.window.start = 10, o.window.steps = window_steps;
    const Result r = run_engine(box(), find_engine("home"), o);
    ASSERT_EQ(r.status, RunStatus::ok) << r.error;
    ASSERT_TRUE(r.window_engine_s);
    ASSERT_EQ(r.window_pace.size(), size_t(kWindowPoints)) << window_steps;
    EXPECT_TRUE(std::is_sorted(r.window_pace.begin(), r.window_pace.end()));
    EXPECT_GT(r.window_pace.front(), 0);
    EXPECT_DOUBLE_EQ(r.window_pace.back(), *r.window_engine_s);
    // The run's whole time on the window's clock: the window is a part of it.
    ASSERT_TRUE(r.window_clock_s);
    EXPECT_GT(*r.window_clock_s, *r.window_engine_s);
    for (int i = 1; i < kWindowPoints; ++i) {
      if (window_prefix_steps(window_steps, i) == window_prefix_steps(window_steps, i - 1)) {
        EXPECT_EQ(r.window_pace[size_t(i)], r.window_pace[size_t(i - 1)]) << i;
      }
    }
  }
}

// A pace projects a run from a point of its steps as its pace run grew from there: in proportion
// for steps of equal work, ten times for a pace that spent a tenth by half way; a pace never falls.
TEST(CostPace, ProjectsAWholeRunFromAPartOfIt) {
  std::vector<double> even(kPacePoints), late(kPacePoints);
  for (int i = 0; i < kPacePoints; ++i) {
    even[i] = i + 1;
    late[i] = i < kPacePoints / 2 ? 0.1 * (i + 1) / (kPacePoints / 2) : 0.1 + 0.9 * (i + 1 - kPacePoints / 2) / (kPacePoints / 2);
  }
  EXPECT_DOUBLE_EQ(CostPace::from_points(even)->project(2.0, 0.25), 8.0);
  EXPECT_NEAR(CostPace::from_points(late)->project(2.0, 0.5), 20.0, 1e-9);
  EXPECT_DOUBLE_EQ(CostPace::from_points(even)->project(2.0, 1.0), 2.0);  // done: what it spent
  EXPECT_FALSE(CostPace::from_points({1}));  // a run that stopped before kPaceFrom of its steps
  std::vector<double> falling = even;
  std::swap(falling[3], falling[4]);
  EXPECT_FALSE(CostPace::from_points(falling));
  EXPECT_FALSE(CostPace::from_points(std::vector<double>(kPacePoints, 0.0)));
}

// A pace run stopped at its cost limit part way is the pace of what it covered, and goes on past it
// at the rate of its last quarter: half a run of equal steps projects as a whole one; one whose
// steps grew costlier projects at its latest steps' rate, never above the rate it reached.
TEST(CostPace, APaceStoppedPartWayGoesOnAtItsLastRate) {
  std::vector<double> half_even(kPacePoints / 2), half_growing(kPacePoints / 2);
  for (int i = 0; i < kPacePoints / 2; ++i) half_even[i] = i + 1, half_growing[i] = (i + 1) * (i + 1);
  const auto even = CostPace::from_points(half_even);
  ASSERT_TRUE(even);
  EXPECT_DOUBLE_EQ(even->project(2.0, 0.25), 8.0);  // inside what it covered
  EXPECT_DOUBLE_EQ(even->project(2.0, 0.75), 2.0 / 0.75);  // past it
  const auto growing = CostPace::from_points(half_growing);
  ASSERT_TRUE(growing);
  // Its last quarter (points 12 .. 16: 144 -> 256) goes on at 28 a point, 16 points more: 704.
  EXPECT_DOUBLE_EQ(growing->project(1.0, 0.5), (256.0 + 28 * 16) / 256.0);
  // A growing pace's true whole (32^2 = 1024) is above the projection: it errs low.
  EXPECT_LT(growing->project(1.0, 0.5), 1024.0 / 256.0);
}

// A try is projected with the pace nearest it: its configuration's one step coarser, else the
// profile as it is at its step or the nearest coarser, else the engine's first run's; a try that
// recorded no pace (stopped before kPaceFrom) is passed over.
TEST(CostPace, ATryIsProjectedWithTheNearestPace) {
  const auto pace = [](double last) { return *CostPace::from_points(std::vector<double>(kPacePoints, last)); };
  const CostPace first = pace(1);
  const std::map<int, CostPace> paces{{0, pace(2)}, {1, pace(3)}, {3, pace(5)}, {4, pace(6)}};
  const std::map<int, int> as_is{{0, 0}, {2, 1}, {4, 2}};  // halvings -> try index; try 2 has none
  const std::map<int, int> own{{1, 3}, {2, 4}, {3, 5}};    // try 5 has none
  const auto last = [](const CostPace* p) { return p ? p->points().back() : -1.0; };
  EXPECT_EQ(last(nearest_pace(own, as_is, paces, 3, &first)), 6);  // its own at dt/4
  EXPECT_EQ(last(nearest_pace(own, as_is, paces, 4, &first)), 6);  // dt/8 recorded none: dt/4
  EXPECT_EQ(last(nearest_pace(own, as_is, paces, 1, &first)), 2);  // none coarser of its own: as is at dt
  EXPECT_EQ(last(nearest_pace({}, as_is, paces, 2, &first)), 3);   // as is at its own step
  EXPECT_EQ(last(nearest_pace({}, as_is, paces, 5, &first)), 3);   // as is at dt/16 recorded none
  EXPECT_EQ(last(nearest_pace({}, {}, paces, 2, &first)), 1);
  EXPECT_EQ(nearest_pace({}, {}, paces, 2, nullptr), nullptr);
}

// A try's whole run from what it ran: at the pace, or in proportion without one; never from less
// than kPaceFrom of its steps (a run that missed at its third step is mostly its engine's start).
TEST(CostPace, AWholeRunIsProjectedOnlyFromEnoughOfIt) {
  std::vector<double> even(kPacePoints);
  for (int i = 0; i < kPacePoints; ++i) even[i] = i + 1;
  const auto pace = CostPace::from_points(even);
  EXPECT_DOUBLE_EQ(*whole_run_cost(2.0, 0.25, &*pace), 8.0);
  EXPECT_DOUBLE_EQ(*whole_run_cost(2.0, 0.25, nullptr), 8.0);
  EXPECT_DOUBLE_EQ(*whole_run_cost(2.0, 1.0, nullptr), 2.0);
  EXPECT_FALSE(whole_run_cost(2.0, 0.001, &*pace));
  EXPECT_FALSE(whole_run_cost(2.0, 0.001, nullptr));
  EXPECT_TRUE(whole_run_cost(2.0, kPaceFrom, nullptr));
}

// Steps of 60 ms under a limit of 0.5 s with a pace of equal steps: from 1/16 of the run on, the time
// so far projects the whole run's 1.2 s, past 1.25 times the limit, so it stops at once, where
// without a pace it runs to the limit (CostLimit.IsCheckedAfterASlowStep). Under a limit above the
// whole run, the same pace lets it finish.
TEST(CostPace, AProjectionPastTheLimitStopsARunEarly) {
  std::vector<double> even(kPacePoints);
  for (int i = 0; i < kPacePoints; ++i) even[i] = i + 1;
  RunOptions o = steps(20);
  o.cost_limit = RunOptions::CostLimit{0.5, "the cost of a cheaper configuration", CostPace::from_points(even)};
  const Result r = run_engine(box(), test_engine("busy", Misbehaviour::Busy, 1), o);
  EXPECT_EQ(r.status, RunStatus::over_cost) << r.error;
  EXPECT_LE(r.steps_done, 3) << r.error;
  EXPECT_NE(r.error.find("projects"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("the cost of a cheaper configuration"), std::string::npos) << r.error;
  o.cost_limit->seconds = 5.0;
  const Result whole = run_engine(box(), test_engine("busy", Misbehaviour::Busy, 1), o);
  EXPECT_EQ(whole.status, RunStatus::ok) << whole.error;
  EXPECT_EQ(whole.steps_done, 20);
}

// Without a pace, a limit with a margin for it projects in proportion to the steps: steps of 60 ms
// project a whole run of 1.2 s, past 1.5 times a limit of 0.5 s, so it stops at once; under a limit
// of 0.9 s (1.35 s with the margin) the projection never passes, and it runs until its time does.
TEST(CostPace, WithoutAPaceALinearMarginProjectsInProportionToTheSteps) {
  RunOptions o = steps(20);
  o.cost_limit = RunOptions::CostLimit{0.5, "1.5x the match's ceiling", std::nullopt, 1.5};
  const Result r = run_engine(box(), test_engine("busy", Misbehaviour::Busy, 1), o);
  EXPECT_EQ(r.status, RunStatus::over_cost) << r.error;
  EXPECT_LE(r.steps_done, 3) << r.error;
  EXPECT_NE(r.error.find("in proportion to its steps"), std::string::npos) << r.error;
  o.cost_limit->seconds = 0.9;
  const Result late = run_engine(box(), test_engine("busy", Misbehaviour::Busy, 1), o);
  EXPECT_EQ(late.status, RunStatus::over_cost) << late.error;
  // 0.9 s of 60 ms steps is 15 of them; one fewer where the CPU clock's reading runs ahead of the
  // steps' own sleep-free loops (scheduler ticks).
  EXPECT_GE(late.steps_done, 14) << late.error;
  EXPECT_NE(late.error.find("its engine time passed"), std::string::npos) << late.error;
}

// A step that computes for ever under a cost limit is killed once the child's CPU time passes
// twice the limit and 5 s, long before the time limit: over cost, inside a step, after the steps it
// made.
TEST(Isolation, AStepThatComputesForEverIsKilledAtTheCostLimitsCpuTime) {
  RunOptions o = steps(50);
  o.cost_limit = RunOptions::CostLimit{0.5, "the cost of a cheaper configuration"};
  const Result r = run_engine_isolated(box(), test_engine("spin", Misbehaviour::Spin), o, {600, ""});
  EXPECT_EQ(r.status, RunStatus::over_cost) << r.error;
  EXPECT_NE(r.error.find("s of CPU inside a step"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("inside a step after step 4 of 50"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("the cost of a cheaper configuration"), std::string::npos) << r.error;
}

// A slow engine that still returns from its steps stops at the first step boundary past its time
// limit, and the steps it made are measured and kept (a hang, stuck in a step, is killed later).
TEST(Isolation, ASlowRunStopsAtItsTimeLimitKeepingItsSteps) {
  const Result r = isolated(test_engine("slow", Misbehaviour::Slow), 1.0);
  EXPECT_EQ(r.status, RunStatus::timed_out);
  EXPECT_NE(r.error.find("the time limit passed after step"), std::string::npos) << r.error;
  EXPECT_GT(r.steps_done, 0);
  EXPECT_LT(r.steps_done, r.steps);
  EXPECT_EQ(r.metrics.count(Metric::samples), r.steps_done + 1);
}

TEST(Isolation, AnEngineExceptionIsStillAFailureNotACrash) {
  const Result r = isolated(test_engine("throw", Misbehaviour::Throw));
  EXPECT_EQ(r.status, RunStatus::failed);
  EXPECT_NE(r.error.find("step 5 threw: the test engine gave up"), std::string::npos) << r.error;
  EXPECT_EQ(r.steps_done, 4);  // the metrics of the steps before are kept
  EXPECT_EQ(r.metrics.count(Metric::samples), 5);
}

TEST(Isolation, BadSettingsFoundInTheChildAreTheUsersError) {
  RunOptions o = steps(10);
  o.overrides = {{"no_such_setting", 1}};
  try {
    run_engine_isolated(box(), find_engine("home"), o, {});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_setting"), std::string::npos) << e.what();
  }
}

// The child's result is the in-process result, bit for bit, timing aside.
TEST(Isolation, GivesTheSameResultAsARunInThisProcess) {
  for (const char* name : {"home", "home-seed"}) {
    nlohmann::json a = to_json(run_engine(box(), find_engine(name), steps(300)));
    nlohmann::json b = to_json(isolated(find_engine(name), 60, 300));
    for (const char* timing : {"engine_s", "engine_cpu_s", "ns_per_step", "ns_per_ball_step", "harness_s"})
      a.erase(timing), b.erase(timing);
    EXPECT_EQ(a, b) << name;
    EXPECT_EQ(a["checksum"]["trajectory"].get<std::string>().size(), 16u);
  }
}

// Two runs at once (a report's scene tables): the rows in engine order, a crash or a hang in one
// row and the others as when run one at a time, bit for bit.
TEST(Isolation, RunsSideBySideKeepTheirOrderAndTheirResults) {
  const EngineEntry segv = test_engine("segv", Misbehaviour::Segfault), hang = test_engine("hang", Misbehaviour::Hang),
                    free = test_engine("free", Misbehaviour::None);
  const std::vector<const EngineEntry*> engines{&find_engine("home"), &segv, &hang, &free, &find_engine("exact")};
  // 5 s for the hang: time for the others beside another test's job.
  cli::Isolation two{true, 5};
  two.jobs = 2;
  const auto side = cli::run_all(box(), engines, "", steps(40), true, two);
  const auto alone = cli::run_all(box(), engines, "", steps(40), true, {true, 5});
  ASSERT_EQ(side.size(), alone.size());
  for (size_t i = 0; i < side.size(); ++i) {
    EXPECT_EQ(side[i].engine, alone[i].engine);
    EXPECT_EQ(side[i].status, alone[i].status) << side[i].engine;
    EXPECT_EQ(side[i].checksum_trajectory, alone[i].checksum_trajectory) << side[i].engine;
  }
  EXPECT_EQ(side[1].status, RunStatus::crashed);
  EXPECT_EQ(side[2].status, RunStatus::timed_out);
  EXPECT_EQ(side[4].steps_done, 40);
}

// The issue's scenario: good engines before and after a crashing, an aborting and a hanging one.
TEST(Isolation, TheComparisonCompletesAroundCrashesAndHangs) {
  const EngineEntry segv = test_engine("segv", Misbehaviour::Segfault), abrt = test_engine("abort", Misbehaviour::Abort),
                    hang = test_engine("hang", Misbehaviour::Hang), free = test_engine("free", Misbehaviour::None);
  const std::vector<const EngineEntry*> engines{&find_engine("home"), &segv, &hang, &abrt, &free};
  const std::string csv = (std::filesystem::temp_directory_path() / "bb_isolation_traj.csv").string();
  const long n = 40;
  const auto results = cli::run_all(box(), engines, "", steps(n), true, {true, 1.5}, csv);
  ASSERT_EQ(results.size(), 5u);
  EXPECT_EQ(results[0].status, RunStatus::ok);
  EXPECT_EQ(results[1].status, RunStatus::crashed);
  EXPECT_EQ(results[2].status, RunStatus::timed_out);
  EXPECT_EQ(results[3].status, RunStatus::crashed);
  EXPECT_EQ(results[4].status, RunStatus::ok);
  for (int i : {0, 4}) {
    EXPECT_EQ(results[i].steps_done, n);
    EXPECT_EQ(results[i].metrics.count(Metric::samples), n + 1);
  }
  // One header, then (n + 1) samples x 20 balls for each complete run, none for the others.
  std::ifstream in(csv);
  std::string line;
  long header = 0, home = 0, free_rows = 0, other = 0;
  while (std::getline(in, line)) {
    if (line == "engine,profile,step,t,id,x,y,vx,vy") ++header;
    else if (line.rfind("home,", 0) == 0) ++home;
    else if (line.rfind("free,", 0) == 0) ++free_rows;
    else ++other;
  }
  EXPECT_EQ(header, 1);
  EXPECT_EQ(home, (n + 1) * 20);
  EXPECT_EQ(free_rows, (n + 1) * 20);
  EXPECT_EQ(other, 0);
  // No part files left behind.
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
    EXPECT_EQ(e.path().filename().string().find("bb_isolation_traj.csv."), std::string::npos) << e.path();
  std::filesystem::remove(csv);
}

// The trajectory CSV is the same whether runs are isolated or not.
TEST(Isolation, TrajectoryIsTheSameWithAndWithoutIsolation) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string a = (dir / "bb_iso_a.csv").string(), b = (dir / "bb_iso_b.csv").string();
  const std::vector<const EngineEntry*> engines{&find_engine("home-seed"), &find_engine("home")};
  cli::run_all(box(), engines, "", steps(30), true, {true, 60}, a);
  cli::run_all(box(), engines, "", steps(30), true, {false, 60}, b);
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_FALSE(slurp(a).empty());
  EXPECT_EQ(slurp(a), slurp(b));
  std::filesystem::remove(a), std::filesystem::remove(b);
}

TEST(DivergingRun, ANonFiniteStateStopsTheRunAtThatStep) {
  const Result r = run_engine(box(), test_engine("nan", Misbehaviour::NonFinite, 7), steps(50));
  EXPECT_EQ(r.status, RunStatus::diverged);
  EXPECT_TRUE(r.diverged());
  EXPECT_EQ(r.diverged_step, 7);
  EXPECT_EQ(r.steps_done, 6);         // the last good step
  EXPECT_EQ(r.metrics.count(Metric::samples), 7);    // steps 0..6: the metrics before the bad state
  EXPECT_TRUE(std::isfinite(r.metrics.value(Metric::energy_final)));
  // The final figures come from the last good state, not from the non-finite one.
  ASSERT_FALSE(r.series.final_pos.empty());
  for (const auto& p : r.series.final_pos) EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]));
}

// seed-box with friction: it rotates, so the engine must read back spins.
Scene rough_box() {
  Scene s = box();
  s.friction = 0.5;
  const State plain = s.initial;
  s.initial.resize(s.n(), true);
  s.initial.pos = plain.pos, s.initial.vel = plain.vel;
  s.initial.w.setZero(), s.initial.angle.setZero();
  return s;
}

TEST(DivergingRun, ANonFiniteSpinStopsTheRunAtThatStep) {
  const Result r = run_engine(rough_box(), test_engine("inf", Misbehaviour::NonFiniteSpin, 4), steps(50));
  EXPECT_EQ(r.status, RunStatus::diverged);
  EXPECT_EQ(r.diverged_step, 4);
  EXPECT_EQ(r.steps_done, 3);
}

TEST(FailedRun, AnEngineThatReadsBackNoSpinForARotatingSceneFails) {
  const Result r = run_engine(rough_box(), test_engine("spinless", Misbehaviour::DropsSpin, 6), steps(50));
  EXPECT_EQ(r.status, RunStatus::failed);
  EXPECT_NE(r.error.find("step 6: the engine read back no angular velocities"), std::string::npos) << r.error;
  EXPECT_EQ(r.steps_done, 5);
  // The same engine on a scene that does not rotate owes none.
  EXPECT_EQ(run_engine(box(), test_engine("spinless", Misbehaviour::DropsSpin, 6), steps(50)).status, RunStatus::ok);
}

TEST(Reference, AConvergedRunStandsInWhereExactRefusesTheScene) {
  // slide-to-roll with a second ball sliding far from the first: two rough balls under gravity,
  // which exact refuses (it has a closed form for one).
  const Scene s = parse_scene(R"(
name = "two-slides"
dt = 0.01
duration = 1.5
gravity = [0.0, -9.81]
restitution = 0.0
friction = 0.5
[container]
min = [0.0, 0.0]
max = [20.0, 4.0]
[[ball]]
pos = [1.0, 0.25]
vel = [3.0, 0.0]
radius = 0.25
[[ball]]
pos = [11.0, 0.25]
vel = [3.0, 0.0]
radius = 0.25
)", "two-slides.toml");
  RunOptions o;
  o.reference = &find_engine("exact");
  // Without a stand-in the refused reference is no comparison at all (never a frictionless run).
  const Result alone = run_engine(s, find_engine("box2d"), o);
  EXPECT_FALSE(alone.reference.available);
  EXPECT_TRUE(std::any_of(alone.skipped.begin(), alone.skipped.end(), [](const std::string& note) {
    return note.find("error against the reference: exact cannot run scene 'two-slides': rough balls resting on each other under gravity") == 0;
  })) << fmt::format("{}", fmt::join(alone.skipped, " | "));
  o.converged_reference = &find_engine("chipmunk");
  const Result r = run_engine(s, find_engine("box2d"), o);
  ASSERT_TRUE(r.reference.available);
  EXPECT_EQ(r.reference.reference, "chipmunk/tuned at dt/64");
  EXPECT_DOUBLE_EQ(r.reference.reference_dt, s.dt / 64);
  // Both roll at 2 m/s; box2d's first-order step lags the converged slide by about mu g dt t.
  EXPECT_LT(r.reference.pos_rms_final, 0.02);
  EXPECT_LT(r.reference.vel_rms_final, 1e-4);
}

TEST(DivergingRun, EnergyBeyondTheBoundStopsTheRun) {
  // From step 10 on the speed doubles every step, so the energy quadruples. The bound is 100 x
  // (E0 + initial kinetic energy) (MetricsConfig::divergence_energy_factor, energy_metric.cpp), here
  // 200 E0 as there is no gravity; 4^3 = 64 < 200 < 256 = 4^4, so the fourth doubling, at step
  // 13, crosses it.
  const Result r = run_engine(box(), test_engine("grow", Misbehaviour::EnergyGrowth, 10), steps(50));
  EXPECT_EQ(r.status, RunStatus::diverged);
  EXPECT_EQ(r.diverged_step, 13);
  EXPECT_EQ(r.steps_done, 13);  // the step that crossed the bound is observed, then the run stops
  EXPECT_NE(r.error.find("energy above 100 x"), std::string::npos) << r.error;
  EXPECT_GT(r.metrics.value(Metric::energy_final), 100 * r.metrics.value(Metric::energy_initial));
}

TEST(DivergingRun, OneDivergingEngineLeavesTheOthersRunning) {
  const EngineEntry nan = test_engine("nan", Misbehaviour::NonFinite, 3);
  const std::vector<const EngineEntry*> engines{&nan, &find_engine("home")};
  for (const bool isolate : {true, false}) {
    const auto results = cli::run_all(box(), engines, "", steps(20), true, {isolate, 60});
    ASSERT_EQ(results.size(), 2u);
    EXPECT_EQ(results[0].status, RunStatus::diverged) << results[0].error << (isolate ? " (isolated)" : "");
    EXPECT_EQ(results[0].diverged_step, 3);
    EXPECT_EQ(results[1].status, RunStatus::ok);
    EXPECT_EQ(results[1].steps_done, 20);
  }
}

TEST(Isolation, SignalDescriptionsNameTheSignal) {
  EXPECT_EQ(signal_description(SIGSEGV).rfind("SIGSEGV (", 0), 0u) << signal_description(SIGSEGV);
  EXPECT_EQ(signal_description(SIGKILL).rfind("SIGKILL (", 0), 0u);
}

// A signal between runs (after one ended, before the next began) still leaves a row marked
// "interrupted", for the run that was next: a results file always says it was cut short. Run in a
// child (a death test), as the interrupt flag, once raised, stays raised for the process.
TEST(Isolation, AnInterruptBetweenRunsMarksTheNextRun) {
  const std::vector<const EngineEntry*> engines{&find_engine("home-seed"), &find_engine("home")};
  EXPECT_EXIT(
      {
        const Scene& scene = box();  // placed first: placing balls is itself cut short by the flag
        install_interrupt_handlers();
        std::raise(SIGINT);
        auto results = cli::run_all(scene, engines, "", steps(5), true, {false, 60});
        bool ok = results.size() == 1 && results[0].engine == "home-seed" && results[0].status == RunStatus::interrupted &&
                  results[0].error.find("before this run started") != std::string::npos;
        // Between placements: the next placement's first run is marked, without drawing it.
        std::vector<Result> more{results[0]};
        more[0].status = RunStatus::ok;
        cli::run_further_placements(more, scene, 3, [](int) -> Scene { std::abort(); }, engines, "", steps(5), true,
                                    {false, 60});
        ok = ok && more.size() == 2 && more[1].status == RunStatus::interrupted && more[1].seed_offset == 1;
        std::exit(ok ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

// SIGHUP (a closed terminal) is a request to stop like SIGINT and SIGTERM, and rows name the
// signal that came. In a child (a death test), as the flag stays raised.
TEST(Isolation, SighupIsARequestToStopNamedAsItself) {
  const std::vector<const EngineEntry*> engines{&find_engine("home-seed")};
  EXPECT_EXIT(
      {
        const Scene& scene = box();
        install_interrupt_handlers();
        std::raise(SIGHUP);  // handled: the process goes on
        const auto results = cli::run_all(scene, engines, "", steps(5), true, {true, 60});
        const bool ok = interrupt_signal() == SIGHUP && std::string(interrupt_name()) == "SIGHUP" &&
                        results.size() == 1 && results[0].error == "interrupted by SIGHUP before this run started";
        std::exit(ok ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

// A run interrupted by SIGTERM is told by SIGTERM: its row names it, not SIGINT.
TEST(Isolation, TheRunIsToldByTheSignalThatCame) {
  const EngineEntry slow = test_engine("slow", Misbehaviour::None);
  EXPECT_EXIT(
      {
        install_interrupt_handlers();
        std::thread([] {
          std::this_thread::sleep_for(std::chrono::milliseconds(300));
          std::raise(SIGTERM);
        }).detach();
        const Result r = run_engine_isolated(box(), slow, steps(50'000'000), {60, ""});
        // Before its first step or after some (a slow set-up, under the sanitizers): SIGTERM either way.
        std::exit(r.status == RunStatus::interrupted && r.error.rfind("interrupted by SIGTERM ", 0) == 0 ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace ballbench

#pragma once
// The one door between the harness and a solver: our own solvers and every adapter implement it.
// An engine never reports metrics; the harness computes them from the states it reads back.
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene.h"
#include "state.h"

namespace ballbench {

// What an engine can simulate faithfully. The runner refuses, with the reason, a scene that needs
// something the engine lacks.
struct Capabilities {
  bool open_space = true;          // no container
  bool gravity = true;
  bool per_ball_radius = true;     // radii may differ
  bool per_ball_mass = true;       // masses may differ
  bool any_restitution = true;     // restitution honoured at any impact speed (no threshold)
  // Coulomb friction between balls and at walls, and the rotation it needs: the scene's inertia
  // and spin are honoured and angular velocity and angle read back (State::w, State::angle).
  bool friction = true;
  bool continuous_collision = false;  // fast balls cannot pass through walls or balls
  bool deterministic = true;       // same build, scene and settings -> same trajectory
};

class Engine {
 public:
  virtual ~Engine() = default;
  // Advances the world by dt seconds.
  virtual void step(double dt) = 0;
  // Writes positions and velocities (double, in scene order) and the engine's time into `out`,
  // and, for a scene that rotates (SceneFeatures::rotation), angular velocities and angles.
  virtual void read(State& out) const = 0;
  // The effective settings, every knob with the value in force (defaults included).
  virtual nlohmann::json settings() const = 0;
  // For 3D engines held to the plane: the largest |z| position or velocity over all balls now
  // (m or m/s). The runner tracks its maximum; 2D engines have none.
  virtual double out_of_plane() const { return 0.0; }
  // For engines in another process (adapters/process/): the step time that process measured
  // around its own step calls, summed since the engine was built (s). The harness's own timing of
  // step() adds the pipe; engines in this process have none.
  virtual std::optional<double> own_step_seconds() const { return std::nullopt; }
  // That time as taken alone: less the time its process waited for a core while other work held
  // them (adapters/process/core_wait.h). It costs the engine as the CPU time costs the others.
  virtual std::optional<double> own_step_cpu_seconds() const { return std::nullopt; }
  // How many steps apart the engine's states can be read: 1 for every step; k when it provides a
  // state only every k steps (an engine run in other processes that dumps samples). The runner
  // then steps k times between reads, and the metrics judged per step (tunnelling) see the samples.
  virtual int state_stride() const { return 1; }
  // The caller takes at most this many more steps: an engine that steps ahead of its reads (one in
  // another process, stepped in batches to spare the pipe's round trips) never steps past them.
  virtual void plan_steps(long /*steps*/) {}
  // Bounds for the steps of a run that wait for another process (RunOptions::stuck): past
  // `wall_end`, once that process has spent `cpu_s` of CPU on one request, or asked to stop
  // (interrupt.h: a grace for the step, none once hurried), the step ends the process and throws
  // StepStuck. An engine in this process is bounded from outside (isolated_run.h): it ignores them.
  virtual void bound_step(std::optional<std::chrono::steady_clock::time_point> /*wall_end*/,
                          std::optional<double> /*cpu_s*/) {}
};

// A step that passed Engine::bound_step's bounds, its engine's process ended.
class StepStuck : public std::runtime_error {
 public:
  enum class By { time_limit, cpu, interrupt };
  StepStuck(const std::string& what, By by, double cpu_s = 0) : std::runtime_error(what), by(by), cpu_s(cpu_s) {}
  By by;
  double cpu_s;  // By::cpu: the CPU it spent on the request (s)
};

// Thrown by an engine's factory for a scene it cannot run faithfully that its capabilities cannot
// express (say, one needing more sub-steps than its cap): the run's status is "unsupported" with
// this message, as for a capability the engine lacks. `settings`: what the engine would have run
// with (recorded in the result, as for a run).
class SceneUnsupported : public std::runtime_error {
 public:
  explicit SceneUnsupported(const std::string& why, nlohmann::json settings = nlohmann::json::object())
      : std::runtime_error(why), settings_(std::move(settings)) {}
  const nlohmann::json& settings() const { return settings_; }

 private:
  nlohmann::json settings_;
};

// An accuracy knob `ballbench sweep` varies: a settings key and the values it tries, one at a time,
// on top of each profile it applies to. The step size is varied for every engine by the sweep
// itself, so it is not listed here.
struct SweepKnob {
  std::string key;
  nlohmann::json values;              // a JSON array of setting values
  std::vector<std::string> profiles{};  // the profiles whose runs it changes; empty: every profile
};

// What an engine is to the harness. The report compares `ours` with `external` engines, measures
// everyone's error against the `reference`, and pictures the `thesis` port beside ours.
enum class EngineRole {
  ours,       // our solver: `home`
  reference,  // the accuracy reference every run is measured against: `exact`
  thesis,     // the 2017 thesis's algorithm ported as it was: `home-seed`
  external,   // an engine we compare against (every adapter)
};

// "ours", "reference", "thesis", "external".
const char* role_name(EngineRole role);

// One user setting of an engine, as `ballbench list --settings` prints it; engine_settings.h's
// SettingsTable::describe makes them from the engine's settings table.
struct SettingInfo {
  std::string name;
  nlohmann::json default_value;  // the settings struct's, before a profile changes it
  std::string range;             // the values it takes: ">= 1", "[0, 1]", "one of: soft, events"; "" any
  std::string unit;              // "" for a flag or a word
  std::string doc;               // one line
};

// How large the step benchmark (bench/step_benchmark.cpp) makes each kind of scene for an engine:
// ball counts go up by tenfold to these (0: the engine has no rows of that kind). An engine's
// limits are its own: what its cost per ball-step or its solver allows in a benchmark's budget.
struct BenchSizes {
  int free_balls = 100'000;    // the scaled gas and bowl, from 10
  int fluid_balls = 100'000;   // the fluid (it piles up), from 1000
  int settled_balls = 10'000;  // a pile at rest, from 100
};

struct BenchLimits {
  BenchSizes sizes;                                // every profile's, unless listed below
  std::map<std::string, BenchSizes> profile_sizes;  // profiles that differ
  nlohmann::json settings = nlohmann::json::object();  // added to the profile in the gas and bowl rows
  const BenchSizes& for_profile(const std::string& profile) const {
    const auto it = profile_sizes.find(profile);
    return it == profile_sizes.end() ? sizes : it->second;
  }
};

// A speed an engine clamps every ball to, and the clamp's name ("b2_maxTranslation 2 m per step").
struct SpeedCap {
  double m_per_s = 0;
  std::string what;
};

// An external engine's profiles: as its own documentation recommends for the scene, then as shipped.
inline const std::vector<std::string> kExternalProfiles{"tuned", "stock"};

struct EngineInfo {
  std::string name;        // as typed on the command line: "home", "box2d"
  std::string version;     // of the engine library or our solver
  std::string summary;     // one line for `ballbench list`
  std::string limits;      // what in the engine shapes results (clamps, slops, precision), for the report
  EngineRole role = EngineRole::external;
  std::string unavailable;  // why it cannot run on this machine (say, its runtime is missing), or ""
  Capabilities caps;
  std::vector<std::string> profiles{"default"};  // settings profiles; the first is the default
  std::vector<SweepKnob> sweep_knobs;             // what trades its run time for accuracy
  std::vector<SettingInfo> settings;              // its user settings (`ballbench list --settings`)
  // Each run costs far more than its steps: a process to start, thousands of DEM sub-steps per
  // step. The quick report's sweeps and frontiers, hundreds of runs each, leave it out.
  bool costly_runs = false;
  // It steps in a process of its own (an engine process, PROTOCOL.md), which isolates its crashes
  // and hangs already: its runs need no forked child, and its process serves run after run.
  bool own_process = false;
  BenchLimits bench;  // the step benchmark's sizes and settings for it
  // Why the engine cannot run a scene that its capabilities allow, judged from the scene alone
  // (say, friction under gravity among several balls, where `exact` has no closed form), or "";
  // unsupported_reason puts "NAME cannot run scene 'S': " before it.
  // unsupported_reason asks it, so the runner refuses such a run and a reference that refuses is
  // replaced by a converged run, before anything is built.
  std::function<std::string(const Scene&)> refuses;
  // The speed it clamps balls to at step dt with its effective settings (Result::settings), or
  // none: a run in which a ball reaches it is noted (Result::clamped), so a clamped run never
  // reads as a plain ok.
  std::function<std::optional<SpeedCap>(double dt, const nlohmann::json& settings)> speed_cap;
};

// Builds an engine for a scene. `settings` is a JSON object of overrides (from the scene's
// [settings.NAME] table and --set); an unknown key or bad value throws InputError.
using EngineFactory =
    std::function<std::unique_ptr<Engine>(const Scene&, const std::string& profile, const nlohmann::json& settings)>;

struct EngineEntry {
  EngineInfo info;
  EngineFactory create;
  // The user's engines file (--engines, BALLBENCH_ENGINES) that registered it, as given; "" for a
  // built-in or an engine of the project's engines.toml. A command reproducing its run names it.
  std::string engines_file{};
};

// For 3D engines that turn balls about z only: the angle (rad) of the unit quaternion
// (qw, 0, 0, qz), 2 atan2(qz, qw), unwrapped against `previous` (the ball's angle at the last read),
// so it accumulates as the 2D engines' angles do. Holds while a ball turns less than half a turn
// between reads.
double angle_about_z(double qw, double qz, double previous);

// Why `info` cannot run `scene` faithfully, or "" if it can.
std::string unsupported_reason(const EngineInfo& info, const Scene& scene);

}  // namespace ballbench

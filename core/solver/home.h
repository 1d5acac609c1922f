#pragma once
// `home`: our ball solver. Design and the reasons for it: core/solver/README.md.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine.h"
#include "solver/soft_step.h"

namespace ballbench {

// Scene-wide shortcuts, each decided once when the world is built, from Scene::features(), never
// per ball per step. A field says the shortcut may be taken; it is taken only when the scene allows
// it. Tests (tests/test_home_specialisations.cpp) and benchmarks (bench/home_benchmark.cpp)
// clear a field to run the general path on the same scene; what each saves: core/solver/PERFORMANCE.md.
struct HomeShortcuts {
  bool no_gravity = true;    // no kick, resting speed 0
  bool no_walls = true;      // no per-ball wall screen or wall contacts
  bool equal_radii = true;   // one radius: no radius array, the pair screen reads no radii
  bool equal_masses = true;  // one inverse mass: no mass array
  bool no_pairs = true;      // fewer than two balls: no broad phase at all
  bool elastic = true;       // restitution exactly 1 and no resting speed (no gravity): no contact pass
};

// How `home` treats resting contact in scenes with gravity (HomeSettings::resting): `automatic`
// ("auto", the default profile's) is resolved to one of the others when the engine is built.
enum class RestingMethod { automatic, events, soft };

// The user settings (every field above "Internal") are declared, bounded and documented once, in
// home.cpp's settings table: a new one is its field here and its row there.
struct HomeSettings {
  /// Most Gauss-Seidel sweeps of the contact pass before the drift; it stops early once every
  /// contact is within the velocity tolerance. Too few leaves resting piles to the event loop
  /// (cluster solves); more costs time only where a pile needs it. (count)
  int contact_iterations = 50;
  /// Normal approach speed below which an impact is treated as resting contact (restitution 0).
  /// Negative means 2 |g| dt: slower than two steps of gravity is a ball settling, not a bounce.
  /// Zero gravity gives 0: every impact bounces with the scene's restitution. (m/s)
  double rest_velocity = -1;
  /// Gap below which two balls (or a ball and a wall) count as touching, as a fraction of the
  /// radius sum (or the radius). An approach that closes less than this over a step is round-off,
  /// not motion. (dimensionless)
  double contact_slop = 1e-6;
  /// Safety valve: more events than this per ball in one step is reported as a failure instead of
  /// running on (it would mean an inelastic collapse the contact pass did not resolve). (count)
  int max_events_per_ball = 1000;
  /// How balls that rest on each other are solved: "soft", the soft step (core/solver/soft_step.h)
  /// over every contact, in scenes with gravity; "events", a contact pass at the start of the step,
  /// then exact event-driven motion with resting clusters solved where they form; "auto", the
  /// default profile's, soft where balls pile up (gravity, a box and two balls or more) with
  /// substeps and stiffness derived from `overlap` (core/solver/home_method.h), events elsewhere.
  /// Scenes without gravity always run the event-driven path, exact between collisions.
  RestingMethod resting = RestingMethod::events;
  /// resting = "auto": the largest overlap the soft step is built for, as a fraction of the
  /// smallest radius; 0 takes the scene's accuracy spec's (scenarios/README.md, "Accuracy").
  /// Substeps or contact_hertz given as settings win over what it derives. (fraction of the radius)
  double overlap = 0;
  /// The soft step's substeps, sweeps, push-out stiffness, damping and speed (resting = "soft").
  SoftStepSettings soft;
  /// The soft step fixes each contact's normal for its step, which holds while the balls move a
  /// small part of their size: a step in which the fastest ball would move more than max_stride of
  /// the smallest radius is cut into parts that do not, at most max_parts (beyond that, the balls
  /// move further per part). (radii, count)
  double max_stride = 0.5;
  int max_parts = 64;
  /// Sleeping (resting = "soft"), by islands as in Box2D (b2BodyDef sleepThreshold, b2_timeToSleep):
  /// balls joined by contacts that push form an island; an island whose every ball has been slower
  /// than sleep_speed for sleep_time stops (velocities set to 0) and is not stepped; it holds the
  /// balls touching it as a wall would, and wakes whole when a ball that can touch one of its balls
  /// within the step moves faster than sleep_speed relative to it. 0, the default, never sleeps: as
  /// for every engine in the harness (each adapter's README), a slow ball is not frozen unless a
  /// run asks for it. (m/s, s)
  double sleep_speed = 0;
  double sleep_time = 0.5;

  // Internal, not user settings (not in settings(), not readable with --set): they change how
  // fast, never what, the solver computes.
  HomeShortcuts allow;  // shortcuts that may be taken (all, unless a test or benchmark clears one)
  int threads = 0;      // threads for the per-ball loops; 0: all cores from 100 000 balls, else 1
  int reorder_steps = -1;  // renumber balls in cell order every this many steps; 0 never; -1: 16 from 10 000 balls
  // Elastic scenes' neighbour list: its skin lets the fastest ball at the build move for this many
  // steps (shorter lists rebuild more often, longer ones screen more pairs: 2 is the fastest at 10^4
  // gas balls).
  double list_steps = 2.0;
};

EngineEntry home_engine();

// The engine with explicit settings, for tests and benchmarks that force the general path.
std::unique_ptr<Engine> make_home(const Scene& scene, const HomeSettings& settings);

}  // namespace ballbench

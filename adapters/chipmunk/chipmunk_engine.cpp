#include "chipmunk/chipmunk_engine.h"

#include <chipmunk/chipmunk.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"

namespace ballbench {
namespace {

static_assert(std::is_same_v<cpFloat, double>, "ballbench needs Chipmunk built with CP_USE_DOUBLES (cpFloat = double)");


// What the library printed on stdout while the first space of this process was created: Debian's
// libchipmunk is built without NDEBUG, so cpSpaceInit prints "Initializing cpSpace - Chipmunk
// v7.0.3 (Debug Enabled)" and a second line once per process. Empty for a release build. Forked
// children inherit it, as they inherit the library's own once-only flag.
std::string& debug_banner() {
  static std::string banner;
  return banner;
}

// cpSpaceNew with the library's debug banner kept off stdout, which carries ballbench's tables and
// may carry its JSON (--json /dev/stdout). The banner is printed with printf, so fd 1 is pointed at
// a pipe for the call: stdio's buffer is flushed first (nothing printed before is lost) and again
// before fd 1 is restored (the banner, buffered when stdout is a pipe or a file, goes into the pipe
// rather than later to the real stdout). What arrived is kept in debug_banner(). The pipe's write
// end is non-blocking, so a library that printed more than a pipe holds would lose text, never
// hang. If fd 1 is closed there is nothing to protect and the call is made as it is.
cpSpace* new_space_quietly() {
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  std::cout.flush();
  std::fflush(stdout);
  const int saved = ::dup(STDOUT_FILENO);
  if (saved < 0) return cpSpaceNew();
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0 || ::fcntl(fds[1], F_SETFL, O_NONBLOCK) != 0 || ::dup2(fds[1], STDOUT_FILENO) < 0) {
    const int err = errno;
    ::close(saved);
    throw std::runtime_error(
        fmt::format("chipmunk: cannot keep the library's debug banner off stdout: {}", std::strerror(err)));
  }
  ::close(fds[1]);
  cpSpace* space = cpSpaceNew();
  std::fflush(stdout);
  ::dup2(saved, STDOUT_FILENO);  // the last write end of the pipe closes here
  ::close(saved);
  std::string printed;
  char buf[512];
  for (ssize_t got; (got = ::read(fds[0], buf, sizeof buf)) > 0 || (got < 0 && errno == EINTR);)
    if (got > 0) printed.append(buf, static_cast<size_t>(got));
  ::close(fds[0]);
  if (debug_banner().empty()) debug_banner() = printed;
  return space;
}

// Chipmunk's own defaults, read from a space created for the purpose (cpSpaceInit sets them).
struct SpaceDefaults {
  int iterations;
  double collision_slop, collision_bias;
  cpTimestamp collision_persistence;
  double idle_speed_threshold, sleep_time_threshold, damping;
};

const SpaceDefaults& space_defaults() {
  static const SpaceDefaults d = [] {
    cpSpace* s = new_space_quietly();
    const SpaceDefaults out{cpSpaceGetIterations(s),        cpSpaceGetCollisionSlop(s),
                            cpSpaceGetCollisionBias(s),     cpSpaceGetCollisionPersistence(s),
                            cpSpaceGetIdleSpeedThreshold(s), cpSpaceGetSleepTimeThreshold(s),
                            cpSpaceGetDamping(s)};
    cpSpaceFree(s);
    return out;
  }();
  return d;
}

std::string version_string() {
#if defined(CP_VERSION_MAJOR) && defined(CP_VERSION_MINOR) && defined(CP_VERSION_RELEASE)
  return fmt::format("{}.{}.{}", CP_VERSION_MAJOR, CP_VERSION_MINOR, CP_VERSION_RELEASE);
#else
  return cpVersionString;
#endif
}

// chipmunk's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings chipmunk` come from these rows.
const SettingsTable<ChipmunkSettings>& chipmunk_settings_table() {
  using S = ChipmunkSettings;
  static const SettingsTable<S> table(
      "chipmunk",
      {// cpSpaceSetIterations asserts iterations > 0 (an abort, not an error), so it is refused here.
       setting("iterations", &S::iterations, at_least(1), "count",
               "sequential-impulse sweeps over all contacts per step"),
       setting("collision_slop", &S::collision_slop, at_least(0, "m"), "m", "overlap the solver leaves alone"),
       // The manual: "Valid values are in the range from 0 to 1, but using 0 is not recommended".
       setting("collision_bias", &S::collision_bias,
               within(0, 1).says("must be from 0 to 1 (the fraction of overlap left after 1 s)"), "1",
               "fraction of the overlap beyond the slop left after 1 s"),
       setting("collision_persistence", &S::collision_persistence, at_least(1, "steps a contact is remembered"),
               "count", "steps a contact's impulse is kept after it ends"),
       setting("wall_radius", &S::wall_radius,
               bound([](double r) { return std::isfinite(r); }, "",
                     "must be a number of metres (negative: derived from the box)"),
               "m", "radius of the wall segments; negative: derived from the box"),
       choice("spatial_index", &S::spatial_index, {{SpatialIndex::bbtree, "bbtree"}, {SpatialIndex::hash, "hash"}},
              "broad phase: bounding-box tree or spatial hash"),
       setting("hash_cell", &S::hash_cell, above(0, "m"), "m", "spatial hash cell edge"),
       setting("hash_count", &S::hash_count, at_least(1), "count", "spatial hash's least number of cells"),
       setting("allow_sleep", &S::allow_sleep, any_value, "", "groups idle for sleep_time_threshold freeze"),
       setting("sleep_time_threshold", &S::sleep_time_threshold, above(0, "s"), "s", "idle time before a group sleeps"),
       setting("idle_speed_threshold", &S::idle_speed_threshold, at_least(0, "m/s; 0 lets Chipmunk derive it"), "m/s",
               "speed below which a body is idle; 0: |g| dt")});
  return table;
}

class ChipmunkEngine final : public Engine {
 public:
  ChipmunkEngine(const Scene& scene, const ChipmunkSettings& s)
      : s_(s), dt_(scene.dt), rotation_(scene.features().rotation), space_(new_space_quietly()) {
    inertia_label_ = fmt::format("{} m r^2 ({})", inertia_factor(scene.inertia), inertia_name(scene.inertia));
    cpSpaceSetIterations(space_, s.iterations);
    cpSpaceSetCollisionSlop(space_, s.collision_slop);
    cpSpaceSetCollisionBias(space_, s.collision_bias);
    cpSpaceSetCollisionPersistence(space_, static_cast<cpTimestamp>(s.collision_persistence));
    cpSpaceSetGravity(space_, cpv(scene.gravity.x(), scene.gravity.y()));
    cpSpaceSetDamping(space_, 1.0);  // no damping (Chipmunk's default)
    cpSpaceSetSleepTimeThreshold(space_, s.allow_sleep ? s.sleep_time_threshold : INFINITY);
    cpSpaceSetIdleSpeedThreshold(space_, s.idle_speed_threshold);
    if (s.spatial_index == SpatialIndex::hash) cpSpaceUseSpatialHash(space_, s.hash_cell, s.hash_count);
    // Chipmunk multiplies the two shapes' elasticities and frictions (cpArbiter: e = a->e * b->e,
    // u = a->u * b->u), so every shape, walls included, gets the square root: each contact then
    // uses the scene's value.
    elasticity_ = std::sqrt(scene.restitution);
    friction_ = std::sqrt(scene.friction);
    if (scene.container.kind == ContainerKind::Box) add_walls(scene);
    bodies_.reserve(scene.n());
    shapes_.reserve(shapes_.size() + scene.n());
    for (int i = 0; i < scene.n(); ++i) add_ball(scene, i);
  }

  ~ChipmunkEngine() override {
    // cpSpaceFree frees neither bodies nor shapes, and removing them one by one first costs O(n)
    // each; freeing the space first touches the bodies (cpSpaceDestroy wakes them) but nothing after.
    cpSpaceFree(space_);
    for (cpShape* shape : shapes_) cpShapeFree(shape);
    for (cpBody* body : bodies_) cpBodyFree(body);
  }

  ChipmunkEngine(const ChipmunkEngine&) = delete;
  ChipmunkEngine& operator=(const ChipmunkEngine&) = delete;

  void step(double dt) override {
    cpSpaceStep(space_, dt);
    t_ += dt;
  }

  void read(State& out) const override {
    const int n = static_cast<int>(bodies_.size());
    out.t = t_;
    out.resize(n, rotation_);
    for (int i = 0; i < n; ++i) {
      // The circle sits on the body's centre of gravity, so the body position is the ball centre.
      const cpVect p = cpBodyGetPosition(bodies_[i]);
      const cpVect v = cpBodyGetVelocity(bodies_[i]);
      out.pos(i, 0) = p.x, out.pos(i, 1) = p.y;
      out.vel(i, 0) = v.x, out.vel(i, 1) = v.y;
      if (rotation_) out.w(i) = cpBodyGetAngularVelocity(bodies_[i]), out.angle(i) = cpBodyGetAngle(bodies_[i]);
    }
  }

  nlohmann::json settings() const override {
    // The solver's values as the space holds them, so the record is what is in force.
    const double bias = cpSpaceGetCollisionBias(space_);
    nlohmann::json j = chipmunk_settings_table().json(s_);
    // The solver's values as the space holds them, so the record is what is in force.
    j["iterations"] = cpSpaceGetIterations(space_);
    j["collision_slop"] = cpSpaceGetCollisionSlop(space_);
    j["collision_bias"] = bias;
    j["collision_persistence"] = cpSpaceGetCollisionPersistence(space_);
    j["wall_radius"] = wall_radius_;
    j["idle_speed_threshold"] = cpSpaceGetIdleSpeedThreshold(space_);
    j["compile_time"] = {{"real", "float64"},
                         {"version_string", cpVersionString},
                         // The library announced itself as a debug build: assertions are compiled
                         // in, and a failed one aborts the process.
                         {"debug_build", debug_banner().find("Debug Enabled") != std::string::npos}};
    // What the knobs mean for this scene.
    j["derived"] = {{"sleeping", std::isfinite(cpSpaceGetSleepTimeThreshold(space_))},
                    {"damping", cpSpaceGetDamping(space_)},                   // 1: none
                    {"overlap_removed_per_step", 1.0 - std::pow(bias, dt_)},  // of the depth beyond the slop
                    {"shape_elasticity", elasticity_},
                    {"shape_friction", friction_},
                    {"moment_of_inertia", inertia_label_}};
    return j;
  }

 private:
  // Four static segments on the space's static body, of radius wall_radius (0: lines on the
  // container's bounds), each set back by its radius so its surface lies on the bound.
  void add_walls(const Scene& scene) {
    cpBody* ground = cpSpaceGetStaticBody(space_);
    const Eigen::Vector2d extent = scene.container.max - scene.container.min;
    wall_radius_ = s_.wall_radius >= 0 ? s_.wall_radius : std::max(1.0, 0.5 * extent.maxCoeff());
    const double w = wall_radius_;
    const double x0 = scene.container.min.x() - w, y0 = scene.container.min.y() - w;
    const double x1 = scene.container.max.x() + w, y1 = scene.container.max.y() + w;
    const cpVect corners[] = {cpv(x0, y0), cpv(x1, y0), cpv(x1, y1), cpv(x0, y1)};
    for (int k = 0; k < 4; ++k) {
      cpShape* wall = cpSegmentShapeNew(ground, corners[k], corners[(k + 1) % 4], w);
      cpShapeSetElasticity(wall, elasticity_);
      cpShapeSetFriction(wall, friction_);
      shapes_.push_back(cpSpaceAddShape(space_, wall));
    }
  }

  void add_ball(const Scene& scene, int i) {
    const double r = scene.radius(i), m = scene.mass(i);
    // The scene's moment k m r^2 about the centre; Chipmunk's own for a solid disc,
    // cpMomentForCircle(m, 0, r, 0), is m r^2 / 2, k = 1/2.
    cpBody* body = cpSpaceAddBody(space_, cpBodyNew(m, scene.moment_of_inertia(i)));
    cpBodySetPosition(body, cpv(scene.initial.pos(i, 0), scene.initial.pos(i, 1)));
    cpBodySetVelocity(body, cpv(scene.initial.vel(i, 0), scene.initial.vel(i, 1)));
    cpBodySetAngularVelocity(body, scene.spin(i));
    bodies_.push_back(body);
    // Added after the body is placed, so the spatial index files it where it is.
    cpShape* shape = cpCircleShapeNew(body, r, cpvzero);
    cpShapeSetElasticity(shape, elasticity_);
    cpShapeSetFriction(shape, friction_);
    shapes_.push_back(cpSpaceAddShape(space_, shape));
  }

  ChipmunkSettings s_;
  double dt_;                    // the scene's step (s), for the derived bias rate
  bool rotation_;                // the scene rotates: spins are read back
  std::string inertia_label_;
  cpSpace* space_;               // owns neither bodies nor shapes (freed in the destructor)
  double elasticity_ = 1, friction_ = 0;  // per shape: square roots of the scene's values
  double wall_radius_ = 0;       // in force (m): the setting, or the thickness derived from the box
  std::vector<cpBody*> bodies_;  // scene order
  std::vector<cpShape*> shapes_; // walls, then balls
  double t_ = 0;
};

}  // namespace

ChipmunkSettings chipmunk_profile(const std::string& profile, const Scene& scene) {
  const SpaceDefaults& d = space_defaults();
  ChipmunkSettings s;
  s.iterations = d.iterations;
  s.collision_slop = d.collision_slop;
  s.collision_bias = d.collision_bias;
  s.collision_persistence = static_cast<int>(d.collision_persistence);
  s.spatial_index = SpatialIndex::bbtree;  // cpSpaceInit's index: cpBBTreeNew
  s.idle_speed_threshold = d.idle_speed_threshold;
  s.allow_sleep = std::isfinite(d.sleep_time_threshold);
  // The hash's size, used by tuned and by `--set chipmunk.spatial_index=hash`: cells of the largest
  // diameter (the manual: "the average collision shape size"; LogoSmash takes 2.0 for balls of
  // radius 0.95), and about 10 cells per shape (the manual: "~10x the number of objects").
  const double largest = scene.n() > 0 ? scene.radius.maxCoeff() : 0.5;
  const double smallest = scene.n() > 0 ? scene.radius.minCoeff() : 0.5;
  s.hash_cell = 2 * largest;
  s.hash_count = static_cast<int>(std::min<long long>(10LL * std::max(scene.n(), 1), 1LL << 30));
  if (profile == "stock") return s;
  if (profile == "tuned") {
    s.iterations = 30;                     // Chipmunk's stacking demos; see the README
    s.collision_slop = 0.01 * smallest;    // overlap left alone: 1% of the smallest radius
    s.spatial_index = SpatialIndex::hash;  // "1000s of objects that are all the same size"
    return s;                              // collision_bias: the default (see the README)
  }
  throw InputError(fmt::format("chipmunk: unknown profile '{}' (known: {})", profile, fmt::join(kExternalProfiles, ", ")));
}

EngineEntry chipmunk_engine() {
  EngineInfo info;
  info.name = "chipmunk";
  info.version = version_string();  // CP_VERSION_* of the installed headers (Debian 7.0.3-5)
  info.limits =
      "double; Debian's debug build (assertions on: a failed one aborts the run, reported as crashed); no CCD: a ball "
      "that moves past a wall's line or through a ball within one step tunnels; overlap up to collision_slop is left "
      "(stock 0.1 m, tuned 1% of the smallest radius) and the rest removed at 1 - bias^dt per step (bias 0.0018: 6% "
      "per step at dt 0.01), by position only; restitution exact for isolated contacts, approximate for simultaneous "
      "ones (iterative solver)";
  info.summary = "Chipmunk2D (double sequential impulses, no CCD); tuned: spatial hash, 30 iterations, small slop";
  info.profiles = kExternalProfiles;
  info.settings = chipmunk_settings_table().describe();
  info.sweep_knobs = {{"iterations", {5, 10, 30}}, {"spatial_index", {"bbtree", "hash"}}};
  info.caps.open_space = true;
  info.caps.gravity = true;
  info.caps.per_ball_radius = true;
  info.caps.per_ball_mass = true;
  // No restitution threshold: every contact bounces with e times the approach speed it had before
  // this step's gravity (cpArbiterPreStep). Simultaneous contacts are approximate, as in any
  // iterative solver (README).
  info.caps.any_restitution = true;
  info.caps.friction = true;  // Coulomb friction on every shape; balls rotate with the scene's moment
  info.caps.continuous_collision = false;  // discrete overlap tests only: fast balls tunnel
  info.caps.deterministic = true;          // cpSpace (not cpHastySpace) steps on one thread
  return {info, [](const Scene& scene, const std::string& profile, const nlohmann::json& overrides) {
            ChipmunkSettings s = chipmunk_profile(profile, scene);
            chipmunk_settings_table().read(overrides, s);
            return std::unique_ptr<Engine>(std::make_unique<ChipmunkEngine>(scene, s));
          }};
}

}  // namespace ballbench

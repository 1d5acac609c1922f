#include "box2d/box2d_engine.h"

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <box2d/box2d.h>
#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"

namespace ballbench {
namespace {

// The b2_common.h constants (Box2D 2.4.1) that bound what a ball scene can get out of Box2D. They
// are #defines compiled into libbox2d, so settings() reports them and an override is refused with
// the reason instead of the generic "unknown setting".
struct CompileTimeConstant {
  const char* key;    // as listed under settings()["compile_time"]
  const char* macro;  // the name in b2_common.h
  double value;       // the decimal b2_common.h writes (0.2, not float's 0.200000003)
  const char* unit;
  bool count = false; // a whole number (listed as an integer)
};

// A float constant as its shortest round-trip decimal, which is how the header spells it.
double as_written(float f) { return std::stod(fmt::format("{}", f)); }

const std::vector<CompileTimeConstant>& compile_time_constants() {
  static const std::vector<CompileTimeConstant> all = {
      {"max_translation", "b2_maxTranslation", as_written(b2_maxTranslation), "m per step"},
      {"linear_slop", "b2_linearSlop", as_written(b2_linearSlop), "m"},
      {"polygon_radius", "b2_polygonRadius", as_written(b2_polygonRadius), "m"},
      {"max_linear_correction", "b2_maxLinearCorrection", as_written(b2_maxLinearCorrection), "m per step"},
      {"baumgarte", "b2_baumgarte", as_written(b2_baumgarte), "1"},
      {"toi_baumgarte", "b2_toiBaumgarte", as_written(b2_toiBaumgarte), "1"},
      {"max_sub_steps", "b2_maxSubSteps", b2_maxSubSteps, "TOI events per contact per step", true},
      {"max_toi_contacts", "b2_maxTOIContacts", b2_maxTOIContacts, "contacts per TOI island", true},
      {"time_to_sleep", "b2_timeToSleep", as_written(b2_timeToSleep), "s"},
      {"linear_sleep_tolerance", "b2_linearSleepTolerance", as_written(b2_linearSleepTolerance), "m/s"},
  };
  return all;
}

void refuse_compile_time_overrides(const nlohmann::json& overrides) {
  if (!overrides.is_object()) return;
  if (overrides.contains("compile_time"))
    throw InputError("settings.box2d.compile_time: read-only; these are compile-time constants of Box2D 2.4.1");
  for (const auto& c : compile_time_constants())
    if (overrides.contains(c.key))
      throw InputError(fmt::format("settings.box2d.{}: {} is a compile-time constant of Box2D 2.4.1 ({} {}) and "
                                   "cannot be changed at run time",
                                   c.key, c.macro, c.value, c.unit));
}

// What the linked library calls itself. Box2D 2.4.1 shipped with b2_version left at {2, 4, 0}
// (src/common/b2_settings.cpp), so this is recorded beside the package's version, not used as it.
std::string b2_version_string() {
  return fmt::format("{}.{}.{}", b2_version.major, b2_version.minor, b2_version.revision);
}

// box2d's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings box2d` come from these rows (the compile-time constants above are not settings).
const SettingsTable<Box2dSettings>& box2d_settings_table() {
  using S = Box2dSettings;
  static const SettingsTable<S> table(
      "box2d",
      {setting("velocity_iterations", &S::velocity_iterations, at_least(1, "0 solves no contact at all"), "count",
               "sequential-impulse sweeps over all contacts per step"),
       setting("position_iterations", &S::position_iterations, at_least(0), "count",
               "sweeps pushing overlaps apart per step"),
       // Box2D applies restitution when the approach speed exceeds the threshold; a negative one
       // would push apart contacts that are already separating.
       setting("restitution_threshold", &S::restitution_threshold, at_least(0, "m/s"), "m/s",
               "approach speed below which a contact does not bounce"),
       setting("bullet", &S::bullet, any_value, "", "balls are bullets: time of impact against each other too"),
       setting("allow_sleep", &S::allow_sleep, any_value, "", "bodies slow for b2_timeToSleep freeze"),
       choice("fixed_rotation", &S::fixed_rotation,
              {{FixedRotation::automatic, "auto"}, {FixedRotation::always, "always"}, {FixedRotation::never, "never"}},
              "balls do not turn: auto, when the scene is frictionless"),
       setting("warm_starting", &S::warm_starting, any_value, "", "each solve starts from the last step's impulses"),
       setting("continuous_physics", &S::continuous_physics, any_value, "", "time-of-impact handling at all"),
       setting("sub_stepping", &S::sub_stepping, any_value, "",
               "at most one time-of-impact event per step (debugging)")});
  return table;
}

class Box2dEngine final : public Engine {
 public:
  Box2dEngine(const Scene& scene, const Box2dSettings& s)
      : s_(s),
        world_(b2Vec2(static_cast<float>(scene.gravity.x()), static_cast<float>(scene.gravity.y()))),
        dt_(scene.dt),
        rotation_(scene.features().rotation),
        fixed_rotation_(s.fixed_rotation == FixedRotation::always ||
                        (s.fixed_rotation == FixedRotation::automatic && !rotation_)) {
    inertia_label_ = fmt::format("{} m r^2 ({})", inertia_factor(scene.inertia), inertia_name(scene.inertia));
    world_.SetAllowSleeping(s.allow_sleep);
    world_.SetWarmStarting(s.warm_starting);
    world_.SetContinuousPhysics(s.continuous_physics);
    world_.SetSubStepping(s.sub_stepping);
    if (scene.container.kind == ContainerKind::Box) add_walls(scene);
    balls_.reserve(scene.n());
    for (int i = 0; i < scene.n(); ++i) add_ball(scene, i);
  }

  void step(double dt) override {
    world_.Step(static_cast<float>(dt), s_.velocity_iterations, s_.position_iterations);
    t_ += dt;
  }

  void read(State& out) const override {
    const int n = static_cast<int>(balls_.size());
    out.t = t_;
    out.resize(n, rotation_);
    for (int i = 0; i < n; ++i) {
      // The circle sits on the body origin, so the origin is the centre of mass and the ball centre.
      const b2Vec2& p = balls_[i]->GetPosition();
      const b2Vec2& v = balls_[i]->GetLinearVelocity();
      out.pos(i, 0) = p.x, out.pos(i, 1) = p.y;
      out.vel(i, 0) = v.x, out.vel(i, 1) = v.y;
      if (rotation_) out.w(i) = balls_[i]->GetAngularVelocity(), out.angle(i) = balls_[i]->GetAngle();
    }
  }

  nlohmann::json settings() const override {
    nlohmann::json constants = nlohmann::json::object();
    for (const auto& c : compile_time_constants())
      constants[c.key] = c.count ? nlohmann::json(static_cast<int>(c.value)) : nlohmann::json(c.value);
    constants["real"] = "float32";
    nlohmann::json j = box2d_settings_table().json(s_);
    j["compile_time"] = constants;
    // What the knobs and constants mean for this scene.
    j["derived"] = {{"b2_version", b2_version_string()},
                    {"fixed_rotation", fixed_rotation_},
                    {"moment_of_inertia", inertia_label_},
                    {"max_speed", b2_maxTranslation / dt_}};  // m/s: faster balls are slowed to it
    return j;
  }

 private:
  b2FixtureDef material(const b2Shape& shape, double friction, double restitution, double density) const {
    b2FixtureDef f;
    f.shape = &shape;
    f.density = static_cast<float>(density);
    // Box2D mixes friction as sqrt(fa fb), restitution as max(ea, eb) and the threshold as
    // min(ta, tb) (b2_contact.h); the same value on every fixture makes each contact use it as is.
    f.friction = static_cast<float>(friction);
    f.restitution = static_cast<float>(restitution);
    f.restitutionThreshold = static_cast<float>(s_.restitution_threshold);
    return f;
  }

  // Four thick static boxes around the container. Box2D rounds every polygon by b2_polygonRadius
  // (b2_polygon_shape.h: "For polygonal shapes this must be b2_polygonRadius"), so each inner face
  // is set back by that much and the rounded surface a ball touches lies on the scene's bound.
  // Thick boxes rather than edges: a ball pushed past a thin two-sided edge would be ejected on the
  // wrong side, while a box pushes it back in until its centre crosses the box's middle.
  void add_walls(const Scene& scene) {
    const Eigen::Vector2d lo = scene.container.min.array() - b2_polygonRadius;
    const Eigen::Vector2d hi = scene.container.max.array() + b2_polygonRadius;
    const double thick = std::max(1.0, 0.5 * (hi - lo).maxCoeff());  // m
    b2BodyDef def;  // static, at the origin
    b2Body* body = world_.CreateBody(&def);
    auto slab = [&](double x0, double y0, double x1, double y1) {
      b2PolygonShape box;
      box.SetAsBox(static_cast<float>(0.5 * (x1 - x0)), static_cast<float>(0.5 * (y1 - y0)),
                   b2Vec2(static_cast<float>(0.5 * (x0 + x1)), static_cast<float>(0.5 * (y0 + y1))), 0.0f);
      const b2FixtureDef f = material(box, scene.friction, scene.restitution, 0.0);
      body->CreateFixture(&f);
    };
    // Left and right run the full height plus the corners, so no gap opens where walls meet.
    slab(lo.x() - thick, lo.y() - thick, lo.x(), hi.y() + thick);
    slab(hi.x(), lo.y() - thick, hi.x() + thick, hi.y() + thick);
    slab(lo.x(), lo.y() - thick, hi.x(), lo.y());
    slab(lo.x(), hi.y(), hi.x(), hi.y() + thick);
  }

  void add_ball(const Scene& scene, int i) {
    const double r = scene.radius(i), m = scene.mass(i);
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(static_cast<float>(scene.initial.pos(i, 0)), static_cast<float>(scene.initial.pos(i, 1)));
    def.linearVelocity.Set(static_cast<float>(scene.initial.vel(i, 0)), static_cast<float>(scene.initial.vel(i, 1)));
    def.linearDamping = 0.0f;
    def.angularDamping = 0.0f;
    def.allowSleep = s_.allow_sleep;
    def.awake = true;
    def.bullet = s_.bullet;
    def.fixedRotation = fixed_rotation_;
    def.angularVelocity = static_cast<float>(scene.spin(i));
    b2Body* body = world_.CreateBody(&def);

    b2CircleShape circle;
    circle.m_radius = static_cast<float>(r);
    // Box2D's circle mass is density * b2_pi * r^2 (b2CircleShape::ComputeMass).
    const b2FixtureDef f = material(circle, scene.friction, scene.restitution, m / (b2_pi * r * r));
    body->CreateFixture(&f);
    // The float product above can miss the scene's mass by an ulp; pin the mass, and the scene's
    // inertia k m r^2 about the centre (Box2D's own is the disk's, k = 1/2; ignored when rotation
    // is fixed).
    b2MassData mass;
    mass.mass = static_cast<float>(m);
    mass.center.SetZero();
    mass.I = static_cast<float>(scene.moment_of_inertia(i));
    body->SetMassData(&mass);
    balls_.push_back(body);
  }

  Box2dSettings s_;
  b2World world_;               // owns every body and fixture
  double dt_;                   // the scene's step (s), for the derived speed limit
  bool rotation_;                // the scene rotates: spins are read back
  bool fixed_rotation_;
  std::string inertia_label_;
  std::vector<b2Body*> balls_;  // scene order
  double t_ = 0;                // kept in double: Box2D only sees the float step
};

}  // namespace

Box2dSettings box2d_profile(const std::string& profile) {
  Box2dSettings s;  // the struct's defaults are "tuned"
  if (profile == "tuned") return s;
  if (profile == "stock") {
    // The testbed's defaults (testbed/settings.h: 8 velocity, 3 position iterations) and the
    // library's own fixture and body defaults.
    s.velocity_iterations = 8;
    s.position_iterations = 3;
    s.restitution_threshold = b2FixtureDef().restitutionThreshold;
    s.bullet = b2BodyDef().bullet;
    return s;
  }
  throw InputError(fmt::format("box2d: unknown profile '{}' (known: tuned, stock)", profile));
}

EngineEntry box2d_engine() {
  EngineInfo info;
  info.name = "box2d";
  info.version = BALLBENCH_BOX2D_VERSION;  // see b2_version_string()
  info.limits =
      "float32; b2_maxTranslation 2 m per step (speed cap 200 m/s at dt 0.01); contacts rest up to 3 x b2_linearSlop "
      "(1.5 cm) deep; restitution only above restitutionThreshold (stock 1 m/s, tuned 0) and approximate for "
      "multiple contacts; TOI against other balls only for bullets (tuned), capped at 8 sub-steps and 32 contacts; "
      "these constants are compiled into 2.4.1";
  info.summary = "Box2D (float32 sequential impulses + TOI); tuned: elastic fast balls, stock: game defaults";
  info.profiles = kExternalProfiles;
  info.speed_cap = [](double dt, const nlohmann::json&) {  // one b2World::Step per scene step
    return std::optional<SpeedCap>(SpeedCap{b2_maxTranslation / dt, "b2_maxTranslation (2 m per step)"});
  };
  // Solver sweeps and both kinds of continuous collision (b2World::SetContinuousPhysics for
  // ball-wall, b2BodyDef::bullet for ball-ball).
  info.settings = box2d_settings_table().describe();
  info.sweep_knobs = {{"velocity_iterations", {2, 8, 32}},
                      {"position_iterations", {1, 3, 10}},
                      {"continuous_physics", {false, true}},
                      {"bullet", {false, true}}};
  info.caps.open_space = true;
  info.caps.gravity = true;
  info.caps.per_ball_radius = true;
  info.caps.per_ball_mass = true;
  // Capabilities are per engine, not per profile: stock ignores restitution below 1 m/s, and even
  // tuned makes the restitution of simultaneous contacts approximate (iterative solver).
  info.caps.any_restitution = false;
  // Balls never pass through walls (TOI against static bodies is always on), and in tuned they are
  // bullets against each other too. Stock can tunnel ball through ball: the tunnelling metric shows it.
  info.caps.continuous_collision = true;
  info.caps.deterministic = true;  // single-threaded, no randomness: same build and input, same result
  return {info, [](const Scene& scene, const std::string& profile, const nlohmann::json& overrides) {
            Box2dSettings s = box2d_profile(profile);
            refuse_compile_time_overrides(overrides);
            box2d_settings_table().read(overrides, s);
            return std::unique_ptr<Engine>(std::make_unique<Box2dEngine>(scene, s));
          }};
}

}  // namespace ballbench

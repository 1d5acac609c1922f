#include "bullet/bullet_engine.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"

namespace ballbench {
namespace {

// Bullet works in float (btScalar); the harness in double. Conversions happen only here.
btVector3 to_bt(double x, double y) { return btVector3(btScalar(x), btScalar(y), btScalar(0)); }

// "3.24" from btGetVersion()'s 324.
std::string bullet_version() {
  const int v = btGetVersion();
  return fmt::format("{}.{:02d}", v / 100, v % 100);
}

// bullet's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings bullet` come from these rows.
const SettingsTable<BulletSettings>& bullet_settings_table() {
  using S = BulletSettings;
  static const SettingsTable<S> table(
      "bullet",
      {setting("solver_iterations", &S::solver_iterations, at_least(1).says("must be at least 1"), "count",
               "sequential-impulse sweeps per step"),
       setting("substeps", &S::substeps, at_least(1).says("must be at least 1"), "count",
               "Bullet's internal steps per step"),
       setting("split_impulse", &S::split_impulse, any_value, "", "push-out by a velocity thrown away after the step"),
       setting("split_impulse_penetration_threshold", &S::split_impulse_penetration_threshold, any_value, "m",
               "penetration (negative) deeper than this uses split impulse"),
       setting("erp", &S::erp, any_value, "1", "Baumgarte factor without split impulse, per step"),
       setting("erp2", &S::erp2, any_value, "1", "Baumgarte factor of the split-impulse push, per step"),
       setting("restitution_velocity_threshold", &S::restitution_velocity_threshold, any_value, "m/s",
               "approach speed below which a contact does not bounce"),
       setting("warmstarting_factor", &S::warmstarting_factor, any_value, "1",
               "fraction of last step's impulse applied first"),
       setting("linear_slop", &S::linear_slop, any_value, "m", "penetration the solver leaves uncorrected"),
       setting("contact_processing_threshold", &S::contact_processing_threshold, any_value, "m",
               "contacts farther apart than this are not solved"),
       setting("ccd_motion_threshold", &S::ccd_motion_threshold, at_least(0), "radii",
               "CCD clamps a ball moving more than this per step; 0: off"),
       setting("ccd_swept_sphere_radius", &S::ccd_swept_sphere_radius, within(0, 1).says("must be in [0, 1] radii"),
               "radii", "radius of the core CCD sweeps"),
       setting("speculative_contact_restitution", &S::speculative_contact_restitution, any_value, "",
               "restitution on CCD's predictive contacts")});
  return table;
}

class BulletWorld final : public Engine {
 public:
  BulletWorld(const Scene& scene, const BulletSettings& s)
      : s_(s),
        rotation_(scene.features().rotation),
        inertia_label_(fmt::format("{} m r^2 ({})", inertia_factor(scene.inertia), inertia_name(scene.inertia))),
        angle_(rotation_ ? scene.n() : 0, 0.0),
        dispatcher_(&collision_config_),
        world_(&dispatcher_, &broadphase_, &solver_, &collision_config_) {
    world_.setGravity(btVector3(btScalar(scene.gravity.x()), btScalar(scene.gravity.y()), 0));
    world_.setApplySpeculativeContactRestitution(s_.speculative_contact_restitution);

    btContactSolverInfo& info = world_.getSolverInfo();
    info.m_numIterations = s_.solver_iterations;
    info.m_splitImpulse = s_.split_impulse ? 1 : 0;
    info.m_splitImpulsePenetrationThreshold = btScalar(s_.split_impulse_penetration_threshold);
    info.m_erp = btScalar(s_.erp);
    info.m_erp2 = btScalar(s_.erp2);
    info.m_restitutionVelocityThreshold = btScalar(s_.restitution_velocity_threshold);
    info.m_warmstartingFactor = btScalar(s_.warmstarting_factor);
    info.m_linearSlop = btScalar(s_.linear_slop);

    // Bullet combines a pair's restitution and friction as the product of the two bodies' values
    // (btManifoldResult::calculateCombinedRestitution / ...Friction). Every body, walls included,
    // gets the square root, so every pair gets exactly the scene's value (up to float rounding).
    // A contact-added callback could set the pair value instead, but Bullet's callback hooks are
    // process-wide globals, shared by every world in the process.
    restitution_ = btScalar(std::sqrt(scene.restitution));
    friction_ = btScalar(std::sqrt(scene.friction));

    if (scene.container.kind == ContainerKind::Box) add_walls(scene.container, scene.radius.maxCoeff());
    add_balls(scene);
  }

  ~BulletWorld() override {
    for (auto& body : bodies_) world_.removeRigidBody(body.get());
  }

  void step(double dt) override {
    // One call per internal step, each with maxSubSteps = 1 and fixedTimeStep = timeStep: exactly
    // one step of h per call (Bullet's accumulator goes h - h = 0 every time), never an
    // interpolated one. A single call with maxSubSteps = k could round to k - 1 steps and carry the
    // rest in the float accumulator, and the clamp to k would then drop a step.
    const btScalar h = btScalar(dt / s_.substeps);
    for (int k = 0; k < s_.substeps; ++k) world_.stepSimulation(h, 1, h);
    t_ += dt;
  }

  void read(State& out) const override {
    const int n = static_cast<int>(balls_.size());
    out.resize(n, rotation_);
    out.t = t_;
    for (int i = 0; i < n; ++i) {
      const btVector3& p = balls_[i]->getWorldTransform().getOrigin();
      const btVector3& v = balls_[i]->getLinearVelocity();
      out.pos(i, 0) = p.x(), out.pos(i, 1) = p.y();
      out.vel(i, 0) = v.x(), out.vel(i, 1) = v.y();
      if (!rotation_) continue;
      out.w(i) = balls_[i]->getAngularVelocity().z();
      const btQuaternion q = balls_[i]->getWorldTransform().getRotation();  // about z only
      out.angle(i) = angle_[i] = angle_about_z(q.w(), q.z(), angle_[i]);
    }
  }

  nlohmann::json settings() const override {
    nlohmann::json j = bullet_settings_table().json(s_);
    j["derived"] = {{"moment_of_inertia", inertia_label_}};
    return j;
  }

  double out_of_plane() const override {
    double m = 0;
    for (const btRigidBody* b : balls_) {
      m = std::max(m, std::abs(double(b->getWorldTransform().getOrigin().z())));
      m = std::max(m, std::abs(double(b->getLinearVelocity().z())));
    }
    return m;
  }

 private:
  btRigidBody* add_body(std::unique_ptr<btCollisionShape> shape, double mass, const btVector3& at) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(btScalar(mass), inertia);
    btRigidBody::btRigidBodyConstructionInfo ci(btScalar(mass), nullptr, shape.get(), inertia);
    ci.m_startWorldTransform.setIdentity();
    ci.m_startWorldTransform.setOrigin(at);
    ci.m_linearDamping = 0;
    ci.m_angularDamping = 0;
    ci.m_restitution = restitution_;
    ci.m_friction = friction_;
    shapes_.push_back(std::move(shape));
    bodies_.push_back(std::make_unique<btRigidBody>(ci));
    btRigidBody* body = bodies_.back().get();
    body->setContactProcessingThreshold(btScalar(s_.contact_processing_threshold));
    return body;
  }

  // Four static slabs whose inner faces lie on the box bounds. Each is as thick as the box is
  // wide, so no ball can cross one in a step, and long enough to close the corners with flat
  // faces (Bullet's box shape rounds its own corners by the collision margin).
  void add_walls(const Container& box, double rmax) {
    const Eigen::Vector2d size = box.max - box.min;
    const double t = std::max(size.x(), size.y());  // half thickness (m)
    const double depth = std::max(t, 4 * rmax);     // half extent along z (m)
    const Eigen::Vector2d c = 0.5 * (box.min + box.max);
    auto slab = [&](double cx, double cy, double hx, double hy) {
      auto shape = std::make_unique<btBoxShape>(btVector3(btScalar(hx), btScalar(hy), btScalar(depth)));
      btRigidBody* wall = add_body(std::move(shape), 0.0, to_bt(cx, cy));
      world_.addRigidBody(wall);
    };
    const double hx = 0.5 * size.x() + 2 * t, hy = 0.5 * size.y() + 2 * t;
    slab(box.min.x() - t, c.y(), t, hy);
    slab(box.max.x() + t, c.y(), t, hy);
    slab(c.x(), box.min.y() - t, hx, t);
    slab(c.x(), box.max.y() + t, hx, t);
  }

  void add_balls(const Scene& scene) {
    for (int i = 0; i < scene.n(); ++i) {
      const double r = scene.radius(i);
      btRigidBody* ball = add_body(std::make_unique<btSphereShape>(btScalar(r)), scene.mass(i),
                                   to_bt(scene.initial.pos(i, 0), scene.initial.pos(i, 1)));
      // Held to the plane: no z motion; no rotation unless the scene rotates, and then only about z,
      // with the scene's moment k m r^2 (a btSphereShape's own is the sphere's, k = 2/5).
      ball->setLinearFactor(btVector3(1, 1, 0));
      ball->setAngularFactor(rotation_ ? btVector3(0, 0, 1) : btVector3(0, 0, 0));
      if (rotation_) {
        const btScalar moment = btScalar(scene.moment_of_inertia(i));
        ball->setMassProps(btScalar(scene.mass(i)), btVector3(moment, moment, moment));
        ball->updateInertiaTensor();
        ball->setAngularVelocity(btVector3(0, 0, btScalar(scene.spin(i))));
      }
      ball->setActivationState(DISABLE_DEACTIVATION);
      ball->setLinearVelocity(to_bt(scene.initial.vel(i, 0), scene.initial.vel(i, 1)));
      if (s_.ccd_motion_threshold > 0) {
        ball->setCcdMotionThreshold(btScalar(s_.ccd_motion_threshold * r));
        ball->setCcdSweptSphereRadius(btScalar(s_.ccd_swept_sphere_radius * r));
      }
      world_.addRigidBody(ball);  // after setLinearFactor: the world's gravity is applied here
      balls_.push_back(ball);
    }
  }

  BulletSettings s_;
  bool rotation_;                       // the scene rotates: balls turn about z, spins are read back
  std::string inertia_label_;
  mutable std::vector<double> angle_;   // each ball's unwrapped angle at the last read (rad)
  btScalar restitution_ = 1, friction_ = 0;
  // Declaration order is construction order: the world needs the four parts above it.
  btDefaultCollisionConfiguration collision_config_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;  // walls and balls
  std::vector<btRigidBody*> balls_;                   // scene order
  double t_ = 0;
};

// Reads the overrides on top of a profile's settings.
BulletSettings read_settings(const std::string& profile, const nlohmann::json& overrides) {
  BulletSettings s = bullet_profile(profile);
  bullet_settings_table().read(overrides, s);
  return s;
}

}  // namespace

BulletSettings bullet_profile(const std::string& profile) {
  BulletSettings s;  // Bullet's defaults: the "stock" profile
  if (profile == "stock") return s;
  if (profile != "tuned")
    throw InputError(fmt::format("bullet: unknown profile '{}' (known: tuned, stock)", profile));
  // What Bullet's maintainers recommend for restitution and fast bodies; sources in README.md.
  s.solver_iterations = 50;
  s.split_impulse = true;
  s.split_impulse_penetration_threshold = 0.0;
  s.restitution_velocity_threshold = 0.0;
  s.warmstarting_factor = 0.0;
  s.linear_slop = 0.0;
  s.contact_processing_threshold = 0.0;
  s.ccd_motion_threshold = 1.0;
  s.ccd_swept_sphere_radius = 0.4;
  return s;
}

EngineEntry bullet_engine() {
  EngineInfo info;
  info.name = "bullet";
  info.version = bullet_version();
  info.limits =
      "float; wall contacts are kept up to 8.66 mm before touching and solved early when contact_processing_threshold "
      "is Bullet's default (stock), losing d / dt of bounce; split impulse below its penetration threshold adds "
      "Baumgarte energy (stock -0.04 m); no bounce below restitution_velocity_threshold (stock 0.2 m/s); CCD is "
      "motion clamping of a 0.4 r core against start-of-step positions (tuned only)";
  info.summary = "Bullet Physics (float), 3D spheres held to the plane; sequential impulses";
  info.profiles = kExternalProfiles;
  // Solver sweeps, Bullet's own sub-stepping and CCD off / on (threshold in radii, 0 = off).
  info.settings = bullet_settings_table().describe();
  info.sweep_knobs = {{"solver_iterations", {4, 10, 50}}, {"substeps", {1, 2, 4}}, {"ccd_motion_threshold", {0.0, 1.0}}};
  // As in the default profile, "tuned" (README.md says what "stock" lacks).
  info.caps.any_restitution = true;        // restitution_velocity_threshold = 0
  info.caps.continuous_collision = true;   // CCD clamping: no wall escapes; grazing ball passes remain
  info.caps.deterministic = true;          // single-threaded world, fixed insertion order
  return {info, [](const Scene& scene, const std::string& profile, const nlohmann::json& overrides) {
            return std::unique_ptr<Engine>(std::make_unique<BulletWorld>(scene, read_settings(profile, overrides)));
          }};
}

}  // namespace ballbench

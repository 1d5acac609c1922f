#include "ode/ode_engine.h"

#include <ode/ode.h>
#include <ode/version.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"

namespace ballbench {
namespace {

static_assert(sizeof(dReal) == sizeof(double), "ballbench needs ODE built with double precision (dDOUBLE)");

// dInitODE2 / dCloseODE once per process: a function-local static is initialised exactly once
// (thread-safe since C++11) and closed at exit, after every world is gone. Each thread that uses
// ODE's collision code also needs its own per-thread data; that call is idempotent.
void ensure_ode_ready() {
  struct Library {
    Library() {
      if (!dInitODE2(0)) throw std::runtime_error("ode: dInitODE2 failed");
      // The headers say double; make sure the shared library we linked agrees.
      if (!dCheckConfiguration("ODE_double_precision"))
        throw std::runtime_error(fmt::format("ode: the library is not double precision ({})", dGetConfiguration()));
    }
    ~Library() { dCloseODE(); }
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;
  };
  static Library library;
  if (!dAllocateODEDataForThread(dAllocateMaskAll)) throw std::runtime_error("ode: dAllocateODEDataForThread failed");
}


// ode's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings ode` come from these rows.
const SettingsTable<OdeSettings>& ode_settings_table() {
  using S = OdeSettings;
  static const SettingsTable<S> table(
      "ode",
      {choice("stepper", &S::stepper, {{OdeStepper::step, "step"}, {OdeStepper::quickstep, "quickstep"}},
              "step: exact big-matrix LCP; quickstep: iterative SOR"),
       choice("space", &S::space, {{OdeSpace::sap, "sap"}, {OdeSpace::hash, "hash"}},
              "broad phase: sweep and prune, or ODE's hash space"),
       setting("quickstep_iterations", &S::quickstep_iterations, at_least(1).says("must be at least 1"), "count",
               "quickstep's sweeps per step"),
       setting("quickstep_w", &S::quickstep_w, inside(0, 2).says("must be in (0, 2)"), "1",
               "quickstep's SOR over-relaxation"),
       setting("erp", &S::erp, within(0, 1).says("must be in [0, 1]"), "1",
               "fraction of the penetration removed per step"),
       setting("cfm", &S::cfm, at_least(0).says("must not be negative (the ODE manual: negative CFM is unstable)"),
               "m/N/s", "constraint force mixing: contact softness"),
       setting("bounce_vel", &S::bounce_vel, at_least(0).says("must not be negative (ODE then never bounces)"), "m/s",
               "approach speed below which a contact does not bounce"),
       setting("contact_surface_layer", &S::contact_surface_layer, at_least(0).says("must not be negative"), "m",
               "penetration tolerated before the push-out starts"),
       setting("max_correcting_vel", &S::max_correcting_vel,
               bound([](double v) { return v > 0 || v == -1; }, "> 0 or -1", "must be positive, or -1 for no cap"),
               "m/s", "cap on the push-out speed; -1: none"),
       setting("align_to_plane", &S::align_to_plane, any_value, "",
               "after each step, turn each body back to a rotation about z")});
  return table;
}

class OdeEngine final : public Engine {
 public:
  OdeEngine(const Scene& scene, OdeSettings settings)
      : s_(std::move(settings)),
        n_(scene.n()),
        rotation_(scene.features().rotation),
        inertia_label_(fmt::format("{} m r^2 ({})", inertia_factor(scene.inertia), inertia_name(scene.inertia))),
        angle_(rotation_ ? n_ : 0, 0.0) {
    ensure_ode_ready();
    world_ = dWorldCreate();
    space_ = s_.space == OdeSpace::sap ? dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XYZ) : dHashSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);

    dWorldSetGravity(world_, scene.gravity.x(), scene.gravity.y(), 0.0);
    dWorldSetERP(world_, s_.erp);
    dWorldSetCFM(world_, s_.cfm);
    dWorldSetQuickStepNumIterations(world_, s_.quickstep_iterations);
    dWorldSetQuickStepW(world_, s_.quickstep_w);
    dWorldSetContactSurfaceLayer(world_, s_.contact_surface_layer);
    dWorldSetContactMaxCorrectingVel(world_, s_.max_correcting_vel < 0 ? dInfinity : s_.max_correcting_vel);
    dWorldSetAutoDisableFlag(world_, 0);  // no sleeping: every ball is simulated every step

    // Hash cells from the smallest to the largest ball diameter (cell size 2^level, m).
    if (n_ > 0 && s_.space == OdeSpace::hash) {
      const double dmin = 2 * scene.radius.minCoeff(), dmax = 2 * scene.radius.maxCoeff();
      dHashSpaceSetLevels(space_, static_cast<int>(std::floor(std::log2(dmin))),
                          static_cast<int>(std::ceil(std::log2(dmax))));
    }

    // Every contact shares one surface: the scene's restitution and friction.
    surface_.mode = dContactBounce;
    surface_.bounce = scene.restitution;
    surface_.bounce_vel = s_.bounce_vel;
    surface_.mu = 0;
    if (scene.friction > 0) {
      // Approx1: mu is a Coulomb coefficient (friction bound = mu * normal force); without it ODE
      // reads mu as a force limit in newtons.
      surface_.mode |= dContactApprox1;
      surface_.mu = scene.friction;
    }

    bodies_.reserve(n_);
    for (int i = 0; i < n_; ++i) {
      dBodyID b = dBodyCreate(world_);
      // The scene's moment k m r^2 about every axis (ODE's dMassSetSphereTotal gives the sphere's,
      // k = 2/5); Plane2D lets the ball turn about z only.
      dMass m;
      const double moment = scene.moment_of_inertia(i);
      dMassSetParameters(&m, scene.mass(i), 0, 0, 0, moment, moment, moment, 0, 0, 0);
      dBodySetMass(b, &m);
      dBodySetPosition(b, scene.initial.pos(i, 0), scene.initial.pos(i, 1), 0.0);
      dBodySetLinearVel(b, scene.initial.vel(i, 0), scene.initial.vel(i, 1), 0.0);
      dBodySetAngularVel(b, 0, 0, scene.spin(i));
      dBodySetAutoDisableFlag(b, 0);
      dGeomID g = dCreateSphere(space_, scene.radius(i));
      dGeomSetBody(g, b);
      dJointID plane = dJointCreatePlane2D(world_, nullptr);
      dJointAttach(plane, b, nullptr);
      bodies_.push_back(b);
    }

    // Walls: an ODE plane (a, b, c, d) is a half-space, solid where n . p < d, so each wall's
    // normal points into the box. A ball can sink into it but never pass behind it.
    if (scene.container.kind == ContainerKind::Box) {
      const auto& lo = scene.container.min;
      const auto& hi = scene.container.max;
      dCreatePlane(space_, 1, 0, 0, lo.x());
      dCreatePlane(space_, -1, 0, 0, -hi.x());
      dCreatePlane(space_, 0, 1, 0, lo.y());
      dCreatePlane(space_, 0, -1, 0, -hi.y());
    }
  }

  ~OdeEngine() override {
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);  // destroys its geoms (cleanup mode is on by default)
    dWorldDestroy(world_);  // destroys bodies and the Plane2D joints
  }

  OdeEngine(const OdeEngine&) = delete;
  OdeEngine& operator=(const OdeEngine&) = delete;

  void step(double dt) override {
    dSpaceCollide(space_, this, &OdeEngine::near_callback);
    const int ok = s_.stepper == OdeStepper::step ? dWorldStep(world_, dt) : dWorldQuickStep(world_, dt);
    dJointGroupEmpty(contacts_);
    if (!ok) throw std::runtime_error("ode: the stepper could not allocate its working memory");
    if (s_.align_to_plane) align_to_plane();
    t_ += dt;
  }

  void read(State& out) const override {
    out.resize(n_, rotation_);
    out.t = t_;
    for (int i = 0; i < n_; ++i) {
      const dReal* p = dBodyGetPosition(bodies_[i]);
      const dReal* v = dBodyGetLinearVel(bodies_[i]);
      out.pos(i, 0) = p[0], out.pos(i, 1) = p[1];
      out.vel(i, 0) = v[0], out.vel(i, 1) = v[1];
      if (!rotation_) continue;
      out.w(i) = dBodyGetAngularVel(bodies_[i])[2];
      const dReal* q = dBodyGetQuaternion(bodies_[i]);  // (w, x, y, z), about z only
      out.angle(i) = angle_[i] = angle_about_z(q[0], q[3], angle_[i]);
    }
  }

  nlohmann::json settings() const override {
    nlohmann::json j = ode_settings_table().json(s_);
    j["derived"] = {{"moment_of_inertia", inertia_label_}};
    return j;
  }

  double out_of_plane() const override {
    double worst = 0;
    for (dBodyID b : bodies_) {
      worst = std::max(worst, std::abs(dBodyGetPosition(b)[2]));
      worst = std::max(worst, std::abs(dBodyGetLinearVel(b)[2]));
    }
    return worst;
  }

 private:
  // dSpaceCollide calls this for every pair whose bounding boxes overlap; one contact per pair is
  // all a sphere-sphere or sphere-plane test can produce.
  static void near_callback(void* data, dGeomID o1, dGeomID o2) {
    auto* self = static_cast<OdeEngine*>(data);
    dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
    if (!b1 && !b2) return;  // wall against wall
    dContact contact{};
    contact.surface = self->surface_;
    if (dCollide(o1, o2, 1, &contact.geom, sizeof(dContact)) == 0) return;
    dJointID j = dJointCreateContact(self->world_, self->contacts_, &contact);
    dJointAttach(j, b1, b2);
  }

  // ODE wiki, "HOWTO constrain objects to 2d": Plane2D corrects positional drift but not rotational
  // drift, so keep only the rotation about z and the angular velocity about z.
  void align_to_plane() {
    for (dBodyID b : bodies_) {
      const dReal* q = dBodyGetQuaternion(b);  // (w, x, y, z)
      const double len = std::hypot(q[0], q[3]);
      if (len > 0) {
        const dQuaternion about_z = {q[0] / len, 0, 0, q[3] / len};
        dBodySetQuaternion(b, about_z);
      }
      const dReal* w = dBodyGetAngularVel(b);
      dBodySetAngularVel(b, 0, 0, w[2]);
    }
  }

  OdeSettings s_;
  int n_;
  bool rotation_;                      // the scene rotates: spins are read back
  std::string inertia_label_;
  mutable std::vector<double> angle_;  // each ball's unwrapped angle at the last read (rad)
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  dSurfaceParameters surface_{};
  std::vector<dBodyID> bodies_;
  double t_ = 0;
};

}  // namespace

OdeSettings ode_settings_for_profile(const std::string& profile) {
  if (profile == "tuned") return OdeSettings{};
  if (profile == "stock") {
    OdeSettings s;
    s.stepper = OdeStepper::quickstep;  // what most ODE applications use; 20 iterations, ODE's default
    s.space = OdeSpace::hash;  // what ODE's demos create (dHashSpaceCreate)
    s.quickstep_iterations = 20;
    s.quickstep_w = 1.3;       // ODE default
    s.erp = 0.2;               // ODE default
    s.cfm = 1e-10;             // ODE default in double precision (1e-5 in single)
    s.bounce_vel = 0.1;        // as in ODE's demos (demo_boxstack, ...)
    s.contact_surface_layer = 0.0;  // ODE default
    s.max_correcting_vel = -1;      // ODE default: dInfinity
    s.align_to_plane = true;
    return s;
  }
  throw InputError(fmt::format("ode: unknown profile '{}' (known: {})", profile, fmt::join(kExternalProfiles, ", ")));
}

EngineEntry ode_engine() {
  EngineInfo info;
  info.name = "ode";
  info.version = dODE_VERSION;  // <ode/version.h> of the installed libode-dev (Debian 2:0.16.2-1)
  info.limits =
      "double; all contacts of a step solved together, each with its own bounce target from before the step, which "
      "puts energy in when a ball is struck from two sides in one step (grows with dt); CFM softness (restitution "
      "short by (1 + e) cfm m_eff / dt); no bounce below bounce_vel (stock 0.1 m/s); ERP push-out; no CCD";
  info.summary = "Open Dynamics Engine, spheres held to z = 0 by Plane2D joints (3D engine, no CCD)";
  // The stock profile's bounce_vel (0.1 m/s) drops restitution to 0 below that approach speed;
  // tuned (bounce_vel 0) honours it at any speed, but the flag is per engine, so it is false.
  info.caps.any_restitution = false;
  info.caps.continuous_collision = false;  // discrete overlap tests only: fast balls tunnel
  info.caps.deterministic = true;          // single-threaded stepping, fixed insertion order
  info.profiles = kExternalProfiles;
  // Stock uses the hash space, whose cost per ball grows with n (README.md: 49 us per ball-step at
  // 10^4), so 10^5 would take minutes per benchmark. Tuned steps with dWorldStep, a dense LCP over
  // every contact, whose cost grows with the cube of the contacts (a settled pile of 100 balls: 87 ms
  // a step; of 1000: no step within minutes); the fluid starts apart and diverges within 20 steps at
  // 1000 balls, so that count stays.
  info.bench.profile_sizes["stock"] = {.free_balls = 10'000, .fluid_balls = 10'000, .settled_balls = 10'000};
  info.bench.profile_sizes["tuned"] = {.free_balls = 100'000, .fluid_balls = 1000, .settled_balls = 100};
  // The iterative stepper's sweeps, and the exact (big-matrix) stepper against it. ODE has no CCD.
  info.settings = ode_settings_table().describe();
  info.sweep_knobs = {{"quickstep_iterations", {5, 20, 80}}, {"stepper", {"step", "quickstep"}}};
  return {info, [](const Scene& scene, const std::string& profile, const nlohmann::json& overrides) {
            OdeSettings s = ode_settings_for_profile(profile);
            ode_settings_table().read(overrides, s);
            return std::unique_ptr<Engine>(std::make_unique<OdeEngine>(scene, s));
          }};
}

}  // namespace ballbench

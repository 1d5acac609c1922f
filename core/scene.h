#pragma once
// A validated, immutable description of one ball scene: what every engine is asked to simulate.
#include <cstdint>
#include <map>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "accuracy_spec.h"
#include "state.h"

namespace ballbench {

enum class ContainerKind { Box, None };

struct Container {
  ContainerKind kind = ContainerKind::None;
  Eigen::Vector2d min{0, 0};  // box corners (m); unused for None
  Eigen::Vector2d max{0, 0};
};

// What the scene needs, derived from its data (never declared by hand, so it cannot lie).
// Engines and the runner use it to skip work a scene does not need.
struct SceneFeatures {
  bool gravity = false;        // non-zero gravity vector
  bool walls = false;          // a box container
  bool equal_radii = false;
  bool equal_masses = false;
  bool elastic = false;        // restitution exactly 1
  bool frictionless = false;   // friction exactly 0
  bool rotation = false;       // friction above 0 or a ball that starts spinning: balls rotate
};

// How a ball's mass is spread: its moment of inertia about its centre is I = k m r^2.
enum class Inertia {
  disk,    // k = 1/2: a solid disk, the 2D ball (the default)
  sphere,  // k = 2/5: a solid sphere, as 3D engines build a ball
};
double inertia_factor(Inertia inertia);  // k
const char* inertia_name(Inertia inertia);  // "disk", "sphere"

// Metrics a scene asks for in its [metrics] table, beyond those every run gets: each is computed
// only where asked, since each needs a scene built for it (scenarios/README.md).
struct RequestedMetrics {
  bool rolling = false;          // balls on the floor: their final speeds against their closed forms (metrics/rolling.h)
  bool angle_of_repose = false;  // a heap on the floor: the slope of its flanks (metrics/angle_of_repose.h)
  bool runout = false;           // a heap on the floor: the length of its deposit (metrics/runout.h)
};

// The [metrics] keys, each a flag of RequestedMetrics; every one measures against a floor (a box
// container, gravity straight down onto it).
struct RequestedMetricKey {
  const char* key;
  bool RequestedMetrics::*flag;
};
inline constexpr RequestedMetricKey kRequestedMetricKeys[] = {{"rolling", &RequestedMetrics::rolling},
                                                              {"angle_of_repose", &RequestedMetrics::angle_of_repose},
                                                              {"runout", &RequestedMetrics::runout}};

struct Scene {
  std::string name;
  std::string source;          // file the scene came from, for messages
  std::string use_case;        // what a game asks of its engine that the scene stands for ("a pile at rest"), or ""
  double dt = 0.01;            // step size (s)
  double duration = 1.0;       // simulated time (s)
  Eigen::Vector2d gravity{0, 0};  // (m/s^2)
  double restitution = 1.0;    // ball-ball and ball-wall, normal component
  double friction = 0.0;       // Coulomb coefficient, ball-ball and ball-wall
  Inertia inertia = Inertia::disk;
  RequestedMetrics metrics;
  SceneAccuracy accuracy;      // its [accuracy] table, on top of its class's default spec (accuracy_spec.h)
  bool allow_overlap = false;  // balls may start overlapping (the thesis's random placement does)
  bool animated = false;       // the report animates its runs and puts them in the viewer (the thesis's scenes)
  Container container;
  Eigen::VectorXd radius;      // (n, m)
  Eigen::VectorXd mass;        // (n, kg)
  State initial;               // t = 0; its w holds each ball's spin when the scene rotates
  nlohmann::json engine_settings = nlohmann::json::object();  // [settings.<engine>] tables
  std::map<std::string, int> setting_lines;  // "ENGINE.KEY" -> its line in the scene file, for messages
  // Random placement: whether any [random] or [lattice] table draws balls, and the offset added to
  // each such table's seed (`run --seeds K` runs offsets 0 .. K-1; 0 is the file as written).
  bool random_placement = false;
  int64_t seed_offset = 0;

  int n() const { return static_cast<int>(radius.size()); }
  long steps() const;          // duration / dt, rounded to the nearest whole step
  SceneFeatures features() const;
  double spin(int i) const { return initial.rotates() ? initial.w(i) : 0.0; }  // initial w (rad/s)
  double moment_of_inertia(int i) const { return inertia_factor(inertia) * mass(i) * radius(i) * radius(i); }
};

}  // namespace ballbench

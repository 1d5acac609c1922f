#pragma once
// What the adapter tests share: the calibration parameters (profile, requested restitution), the
// two calibration scenes (a ball meeting a wall, two balls head-on), and running an engine for a
// number of steps from a scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "conformance.h"
#include "registry.h"
#include "scene_loader.h"

namespace ballbench::calibration {

struct Calibration {
  std::string profile;
  double e;
};

inline void PrintTo(const Calibration& c, std::ostream* os) { *os << c.profile << ", e = " << c.e; }

// A test name such as tuned_e80.
inline std::string calibration_name(const ::testing::TestParamInfo<Calibration>& p) {
  return fmt::format("{}_e{}", p.param.profile, static_cast<int>(std::lround(p.param.e * 100)));
}

// The state after `steps` steps of `engine` (a registered name) under `profile`.
inline State run_steps(const std::string& engine, const Scene& s, const std::string& profile, int steps,
                       const nlohmann::json& overrides = {}) {
  auto e = find_engine(engine).create(s, profile, overrides);
  for (int k = 0; k < steps; ++k) e->step(s.dt);
  State st;
  e->read(st);
  return st;
}

// A ball of radius 0.1 crossing a 2 m box along x at `speed`: it meets the wall at x = 1 once
// within `steps` and is on its way back when read.
inline Scene wall_scene(double e, double speed) {
  return parse_scene(fmt::format(R"(
dt = 0.01
duration = 1.0
restitution = {}
[container]
min = [-1.0, -1.0]
max = [1.0, 1.0]
[[ball]]
pos = [0.0, 0.0]
vel = [{}, 0.0]
radius = 0.1
)",
                                 e, speed),
                     "wall.toml");
}

// The friction coefficient and inertia factor an engine applies, measured on slide-to-roll
// (conformance.h's measure_slide).
using FrictionCalibration = SlideMeasure;

inline FrictionCalibration measure_friction(const std::string& engine, const std::string& profile, Inertia inertia) {
  Scene s = load_scene("slide-to-roll");
  s.inertia = inertia;
  return measure_slide(*find_engine(engine).create(s, profile, {}), s);
}

// The scene's friction (0.5) and each inertia (disk 1/2, sphere 2/5) within 0.5% (of mu and of
// 1 + k: the rolling speed's), for every profile of `engine`; the figures are printed.
inline void expect_friction_and_inertia_are_the_scenes(const std::string& engine) {
  for (const std::string& profile : find_engine(engine).info.profiles)
    for (const Inertia inertia : {Inertia::disk, Inertia::sphere}) {
      const FrictionCalibration c = measure_friction(engine, profile, inertia);
      const double k = inertia_factor(inertia);
      std::printf("%s/%s %s: friction %.6g (0.5), inertia factor %.6g (%g)\n", engine.c_str(), profile.c_str(),
                  inertia_name(inertia), c.mu, c.k, k);
      EXPECT_NEAR(c.mu, 0.5, 0.005 * 0.5) << engine << "/" << profile << " " << inertia_name(inertia);
      EXPECT_NEAR(1 + c.k, 1 + k, 0.005 * (1 + k)) << engine << "/" << profile << " " << inertia_name(inertia);
    }
}

// Head-on in open space, unequal radii and masses: relative speed 5 m/s, contact at t = 0.1 s.
inline Scene head_on_scene(double e) {
  return parse_scene(fmt::format(R"(
dt = 0.01
duration = 1.0
restitution = {}
[[ball]]
pos = [-0.5, 0.0]
vel = [3.0, 0.0]
radius = 0.2
mass = 1.0
[[ball]]
pos = [0.5, 0.0]
vel = [-2.0, 0.0]
radius = 0.3
mass = 2.0
)",
                                 e),
                     "head-on.toml");
}

}  // namespace ballbench::calibration

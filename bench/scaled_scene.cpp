#include "scaled_scene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "scene_loader.h"

namespace ballbench::bench {

const char* scene_kind_name(SceneKind k) {
  switch (k) {
    case SceneKind::Gas: return "gas";
    case SceneKind::Bowl: return "bowl";
    case SceneKind::Fluid: return "fluid";
  }
  return "?";
}

namespace {

Scene fluid_scene(int n) {
  const double scale = std::sqrt(72.0 / n);
  const int columns = std::max(1, static_cast<int>(std::lround(std::sqrt(8.0 * n / 9.0))));
  return parse_scene(fmt::format(R"(
name = "fluid-{0}"
dt = 0.01
duration = 3.0
gravity = [0.0, -100.0]
restitution = 0.99
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
[lattice]
count = {0}
radius = {1}
spacing = {2}
origin = [-4.6, -4.6]
columns = {3}
vel_min = [-2.5, -2.5]
vel_max = [2.5, 2.5]
seed = 2017
[accuracy]
overlap = 0.02
rest_speed = false
)", n, 0.25 * scale, 0.6 * scale, columns),
                     fmt::format("fluid-{}", n));
}

}  // namespace

Scene scaled_scene(SceneKind kind, int n) {
  if (kind == SceneKind::Fluid) return fluid_scene(n);
  const double half = 0.5 * std::sqrt(5.0 * n);  // box side sqrt(5 n): the seed-box's area per ball
  if (kind == SceneKind::Gas)
    return parse_scene(fmt::format(R"(
name = "gas-{0}"
dt = 0.01
duration = 1.0
restitution = 1.0
[container]
min = [{1}, {1}]
max = [{2}, {2}]
[random]
count = {0}
radius = 0.25
vel_min = [-12.5, -12.5]
vel_max = [12.5, 12.5]
seed = 1
)", n, -half, half),
                       fmt::format("gas-{}", n));
  // The bowl: the seed's 72 balls fill 8 x 9 grid places at spacing 0.6 in the lower left of a
  // 10 x 10 box; here they fill the lower half of the box at the same spacing.
  return parse_scene(fmt::format(R"(
name = "bowl-{0}"
dt = 0.01
duration = 1.0
gravity = [0.0, -100.0]
restitution = 0.99
[container]
min = [{1}, {1}]
max = [{2}, {2}]
[random]
count = {0}
radius = 0.25
pos_min = [{3}, {3}]
pos_max = [{4}, {5}]
vel_min = [-2.5, -2.5]
vel_max = [2.5, 2.5]
seed = 1
)", n, -half, half, -half + 0.25, half - 0.25, 0.0),
                     fmt::format("bowl-{}", n));
}

const Scene& shared_scaled_scene(SceneKind kind, int n) {
  static std::map<std::pair<SceneKind, int>, Scene> scenes;
  auto it = scenes.find({kind, n});
  if (it == scenes.end()) it = scenes.emplace(std::make_pair(kind, n), scaled_scene(kind, n)).first;
  return it->second;
}

}  // namespace ballbench::bench

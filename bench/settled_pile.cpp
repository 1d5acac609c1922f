#include "settled_pile.h"

#include <cmath>
#include <cstdio>
#include <map>

#include <fmt/format.h>

#include "scene_loader.h"
#include "solver/home.h"

namespace ballbench::bench {
namespace {

double rms_speed(const State& s) { return std::sqrt(s.vel.rowwise().squaredNorm().mean()); }

}  // namespace

Scene settled_pile(int n) {
  // A square lattice of spacing 0.6 (gaps of 0.1 between the balls), `columns` wide, with small
  // random velocities so the pile does not stay a square stack.
  constexpr double kSpacing = 0.6, kRadius = 0.25;
  const int columns = std::max(2, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))));
  const int rows = (n + columns - 1) / columns;
  const double width = columns * kSpacing, height = (rows + 1) * kSpacing;
  Scene scene = parse_scene(fmt::format(R"(
name = "settled-{0}"
dt = 0.01
duration = 1.0
gravity = [0.0, -9.81]
restitution = 0.5
[container]
min = [0.0, 0.0]
max = [{1}, {2}]
[lattice]
count = {0}
radius = {3}
spacing = {4}
columns = {5}
origin = [{6}, {6}]
vel_min = [-0.5, -0.5]
vel_max = [0.5, 0.5]
seed = 1
)", n, width, height, kRadius, kSpacing, columns, 0.5 * kSpacing),
                            fmt::format("settled-{}", n));
  // Settled by `home` without sleeping (each ball's own state, none frozen by a rule), as built for
  // the spec the benchmark judges it at (its default profile: overlap <= 1%, spec_check.h) up to
  // kSettledAtSpecBalls; a pile settled looser springs apart under an engine stiffer than the one
  // that settled it (home's default from the soft profile's 5% at 10^4 balls: RMS 3.6 m/s after
  // 1.6 s). Larger piles, whose settling at the spec would take hours, by the soft profile.
  const auto engine = home_engine().create(scene, n <= kSettledAtSpecBalls ? "default" : "soft",
                                           nlohmann::json::object());
  State state;
  int steps = 0;
  for (; steps < kSettleSteps; ++steps) {
    engine->step(scene.dt);
    if (steps % 50 == 49) {
      engine->read(state);
      if (rms_speed(state) < kSettledSpeed) break;
    }
  }
  engine->read(state);
  std::fprintf(stderr, "settled-%d: %d steps of settling, RMS speed %.3g m/s\n", n, steps + 1, rms_speed(state));
  state.t = 0;
  scene.initial = state;
  return scene;
}

const Scene& shared_settled_pile(int n) {
  static std::map<int, Scene> scenes;
  auto it = scenes.find(n);
  if (it == scenes.end()) it = scenes.emplace(n, settled_pile(n)).first;
  return it->second;
}

}  // namespace ballbench::bench

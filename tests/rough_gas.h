#pragma once
// What the rough-gas tests of home and exact share: the gas (200 spinning balls in open space,
// friction 0.5, no gravity, no walls within reach) and the two sums they check, computed here
// from the state alone so that the check does not lean on the metrics under test.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "scene_loader.h"
#include "state.h"

namespace ballbench::rough_gas {

inline Scene scene(double restitution) {
  return parse_scene(fmt::format(R"(
dt = 0.01
duration = 2.0
restitution = {}
friction = 0.5
[random]
count = 200
radius = 0.1
mass = 1.0
pos_min = [-3.0, -3.0]
pos_max = [3.0, 3.0]
vel_min = [-2.0, -2.0]
vel_max = [2.0, 2.0]
spin_min = -10.0
spin_max = 10.0
seed = 5
)",
                                 restitution),
                     "rough-gas.toml");
}

// Translational plus rotational kinetic energy (J).
inline double kinetic_energy(const Scene& s, const State& st) {
  double e = 0;
  for (int i = 0; i < s.n(); ++i) {
    e += 0.5 * s.mass(i) * st.vel.row(i).squaredNorm();
    if (st.rotates()) e += 0.5 * s.moment_of_inertia(i) * st.w(i) * st.w(i);
  }
  return e;
}

// Orbital plus spin angular momentum about the origin (kg m^2/s); `scale` gets the sum of the
// terms' magnitudes, what round-off is relative to.
inline double angular_momentum(const Scene& s, const State& st, double* scale = nullptr) {
  double l = 0, size = 0;
  for (int i = 0; i < s.n(); ++i) {
    const double orbital = s.mass(i) * (st.pos(i, 0) * st.vel(i, 1) - st.pos(i, 1) * st.vel(i, 0));
    const double spin = st.rotates() ? s.moment_of_inertia(i) * st.w(i) : 0.0;
    l += orbital + spin;
    size += std::abs(orbital) + std::abs(spin);
  }
  if (scale) *scale = size;
  return l;
}

}  // namespace ballbench::rough_gas

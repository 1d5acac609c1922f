#pragma once
// Mechanical energy of a state: kinetic (translation and rotation) + gravitational potential.
//   E = sum_i m_i |v_i|^2 / 2 + I_i w_i^2 / 2 + m_i |g| h_i,   h_i = -(g / |g|) . (x_i - x_ref)
// with I_i = k m_i r_i^2 (Scene::inertia); the rotation term is there only for a state that rotates.
// x_ref is the lowest point of the container along g (its floor), so E >= 0 for balls inside a
// box and E0 > 0 makes the relative drift |E - E0| / E0 meaningful. In open space x_ref is the
// lowest initial ball centre. The reference only shifts E by a constant; it is reported.
#include <Eigen/Core>

#include "scene.h"
#include "state.h"

namespace ballbench {

// -g . x_ref (J/kg): the potential per unit mass at the reference height.
double energy_reference(const Scene& scene);

double kinetic_energy(const State& s, const Scene& scene);
double potential_energy(const State& s, const Eigen::VectorXd& mass, const Eigen::Vector2d& gravity, double reference);
double total_energy(const State& s, const Scene& scene, double reference);

}  // namespace ballbench

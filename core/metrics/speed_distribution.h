#pragma once
// The speed distribution of an equilibrated 2D elastic gas is Rayleigh (2D Maxwell-Boltzmann):
// F(v) = 1 - exp(-v^2 / (2 s^2)) with s^2 = <|v|^2> / 2 for equal masses (equipartition over two
// degrees of freedom). The Kolmogorov-Smirnov statistic D = sup |F_empirical - F| measures the fit;
// at the 1% level the critical value is 1.63 / sqrt(n) (Kolmogorov's asymptotic distribution).
#include "scene.h"
#include "state.h"

namespace ballbench {

// Is the test meaningful for this scene? Elastic, no gravity, equal masses, at least 100 balls.
bool speed_distribution_applies(const Scene& scene);

// D for the state's speeds against the Rayleigh law with the state's own mean square speed.
double rayleigh_ks_statistic(const State& s);

// 1.63 / sqrt(n): D above this rejects the Rayleigh law at the 1% level.
double rayleigh_ks_critical(int n);

}  // namespace ballbench

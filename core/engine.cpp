#include "engine.h"

#include <cmath>

#include <vector>

#include <fmt/format.h>

namespace ballbench {

const char* role_name(EngineRole role) {
  switch (role) {
    case EngineRole::ours: return "ours";
    case EngineRole::reference: return "reference";
    case EngineRole::thesis: return "thesis";
    case EngineRole::external: return "external";
  }
  return "external";
}

double angle_about_z(double qw, double qz, double previous) {
  const double a = 2 * std::atan2(qz, qw);
  return previous + std::remainder(a - previous, 2 * M_PI);
}

std::string unsupported_reason(const EngineInfo& info, const Scene& scene) {
  if (!info.unavailable.empty()) return fmt::format("{} is unavailable here: {}", info.name, info.unavailable);
  const SceneFeatures f = scene.features();
  std::vector<std::string> missing;
  if (!f.walls && !info.caps.open_space) missing.push_back("open space (no container)");
  if (f.gravity && !info.caps.gravity) missing.push_back("gravity");
  if (!f.equal_radii && !info.caps.per_ball_radius) missing.push_back("balls of different radii");
  if (!f.equal_masses && !info.caps.per_ball_mass) missing.push_back("balls of different masses");
  if (!f.frictionless && !info.caps.friction) missing.push_back("friction (it has no rotation: friction would be ignored)");
  else if (f.rotation && !info.caps.friction) missing.push_back("spin (it has no rotation: the spin would be dropped)");
  if (missing.empty()) {
    const std::string refusal = info.refuses ? info.refuses(scene) : "";
    return refusal.empty() ? "" : fmt::format("{} cannot run scene '{}': {}", info.name, scene.name, refusal);
  }
  return fmt::format("{} cannot run scene '{}': it needs {}", info.name, scene.name, fmt::join(missing, ", "));
}

}  // namespace ballbench

#include "scene_digest.h"

#include <xxhash.h>

#include <memory>

#include <fmt/format.h>

#include "scene_writer.h"

namespace ballbench {

std::string scene_digest(const Scene& scene) {
  const std::string head = scene_at_state(scene, State{}, scene.name, scene.duration).text;
  const std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> h(XXH3_createState(), &XXH3_freeState);
  XXH3_64bits_reset(h.get());
  XXH3_64bits_update(h.get(), head.data(), head.size());
  const auto add = [&](const auto& m) { XXH3_64bits_update(h.get(), m.data(), sizeof(double) * size_t(m.size())); };
  add(scene.radius), add(scene.mass);
  add(scene.initial.pos), add(scene.initial.vel), add(scene.initial.w), add(scene.initial.angle);
  return fmt::format("{:016x}", XXH3_64bits_digest(h.get()));
}

}  // namespace ballbench

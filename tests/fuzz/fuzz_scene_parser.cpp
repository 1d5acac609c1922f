// libFuzzer target for the scene parser (core/scene_loader.cpp): any bytes must give either a
// valid Scene or one InputError with a one-line message, never a crash, a hang or a sanitizer
// report. Built with BALLBENCH_FUZZ=ON and clang (CMake preset `fuzz`); run briefly by .ci/run:
//   build/fuzz/tests/fuzz/fuzz_scene_parser -max_total_time=60 NEW_CORPUS_DIR tests/fuzz/corpus
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include <toml++/toml.h>

#include "input_error.h"
#include "scene_loader.h"

namespace {

// Random placement costs time and memory in proportion to `count`, by design (up to 5e7 balls):
// the fuzzer is here for crashes, not to time legitimately huge scenes, so it skips those.
constexpr int64_t kMaxFuzzedBalls = 100'000;

bool asks_for_many_balls(const toml::table& doc) {
  const toml::node* random = doc.get("random");
  if (!random) return false;
  auto too_many = [](const toml::node* group) {
    const toml::table* t = group ? group->as_table() : nullptr;
    const toml::node* count = t ? t->get("count") : nullptr;
    return count && count->is_integer() && count->as_integer()->get() > kMaxFuzzedBalls;
  };
  if (const toml::array* groups = random->as_array()) {
    for (const toml::node& g : *groups)
      if (too_many(&g)) return true;
    return false;
  }
  return too_many(random);
}

// A parsed scene must satisfy what the loader promises (core/scene.h).
bool valid(const ballbench::Scene& s) {
  if (s.n() <= 0 || !(s.dt > 0) || !(s.duration > 0) || !std::isfinite(s.dt) || !std::isfinite(s.duration)) return false;
  if (!s.initial.pos.allFinite() || !s.initial.vel.allFinite() || !s.gravity.allFinite()) return false;
  if (!((s.radius.array() > 0).all() && (s.mass.array() > 0).all() && s.radius.allFinite() && s.mass.allFinite()))
    return false;
  return s.restitution >= 0 && s.restitution <= 1 && s.friction >= 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    if (asks_for_many_balls(toml::parse(text))) return 0;
  } catch (const toml::parse_error&) {
    // The parser below reports it.
  }
  try {
    if (!valid(ballbench::parse_scene(text, "fuzz.toml"))) __builtin_trap();
  } catch (const ballbench::InputError& e) {
    if (std::string(e.what()).find('\n') != std::string::npos) __builtin_trap();  // one line per problem
  }
  return 0;
}

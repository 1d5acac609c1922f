#include "metrics/events.h"

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {

namespace {
constexpr const char* kNames[] = {"tunnel-wall", "tunnel-pair", "stick-wall", "stick-pair"};
}

const char* event_kind_name(EventKind kind) { return kNames[static_cast<int>(kind)]; }

EventKind event_kind_from_name(const std::string& name) {
  for (int k = 0; k < 4; ++k)
    if (name == kNames[k]) return static_cast<EventKind>(k);
  throw InputError(fmt::format("unknown event kind '{}' (known: tunnel-wall, tunnel-pair, stick-wall, stick-pair)", name));
}

}  // namespace ballbench

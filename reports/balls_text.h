#pragma once
// "1 ball", "20 balls": a scene's size in the report's text.
#include <string>

#include <fmt/format.h>

namespace ballbench {

inline std::string balls_text(long n) { return n == 1 ? "1 ball" : fmt::format("{} balls", n); }

}  // namespace ballbench

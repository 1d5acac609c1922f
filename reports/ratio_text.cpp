#include "ratio_text.h"

#include <cmath>

#include <fmt/format.h>

#include "no_data.h"

namespace ballbench {

std::string ratio_text(double r) {
  if (!(r > 0) || !std::isfinite(r)) return kNoData;
  if (r < 0.1) return fmt::format("1/{:.0f}x", 1 / r);
  return r >= 10 ? fmt::format("{:.0f}x", r) : r >= 1 ? fmt::format("{:.1f}x", r) : fmt::format("{:.2f}x", r);
}

}  // namespace ballbench

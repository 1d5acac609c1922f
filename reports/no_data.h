#pragma once
// The one symbol the report prints where there is no figure: the run made no step, or the figure is
// not defined for it. Never "-", which a reader takes for a minus or a "below".

namespace ballbench {

inline constexpr const char* kNoData = "n/a";

}  // namespace ballbench

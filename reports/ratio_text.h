#pragma once
// How the report prints a ratio of two costs.
#include <string>

namespace ballbench {

// As a reader takes it in: "48x", "2.5x", "0.50x", and below 0.1 its inverse, "1/330x" (not
// "0.0x"); "n/a" for no ratio.
std::string ratio_text(double ratio);

}  // namespace ballbench

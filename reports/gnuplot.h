#pragma once
// Running gnuplot (Debian's gnuplot-nox, pngcairo) on a script draw_plot (plot.h) writes, and naming
// the figures' files.
#include <filesystem>
#include <string>

namespace ballbench {

// Runs gnuplot on `script` (its data files named relative to the working folder); throws
// std::runtime_error naming the script and its log if gnuplot fails.
void run_gnuplot(const std::filesystem::path& script);

// A name safe for files: "box2d/tuned" -> "box2d-tuned".
std::string slug(std::string s);

}  // namespace ballbench

#pragma once
// Figures for the report, drawn by gnuplot (Debian's gnuplot-nox, pngcairo) from the series in the
// result files: energy over time per engine, pictures of a scene like the thesis's figures 3-5
// (final positions, the tracks of a few balls, the centre-of-mass trail), work against precision
// (sweeps), the stability frontier (stress) and scaling (the step benchmark).
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

// Writes data, gnuplot scripts and PNGs into OUT/figures/. Throws std::runtime_error naming the
// figure if gnuplot fails; returns the figures made.
std::vector<Figure> draw_figures(const ReportInputs& in, const std::string& out_dir);

}  // namespace ballbench

#include "figures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "data_file.h"
#include "front_figures.h"
#include "gnuplot.h"
#include "ordered_set.h"
#include "palette.h"
#include "viewer_page.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

// Text as a gnuplot string: single-quoted, a quote doubled. Terminals are set noenhanced, so '_'
// and '^' are themselves.
std::string quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// A run's colour and dash (palette.h) as gnuplot line properties.
std::string line_style(const std::string& engine, const std::string& profile) {
  const RunStyle s = run_style(engine, profile);
  return fmt::format("lc rgb '{}' dt {}", s.colour, s.dash);
}

// A line with the run's markers on it.
std::string linespoints_style(const std::string& engine, const std::string& profile) {
  return fmt::format("{} pt {}", line_style(engine, profile), run_style(engine, profile).point);
}

// Points of the same run that are not on its line (a knob set): its marker, open.
std::string open_points_style(const std::string& engine, const std::string& profile) {
  const RunStyle s = run_style(engine, profile);
  return fmt::format("lc rgb '{}' pt {}", s.colour, s.open_point());
}

// A ball's radius in a picture: its own where the result has every ball's, else the mean.
double ball_radius(const Result& r, size_t b) {
  return r.series.radius.size() > b ? r.series.radius[b] : r.series.radius_mean;
}

// The part of the plane a picture shows: the container, and every ball that left it unless one
// went far (a diverged run: 10^6 m away), which would shrink the container to a dot; those stay
// outside and are counted.
struct View {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  bool contains(const std::array<double, 2>& p) const { return p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1; }
};

// `points` with the largest radius `reach` around them; a container's size beyond its walls at most.
View scene_view(const std::optional<std::array<double, 4>>& box, const std::vector<std::array<double, 2>>& points,
                double reach) {
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  auto take = [&](double x, double y) { x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y); };
  if (box) take((*box)[0], (*box)[1]), take((*box)[2], (*box)[3]);
  const double size = box ? std::max((*box)[2] - (*box)[0], (*box)[3] - (*box)[1]) : 0;
  for (const auto& p : points) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) continue;
    if (box && (p[0] < (*box)[0] - size || p[0] > (*box)[2] + size || p[1] < (*box)[1] - size || p[1] > (*box)[3] + size))
      continue;  // far away: counted, not shown
    take(p[0] - reach, p[1] - reach), take(p[0] + reach, p[1] + reach);
  }
  if (!(x0 <= x1)) return {};
  const double margin = 0.04 * std::max({x1 - x0, y1 - y0, 1e-9});
  return {x0 - margin, y0 - margin, x1 + margin, y1 + margin};
}

// The gnuplot lines that frame a picture: the view, equal scales, the container's walls.
std::string view_lines(const View& v, const std::optional<std::array<double, 4>>& box) {
  std::string out = fmt::format("set size ratio -1\nset xrange [{}:{}]\nset yrange [{}:{}]\nunset object\n", v.x0, v.x1, v.y0, v.y1);
  if (box)
    out += fmt::format("set object 1 rect from {},{} to {},{} fs empty border rgb '#c03030' lw 2 front\n", (*box)[0],
                       (*box)[1], (*box)[2], (*box)[3]);
  return out;
}

// How many of `points` lie outside `v`, as a line for the picture, or "" when none.
std::string outside_note(const View& v, const std::vector<std::array<double, 2>>& points) {
  int outside = 0;
  std::array<double, 2> far{0, 0};
  double farthest = -1;
  for (const auto& p : points)
    if (!v.contains(p)) {
      ++outside;
      const double d = std::hypot(p[0], p[1]);
      if (!(d <= farthest)) farthest = d, far = p;  // a non-finite position is the farthest
    }
  if (outside == 0) return "";
  return fmt::format("{} ball{} beyond the view, farthest at ({:.3g}, {:.3g}) m", outside, outside == 1 ? "" : "s", far[0],
                     far[1]);
}

// Energy over time relative to the start, log scale, one line per run in its palette style. Every
// engine's first profile in the upper panel, the other profiles in the lower one with the
// reference repeated for comparison, so no panel holds more lines than there are engines. None
// when no run of the scene has an energy to plot (every engine refused it, say).
std::optional<Figure> energy_figure(const std::string& scene, const std::vector<const Result*>& runs,
                                    const ReportInputs& in, const fs::path& dir) {
  const std::string base = slug(scene) + "-energy";
  std::string first, others, reference;
  for (const Result* r : runs) {
    const double e0 = r->metrics.value(Metric::energy_initial);
    if (r->series.t.empty() || e0 <= 0) continue;
    const std::string data = base + "-" + slug(run_label(*r)) + ".dat";
    std::ofstream f(dir / data);
    for (size_t k = 0; k < r->series.t.size(); ++k)
      f << r->series.t[k] << ' ' << r->series.energy[k] / e0 << '\n';
    // A run that stopped says when in its key: its line ends there, or leaves the plot.
    const std::string title = r->status == RunStatus::ok
                                  ? run_label(*r)
                                  : fmt::format("{} ({} at {:.3g} s)", run_label(*r), run_status_text(r->status), stop_time(*r));
    const std::string item = fmt::format("'{}' with lines lw 2 {} title {}", data, line_style(r->engine, r->profile),
                                         quoted(title));
    std::string& panel = run_style(r->engine, r->profile).dash == 1 ? first : others;
    panel += (panel.empty() ? "" : ", ") + item;
    if (role_of(in, r->engine) == EngineRole::reference)
      reference = fmt::format("'{}' with lines lw 1.5 {} title {}", data, line_style(r->engine, r->profile),
                              quoted(run_label(*r) + " (reference)"));
  }
  if (first.empty() && others.empty()) return std::nullopt;
  const bool two = !first.empty() && !others.empty();
  if (two && !reference.empty()) others = reference + ", " + others;
  constexpr int kPanelHeight = 360;
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size 900," << (two ? 2 : 1) * kPanelHeight + 20 << " font 'sans,10'\nset termoption noenhanced\n"
     << "set output '" << base << ".png'\n"
     << "set xlabel 'time (s)'\nset ylabel 'E / E0 (log scale)'\nset logscale y\nset yrange [1e-4<*:*<1e4]\nset grid\n"
     << "set key outside right top font ',9'\nset lmargin at screen 0.09\nset rmargin at screen 0.70\n";
  if (two) gp << "set multiplot layout 2,1\n";
  gp << "set title " << quoted("Energy over time, " + scene + (two ? ": each engine's first profile" : "")) << "\n"
     << "plot " << (first.empty() ? others : first) << '\n';
  if (two)
    gp << "set title " << quoted(scene + ": the other profiles (dashed)") << "\nplot " << others << "\nunset multiplot\n";
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return Figure{FigureKind::energy, scene, "figures/" + base + ".png",
                two ? "Energy over time relative to the start (log scale): above, each engine's first profile; below, "
                      "its other profiles (dashed), with the reference for comparison. One colour per engine, as in "
                      "every figure and the viewer; a run that stopped early says when in the key."
                    : "Energy over time relative to the start (log scale), one line per engine and profile; a run that "
                      "stopped early says when in the key."};
}

// One panel per run, like the thesis's figures 3 to 5: the balls at the end (each its own radius,
// in its engine's colour), the tracks of the first balls (a colour per ball), and the
// centre-of-mass trail; the container's walls, and every ball that left it, in view, axes in metres.
Figure scene_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
  const std::string base = slug(scene) + "-picture";
  const size_t cols = std::min<size_t>(3, runs.size()), rows = (runs.size() + cols - 1) / cols;
  const int panel = cols == 1 ? 560 : cols == 2 ? 450 : 310;
  std::vector<std::array<double, 2>> everything;
  double reach = 0;
  for (const Result* r : runs) {
    for (size_t b = 0; b < r->series.final_pos.size(); ++b) reach = std::max(reach, ball_radius(*r, b));
    everything.insert(everything.end(), r->series.final_pos.begin(), r->series.final_pos.end());
  }
  const View view = scene_view(runs.front()->series.box, everything, reach);
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size " << panel * cols << "," << (panel + 70) * rows << " font 'sans,10'\n"
     << "set termoption noenhanced\nset output '" << base << ".png'\nset multiplot layout " << rows << "," << cols << "\n"
     << "set xlabel 'x (m)'\nset ylabel 'y (m)' offset 1,0\nset key below font ',8' samplen 2\n"
     << view_lines(view, runs.front()->series.box);
  for (size_t k = 0; k < runs.size(); ++k) {
    const Result* r = runs[k];
    const std::string name = slug(run_label(*r));
    const RunStyle style = run_style(r->engine, r->profile);
    {
      std::ofstream f(dir / fmt::format("{}-{}-balls.dat", base, name));
      for (size_t b = 0; b < r->series.final_pos.size(); ++b)
        f << r->series.final_pos[b][0] << ' ' << r->series.final_pos[b][1] << ' ' << ball_radius(*r, b) << '\n';
    }
    {
      std::ofstream f(dir / fmt::format("{}-{}-tracks.dat", base, name));
      for (const auto& track : r->series.tracks) {
        for (const auto& p : track) f << p[0] << ' ' << p[1] << '\n';
        f << "\n\n";  // a new gnuplot data block per ball
      }
    }
    {
      std::ofstream f(dir / fmt::format("{}-{}-com.dat", base, name));
      for (size_t c = 0; c < r->series.com_x.size(); ++c) f << r->series.com_x[c] << ' ' << r->series.com_y[c] << '\n';
    }
    const std::string stopped = r->status == RunStatus::ok ? "" : fmt::format(" ({})", run_status_text(r->status));
    gp << "set title " << quoted(fmt::format("{} at t = {:.3g} s{}", run_label(*r), r->series.t.empty() ? 0.0 : r->series.t.back(), stopped))
       << "\nunset label\n";
    if (const std::string note = outside_note(view, r->series.final_pos); !note.empty())
      gp << "set label 1 " << quoted(note) << " at graph 0.02, graph 0.97 left front font ',8' textcolor rgb '#b03030'\n";
    // The same key under every panel, so that every panel keeps the same size.
    auto t = [&](const std::string& title) { return "title " + quoted(title); };
    std::string plot = fmt::format("'{0}-{1}-balls.dat' using 1:2:3 with circles lc rgb '{2}' fs transparent solid 0.45 "
                                   "border lc rgb '{2}' {3}",
                                   base, name, style.colour, t("balls"));
    for (size_t b = 0; b < r->series.tracks.size(); ++b)
      plot += fmt::format(", '{}-{}-tracks.dat' index {} using 1:2 with lines lw 1.2 lc rgb '{}' {}", base, name, b,
                          track_colour(static_cast<int>(b)), t(fmt::format("track of ball {}", b)));
    plot += fmt::format(", '{}-{}-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' {}", base, name, t("centre of mass"));
    gp << "plot " << plot << '\n';
  }
  gp << "unset multiplot\n";
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {FigureKind::picture, scene, "figures/" + base + ".png",
          "The scene at the end, to scale in metres: the balls in their engine's colour, the tracks of the first four "
          "balls (a colour each), the centre-of-mass trail (dark grey) and the container's walls (red), as in the "
          "thesis's figures 3 to 5."};
}

// The scene in motion, one panel per run (the thesis's port, ours, an external engine), as an
// animated GIF (gnuplot's gif terminal): every ball at each of about kGifFrames frames taken evenly
// from Result::series::frames (which hold more, for the viewer), in its engine's colour. A run that
// stopped early shows its last frame greyed, marked with when it stopped.
//
// gd, behind the gif terminal, fills a `with circles` disc as a polygon on whole pixels: small
// balls come out as octagons. Its own disc (point type 7) is round, sized in whole pixels (3 per
// unit of point size), so each panel's plot area is placed in pixels and a ball's point size is
// its radius in them. And a colour that first appears in a later frame comes out black: every
// colour a frame may use is in the first one (the frames grey), and text is black, whose
// antialiasing shades the titles of the first frame hold.
// How the GIF samples the runs' frames and lays their panels out.
struct AnimationLayout {
  size_t stride = 1, frames = 0;  // GIF frame k shows recorded frame k * stride
  size_t cols = 1;
  double pw = 0, ph = 0, width = 0, height = 0, scale = 0;  // plot area, canvas (pixels); pixels per metre
  View view;
  // The recorded frame a run shows at GIF frame k: its last one once it stopped.
  size_t held(const Result* r, size_t k) const { return std::min(k * stride, r->series.frames.size() - 1); }
};

constexpr std::string_view kStoppedGrey = "#bbbbbb";
constexpr double kSide = 400, kTitle = 26, kGap = 12, kGdPixelsPerPointSize = 3;

// Pixels: two columns from three runs on, each plot area at most kSide square, the view's shape.
AnimationLayout animation_layout(const std::vector<const Result*>& runs) {
  constexpr size_t kGifFrames = 80;  // 8 s at 10 frames per second, and the GIF under 2 MB
  AnimationLayout l;
  size_t recorded = 0;
  for (const Result* r : runs) recorded = std::max(recorded, r->series.frames.size());
  l.stride = std::max<size_t>(1, (recorded + kGifFrames - 1) / kGifFrames);
  l.frames = (recorded + l.stride - 1) / l.stride;
  std::vector<std::array<double, 2>> everything;
  double reach = 0;
  for (const Result* r : runs) {
    for (size_t b = 0; b < r->series.frames.front().size(); ++b) reach = std::max(reach, ball_radius(*r, b));
    for (size_t k = 0; k < l.frames; ++k)
      everything.insert(everything.end(), r->series.frames[l.held(r, k)].begin(), r->series.frames[l.held(r, k)].end());
  }
  l.view = scene_view(runs.front()->series.box, everything, reach);
  l.cols = runs.size() <= 2 ? runs.size() : 2;
  const size_t rows = (runs.size() + l.cols - 1) / l.cols;
  const double vw = l.view.x1 - l.view.x0, vh = l.view.y1 - l.view.y0;
  l.pw = std::round(vw >= vh ? kSide : kSide * vw / vh), l.ph = std::round(vw >= vh ? kSide * vh / vw : kSide);
  l.scale = l.pw / vw;  // the same both ways
  l.width = kGap + l.cols * (kSide + kGap), l.height = kGap + rows * (l.ph + kTitle + kGap);
  return l;
}

// Each run's balls, a gnuplot data block per GIF frame.
void write_animation_data(const std::vector<const Result*>& runs, const AnimationLayout& l, const std::string& base,
                          const fs::path& dir) {
  for (const Result* r : runs) {
    std::ofstream f(dir / fmt::format("{}-{}.dat", base, slug(run_label(*r))));
    for (size_t k = 0; k < l.frames; ++k) {
      const auto& frame = r->series.frames[l.held(r, k)];
      for (size_t b = 0; b < frame.size(); ++b) f << frame[b][0] << ' ' << frame[b][1] << ' ' << ball_radius(*r, b) << '\n';
      f << "\n\n";
    }
  }
}

// Run i's panel of GIF frame k.
void put_animation_panel(std::ostream& gp, const AnimationLayout& l, const Result* r, size_t i, size_t k,
                         const std::string& base) {
  const size_t h = l.held(r, k);
  const bool stopped = h < k * l.stride;
  const double t = r->series.frame_t[h];
  const double left = kGap + (i % l.cols) * (kSide + kGap) + (kSide - l.pw) / 2,
               top = kGap + (i / l.cols) * (l.ph + kTitle + kGap) + kTitle;
  gp << fmt::format("set lmargin at screen {}\nset rmargin at screen {}\nset tmargin at screen {}\nset bmargin at screen {}\n",
                    left / l.width, (left + l.pw) / l.width, 1 - top / l.height, 1 - (top + l.ph) / l.height)
     << "unset label\n";
  if (stopped)
    gp << "set title " << quoted(fmt::format("{}   t = {:.2f} s, its last frame", run_label(*r), t)) << "\nset label 1 "
       << quoted(fmt::format("{} at t = {:.2f} s", run_status_text(r->status), stop_time(*r)))
       << " at graph 0.5, graph 0.5 center front font ',13'\n";
  else
    gp << "set title " << quoted(fmt::format("{}   t = {:.1f} s", run_label(*r), t)) << "\n";
  if (const std::string note = outside_note(l.view, r->series.frames[h]); !note.empty())
    gp << "set label 2 " << quoted(note) << " at graph 0.02, graph 0.04 left front font ',9'\n";
  gp << fmt::format("plot '{0}-{1}.dat' index {2} using 1:2:(size($3)) with points pt 7 ps variable lc rgb '{3}', "
                    "'' index {2} using 1:2:(size($3)) with points pt 6 ps variable lc rgb '#404040'\n",
                    base, slug(run_label(*r)), k, stopped ? std::string(kStoppedGrey) : run_style(r->engine, r->profile).colour);
}

Figure animation_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
  const std::string base = slug(scene) + "-animation";
  const AnimationLayout l = animation_layout(runs);
  std::ofstream gp(dir / (base + ".gp"));
  gp << fmt::format("set terminal gif animate delay 10 optimize size {},{} font 'sans,10'\n", l.width, l.height)
     << "set termoption noenhanced\nset output '" << base << ".gif'\nunset key\nunset xtics\nunset ytics\n"
     << "set border lc rgb '" << kStoppedGrey << "'\n"
     << fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\n", l.view.x0, l.view.x1, l.view.y0, l.view.y1)
     << fmt::format("size(r) = r * {} / {}  # a radius in metres as a gd point size\n", l.scale, kGdPixelsPerPointSize);
  if (const auto& b = runs.front()->series.box)
    gp << fmt::format("set object 1 rect from {},{} to {},{} fs empty border rgb '#c03030' lw 2 back\n", (*b)[0], (*b)[1],
                      (*b)[2], (*b)[3]);
  write_animation_data(runs, l, base, dir);
  for (size_t k = 0; k < l.frames; ++k) {
    gp << "set multiplot\n";
    for (size_t i = 0; i < runs.size(); ++i) put_animation_panel(gp, l, runs[i], i, k, base);
    gp << "unset multiplot\n";
  }
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {FigureKind::animation, scene, "figures/" + base + ".gif",
          fmt::format("The scene in motion ({} frames, animated GIF): the thesis's algorithm, ours and an external "
                      "engine side by side, balls to scale in their engine's colour; a run that stopped early shows its "
                      "last frame greyed, with when and why it stopped.",
                      l.frames)};
}

// The trajectory viewer (viewer_page.h): every run of the scene that has frames, on one page.
Figure viewer_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
  const std::string file = slug(scene) + "-viewer.html";
  const std::string page = viewer_page(runs);
  write_file_atomically((dir / file).string(), page, "the viewer page");
  size_t frames = 0;
  for (const Result* r : runs) frames = std::max(frames, r->series.frames.size());
  return {FigureKind::viewer, scene, "figures/" + file,
          fmt::format("every engine and profile side by side, {} frames ({:.1f} MB, opens offline in any browser): "
                      "play, pause, scrub and speed, the tracks of four balls, every tunnelling and sticking event "
                      "marked where and when it happened (click one in the list to jump there), energy over time "
                      "beside the playback, one colour per engine as in these figures",
                      frames, static_cast<double>(page.size()) / 1e6)};
}

// Error against step time, log-log: per engine and profile a line through its step-size series
// (x error bars: the spread of the timing repeats), and its other knob settings as open points in
// the same colour. The reference itself (error 0) cannot be drawn on a log scale.
Figure work_precision_figure(const SweepResult& sw, const fs::path& dir) {
  const std::string base = slug(sw.scene) + "-work-precision";
  std::vector<std::string> order;  // engine/profile in the sweep's order
  std::map<std::string, std::string> looks, knob_looks;  // its line style; its knobs' points
  for (const SweepPoint& p : sw.points) {
    const std::string l = run_label(p.engine, p.profile);
    if (p.engine != sw.reference)
      add_once(order, l), looks[l] = linespoints_style(p.engine, p.profile), knob_looks[l] = open_points_style(p.engine, p.profile);
  }
  std::vector<double> dts;
  for (const SweepPoint& p : sw.points)
    if (p.knob == "dt") add_once(dts, p.dt);
  double ymax = 0;  // the largest error drawn
  std::string plot;
  for (size_t k = 0; k < order.size(); ++k) {
    const std::string name = slug(order[k]);
    std::ofstream line(dir / fmt::format("{}-{}-dt.dat", base, name)), knobs(dir / fmt::format("{}-{}-knobs.dat", base, name));
    int drawn = 0;
    for (const SweepPoint& p : sw.points) {
      if (run_label(p.engine, p.profile) != order[k] || p.status != RunStatus::ok || p.engine_s.empty() || !(p.pos_rms > 0)) continue;
      const auto [lo, hi] = std::minmax_element(p.engine_s.begin(), p.engine_s.end());
      (p.knob == "dt" ? line : knobs) << 1e3 * p.engine_s_median() << ' ' << p.pos_rms << ' ' << 1e3 * *lo << ' '
                                      << 1e3 * *hi << '\n';
      drawn += p.knob == "dt";
      ymax = std::max(ymax, p.pos_rms);
    }
    line << "\n", knobs << "\n";  // never empty: gnuplot rejects a data file without points
    if (drawn == 0) continue;
    plot += fmt::format("{}'{}-{}-dt.dat' using 1:2:3:4 with xerrorlines {} lw 2 ps 0.8 title '{}', "
                        "'{}-{}-knobs.dat' using 1:2 with points {} ps 1.2 notitle",
                        plot.empty() ? "" : ", ", base, name, looks[order[k]], order[k], base, name,
                        knob_looks[order[k]]);
  }
  // Two panels: every point, and the top two decades of error, where engines that differ by a
  // factor of two would otherwise share a pixel when another engine is at round-off.
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size 1300,560 font 'sans,10'\n"
     << "set output '" << base << ".png'\nset multiplot layout 1,2\n"
     << "set xlabel 'engine time to t = " << sw.horizon << " s (ms, median of " << sw.repeats << ")'\n"
     << "set ylabel 'position RMS error against " << sw.reference << " (m)'\n"
     << "set logscale xy\nset grid\nset key bottom right font ',8'\n"
     << "set title 'Work against precision, " << sw.scene << ": error at t = " << sw.horizon << " s'\n"
     << "plot " << (plot.empty() ? "1/0 notitle" : plot) << '\n'
     << "set title 'The same, top two decades of error'\nunset key\n"
     << fmt::format("set yrange [{}:{}]\n", ymax > 0 ? ymax / 100 : 1e-3, ymax > 0 ? ymax * 2 : 1.0)
     << "plot " << (plot.empty() ? "1/0 notitle" : plot) << '\n'
     << "unset multiplot\n";
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {FigureKind::work_precision, sw.scene, "figures/" + base + ".png",
          fmt::format("Work against precision on {}: each line is one engine and profile at the step sizes {} s "
                      "(cost grows as dt shrinks), x bars the spread of {} timing runs; open circles are the same "
                      "engine with one of its own knobs changed at the scene's dt (table below); the right panel "
                      "zooms on the top two decades of error. Lower left is better.",
                      sw.scene, fmt::join(dts, ", "), sw.repeats)};
}

// Why a benchmark point is missing, in a few words: its error's kind.
std::string missing_reason(const std::string& error) {
  if (error.starts_with("diverged")) return "diverged";
  if (error.find("budget") != std::string::npos) return "over the time budget";
  if (error.find("sub-steps") != std::string::npos) return "refused: more sub-steps than its cap";
  return "skipped";
}

// "Not drawn" lines for a scaling panel: per reason, each run and the ball counts it did not reach,
// wrapped to the figure's width.
std::vector<std::string> missing_lines(const std::vector<const BenchRow*>& failed) {
  std::vector<std::string> reasons, lines;
  std::map<std::string, std::vector<std::string>> runs;                   // reason -> run labels in order
  std::map<std::pair<std::string, std::string>, std::vector<long>> counts;  // (reason, run) -> ball counts
  for (const BenchRow* r : failed) {
    const std::string reason = missing_reason(r->error), label = run_label(r->engine, r->profile);
    add_once(reasons, reason);
    add_once(runs[reason], label);
    counts[{reason, label}].push_back(r->n);
  }
  constexpr size_t kWidth = 130;  // characters a line of the figure holds
  for (const std::string& reason : reasons) {
    std::string line = "Not drawn, " + reason + ":";
    for (size_t k = 0; k < runs[reason].size(); ++k) {
      const std::string& label = runs[reason][k];
      const std::string item = fmt::format(" {} ({}){}", label, fmt::join(counts[{reason, label}], ", "),
                                           k + 1 < runs[reason].size() ? ";" : "");
      if (line.size() + item.size() > kWidth) lines.push_back(line), line = "   ";
      line += item;
    }
    lines.push_back(line);
  }
  return lines;
}

// ns per ball-step against ball count, one figure per benchmark scene, one line per engine and
// profile in its palette style, the key beside the plot, and the points that are missing named
// under it. Log scales: ball counts span decades, and so do costs (an asleep pile costs next to
// nothing).
std::vector<Figure> scaling_figures(const BenchResults& bench, const fs::path& dir) {
  std::vector<std::string> scenes, order;
  std::map<std::string, std::string> looks;  // run label -> line style
  for (const BenchRow& r : bench.rows) {
    add_once(scenes, r.scene);
    const std::string l = run_label(r.engine, r.profile);
    add_once(order, l);
    looks[l] = linespoints_style(r.engine, r.profile);
  }
  std::vector<Figure> figures;
  for (const std::string& scene : scenes) {
    const std::string base = "scaling-" + slug(scene);
    std::string plot;
    std::vector<const BenchRow*> failed;
    for (const std::string& label : order) {
      const std::string data = fmt::format("{}-{}.dat", base, slug(label));
      std::ofstream f(dir / data);
      int points = 0;
      for (const BenchRow& r : bench.rows) {
        if (r.scene != scene || run_label(r.engine, r.profile) != label) continue;
        if (r.error.empty() && r.ns_per_ball_step > 0) f << r.n << ' ' << r.ns_per_ball_step << '\n', ++points;
        else failed.push_back(&r);
      }
      if (points)
        plot += fmt::format("{}'{}' with linespoints {} lw 2 ps 0.8 title {}", plot.empty() ? "" : ", ", data,
                            looks[label], quoted(label));
    }
    const std::vector<std::string> missing = missing_lines(failed);
    constexpr int kPlotHeight = 470, kLineHeight = 15;
    const int height = kPlotHeight + kLineHeight * static_cast<int>(missing.size());
    std::ofstream gp(dir / (base + ".gp"));
    gp << "set terminal pngcairo size 900," << height << " font 'sans,10'\nset termoption noenhanced\n"
       << "set output '" << base << ".png'\nset logscale xy\nset grid\nset key outside right top font ',9'\n"
       << "set format x '%.0f'\n"
       << "set xlabel 'balls'\nset ylabel 'engine ns per ball-step'\n"
       << fmt::format("set bmargin at screen {}\n", (kLineHeight * (missing.size() + 1.0) + 45) / height)
       << "set title " << quoted("Step cost against ball count, " + scene) << "\n";
    for (size_t k = 0; k < missing.size(); ++k)
      gp << "set label " << k + 1 << ' ' << quoted(missing[k]) << " at screen 0.01, screen "
         << (kLineHeight * (missing.size() - k) - 4.0) / height << " left font ',8' textcolor rgb '#b03030'\n";
    if (plot.empty()) gp << "set label 100 'no engine ran this scene' at graph 0.5, graph 0.5 center\nset xrange [1:10]\nset yrange [1:10]\n";
    gp << "plot " << (plot.empty() ? "1/0 notitle" : plot) << '\n';
    gp.close();
    run_gnuplot(dir / (base + ".gp"));
    figures.push_back({FigureKind::scaling, "", "figures/" + base + ".png",
                       fmt::format("Step cost against ball count on {} (bench/ballbench_step_benchmark, engine step "
                                   "only), one line per engine and profile, log-log: flat is linear scaling. Points "
                                   "an engine did not reach are named under the plot.",
                                   scene)});
  }
  return figures;
}

// Doublings each engine survived per knob, as clustered bars (engines along x, one bar per knob).
Figure frontier_figure(const FrontierResult& f, const fs::path& dir) {
  const std::string base = slug(f.scene) + "-frontier";
  std::vector<std::string> knobs, engines;
  for (const FrontierRow& r : f.rows) {
    add_once(knobs, r.knob);
    const std::string l = run_label(r.engine, r.profile);
    add_once(engines, l);
  }
  {
    std::ofstream d(dir / (base + ".dat"));
    d << "engine";
    for (const auto& k : knobs) d << ' ' << k;
    d << '\n';
    for (const auto& e : engines) {
      d << e;
      for (const auto& k : knobs) {
        int passed = 0;
        for (const FrontierRow& r : f.rows)
          if (run_label(r.engine, r.profile) == e && r.knob == k) passed = r.levels_passed;
        d << ' ' << passed;
      }
      d << '\n';
    }
  }
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size 1000,480 font 'sans,10'\n"
     << "set output '" << base << ".png'\n"
     << "set title 'Stability frontier, " << f.scene << ": levels passed of " << f.levels << " (level k: knob x 2^(k-1))'\n"
     << "set style data histogram\nset style histogram cluster gap 1\nset style fill solid 0.8 border -1\n"
     << "set boxwidth 0.9\nset yrange [0:" << f.levels + 0.5 << "]\nset ytics 1\nset grid y\nset key outside right\n"
     << "set xtics rotate by -30\nset ylabel 'levels passed'\n"
     << "plot for [k=2:" << knobs.size() + 1 << "] '" << base << ".dat' using k:xtic(1) title columnheader\n";
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {FigureKind::frontier, f.scene, "figures/" + base + ".png",
          fmt::format("Stability frontier on {}: for each engine, how many doublings of each knob it survived ({} "
                      "steps per run; a run fails on tunnelling, a non-finite state, or energy off the reference by "
                      "more than {:.0f}%). 0: the scene itself already failed.",
                      f.scene, f.steps, 100 * f.energy_tolerance)};
}

}  // namespace

std::vector<Figure> draw_figures(const ReportInputs& in, const std::string& out_dir) {
  const fs::path dir = fs::path(out_dir) / "figures";
  fs::create_directories(dir);
  const fs::path here = fs::current_path();
  fs::current_path(dir);  // gnuplot scripts name their data files relative to the figures folder
  std::vector<Figure> figures;
  try {
    std::vector<std::string> order;
    std::map<std::string, std::vector<const Result*>> by_scene;
    for (const auto& r : in.results) {
      if (!by_scene.contains(r.scene)) order.push_back(r.scene);
      by_scene[r.scene].push_back(&r);
    }
    for (const auto& scene : order) {
      if (auto energy = energy_figure(scene, by_scene[scene], in, ".")) figures.push_back(std::move(*energy));
      std::vector<const Result*> pictured;  // the thesis's algorithm beside ours
      for (const Result* r : by_scene[scene])
        if ((role_of(in, r->engine) == EngineRole::thesis || role_of(in, r->engine) == EngineRole::ours) &&
            !r->series.final_pos.empty()) pictured.push_back(r);
      if (!pictured.empty()) figures.push_back(scene_figure(scene, pictured, "."));
      // Animated: the thesis's port and ours, with the first external engine that ran to the end.
      std::vector<const Result*> animated;
      for (const Result* r : pictured)
        if (!r->series.frames.empty()) animated.push_back(r);
      for (const Result* r : by_scene[scene])
        if (role_of(in, r->engine) == EngineRole::external && r->status == RunStatus::ok && !r->series.frames.empty()) {
          animated.push_back(r);
          break;
        }
      if (animated.size() >= 2) figures.push_back(animation_figure(scene, animated, "."));
      if (std::any_of(by_scene[scene].begin(), by_scene[scene].end(), [](const Result* r) { return !r->series.frames.empty(); }))
        figures.push_back(viewer_figure(scene, by_scene[scene], "."));
    }
    for (const SweepResult& sw : in.sweeps) figures.push_back(work_precision_figure(sw, "."));
    for (Figure& f : front_figures(in)) figures.push_back(std::move(f));
    for (const FrontierResult& f : in.frontiers) figures.push_back(frontier_figure(f, "."));
    if (in.bench && !in.bench->rows.empty())
      for (Figure& f : scaling_figures(*in.bench, ".")) figures.push_back(std::move(f));
  } catch (...) {
    fs::current_path(here);
    throw;
  }
  fs::current_path(here);
  return figures;
}

}  // namespace ballbench

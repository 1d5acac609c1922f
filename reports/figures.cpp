#include "figures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "data_file.h"
#include "front_figures.h"
#include "gnuplot.h"
#include "ordered_set.h"
#include "palette.h"
#include "plot.h"
#include "viewer_page.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

// A series in a run's colour and dash (palette.h).
PlotSeries run_line(const std::string& engine, const std::string& profile, const std::string& data) {
  const RunStyle s = run_style(engine, profile);
  PlotSeries line;
  line.data = data, line.colour = s.colour, line.dash = s.dash;
  return line;
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

// The panel settings that frame a picture: the view, its axes' ranges.
void set_view(PlotPanel& p, const View& v) {
  p.x.range.min = v.x0, p.x.range.max = v.x1;
  p.y.range.min = v.y0, p.y.range.max = v.y1;
}

// The container's walls, red, over the balls or behind them.
std::vector<PlotRectangle> walls(const std::optional<std::array<double, 4>>& box, bool in_front) {
  if (!box) return {};
  return {{(*box)[0], (*box)[1], (*box)[2], (*box)[3], "#c03030", 2, in_front}};
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
PlotPanel energy_panel(const std::string& title, std::vector<PlotSeries> series) {
  PlotPanel p;
  p.title = title;
  p.x.label = "time (s)", p.y.label = "E / E0 (log scale)";
  p.log = LogAxes::y;
  p.y.range.floor = 1e-4, p.y.range.ceiling = 1e4;
  p.grid = Grid::xy;
  p.key.place = KeyPlace::outside_right_top, p.key.font = ",9";
  p.margins.left = 0.09, p.margins.right = 0.70;
  p.series = std::move(series);
  return p;
}

std::optional<Figure> energy_figure(const std::string& scene, const std::vector<const Result*>& runs,
                                    const ReportInputs& in) {
  Plot plot;
  plot.name = slug(scene) + "-energy";
  std::vector<PlotSeries> first, others;
  std::optional<PlotSeries> reference;
  for (const Result* r : runs) {
    const double e0 = r->metrics.value(Metric::energy_initial);
    if (r->series.t.empty() || e0 <= 0) continue;
    DataFile& f = plot.data.emplace_back(plot.name + "-" + slug(run_label(*r)) + ".dat");
    for (size_t k = 0; k < r->series.t.size(); ++k) f.blocks[0].add({r->series.t[k], r->series.energy[k] / e0});
    PlotSeries line = run_line(r->engine, r->profile, f.name);
    line.line_width = 2;
    // A run that stopped says when in its key: its line ends there, or leaves the plot.
    line.title = r->status == RunStatus::ok
                     ? run_label(*r)
                     : fmt::format("{} ({} at {:.3g} s)", run_label(*r), run_status_text(r->status), stop_time(*r));
    (line.dash == 1 ? first : others).push_back(line);
    if (role_of(in, r->engine) == EngineRole::reference)
      reference = line, reference->line_width = 1.5, reference->title = run_label(*r) + " (reference)";
  }
  if (first.empty() && others.empty()) return std::nullopt;
  const bool two = !first.empty() && !others.empty();
  if (two && reference) others.insert(others.begin(), *reference);
  constexpr int kPanelHeight = 360;
  plot.terminal.height = (two ? 2 : 1) * kPanelHeight + 20;
  plot.panels.push_back(energy_panel("Energy over time, " + scene + (two ? ": each engine's first profile" : ""),
                                     first.empty() ? others : first));
  if (two) {
    plot.layout = LayoutKind::grid, plot.rows = 2;
    plot.panels.push_back(energy_panel(scene + ": the other profiles (dashed)", others));
  }
  draw_plot(plot);
  return Figure{FigureKind::energy, scene, "figures/" + plot.output(),
                two ? "Energy over time relative to the start (log scale): above, each engine's first profile; below, "
                      "its other profiles (dashed), with the reference for comparison. One colour per engine, as in "
                      "every figure and the viewer; a run that stopped early says when in the key."
                    : "Energy over time relative to the start (log scale), one line per engine and profile; a run that "
                      "stopped early says when in the key."};
}

// A run's picture data: the balls at the end (x, y, radius), a block per tracked ball, the
// centre-of-mass trail; the series that read them, named NAME-balls.dat, -tracks.dat, -com.dat.
std::vector<PlotSeries> picture_series(const Result& r, const std::string& name, Plot& plot) {
  DataFile balls(name + "-balls.dat", 1, 3), tracks(name + "-tracks.dat", 0), com(name + "-com.dat");
  for (size_t b = 0; b < r.series.final_pos.size(); ++b)
    balls.blocks[0].add({r.series.final_pos[b][0], r.series.final_pos[b][1], ball_radius(r, b)});
  for (const auto& track : r.series.tracks) {
    DataBlock& block = tracks.blocks.emplace_back();
    for (const auto& p : track) block.add({p[0], p[1]});
  }
  for (size_t c = 0; c < r.series.com_x.size(); ++c) com.blocks[0].add({r.series.com_x[c], r.series.com_y[c]});
  const std::string colour = run_style(r.engine, r.profile).colour;
  // The same key under every panel, so that every panel keeps the same size.
  std::vector<PlotSeries> series(1);
  series[0].data = balls.name, series[0].columns = "1:2:3", series[0].style = SeriesStyle::circles;
  series[0].colour = colour, series[0].fill_opacity = 0.45, series[0].title = "balls";
  for (size_t b = 0; b < r.series.tracks.size(); ++b) {
    PlotSeries& track = series.emplace_back();
    track.data = tracks.name, track.index = static_cast<int>(b), track.columns = "1:2";
    track.colour = track_colour(static_cast<int>(b)), track.line_width = 1.2;
    track.title = fmt::format("track of ball {}", b);
  }
  PlotSeries& trail = series.emplace_back();
  trail.data = com.name, trail.columns = "1:2", trail.title = "centre of mass";
  trail.colour = "#303030", trail.line_width = 2;
  plot.data.push_back(std::move(balls)), plot.data.push_back(std::move(tracks)), plot.data.push_back(std::move(com));
  return series;
}

// One panel per run, like the thesis's figures 3 to 5: the balls at the end (each its own radius,
// in its engine's colour), the tracks of the first balls (a colour per ball), and the
// centre-of-mass trail; the container's walls, and every ball that left it, in view, axes in metres.
Figure scene_figure(const std::string& scene, const std::vector<const Result*>& runs) {
  const size_t cols = std::min<size_t>(3, runs.size()), rows = (runs.size() + cols - 1) / cols;
  const int side = cols == 1 ? 560 : cols == 2 ? 450 : 310;
  Plot plot;
  plot.name = slug(scene) + "-picture";
  plot.terminal.width = double(side * cols), plot.terminal.height = double((side + 70) * rows);
  plot.layout = LayoutKind::grid, plot.rows = int(rows), plot.columns = int(cols);
  std::vector<std::array<double, 2>> everything;
  double reach = 0;
  for (const Result* r : runs) {
    for (size_t b = 0; b < r->series.final_pos.size(); ++b) reach = std::max(reach, ball_radius(*r, b));
    everything.insert(everything.end(), r->series.final_pos.begin(), r->series.final_pos.end());
  }
  const View view = scene_view(runs.front()->series.box, everything, reach);
  for (const Result* r : runs) {
    PlotPanel& p = plot.panels.emplace_back();
    p.x.label = "x (m)", p.y.label = "y (m)", p.y.label_offset = 1;
    p.key.place = KeyPlace::below, p.key.font = ",8", p.key.sample_length = 2;
    p.equal_scales = true;
    set_view(p, view);
    p.rectangles = walls(runs.front()->series.box, true);
    const std::string stopped = r->status == RunStatus::ok ? "" : fmt::format(" ({})", run_status_text(r->status));
    p.title = fmt::format("{} at t = {:.3g} s{}", run_label(*r), r->series.t.empty() ? 0.0 : r->series.t.back(), stopped);
    if (const std::string note = outside_note(view, r->series.final_pos); !note.empty())
      p.labels.push_back({note, Coordinates::graph, 0.02, 0.97, Align::left, ",8", "#b03030"});
    p.series = picture_series(*r, plot.name + "-" + slug(run_label(*r)), plot);
  }
  draw_plot(plot);
  return {FigureKind::picture, scene, "figures/" + plot.output(),
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

// Each run's balls (x, y, radius), a gnuplot data block per GIF frame, in NAME-RUN.dat.
void add_animation_data(const std::vector<const Result*>& runs, const AnimationLayout& l, Plot& plot) {
  for (const Result* r : runs) {
    DataFile& f = plot.data.emplace_back(fmt::format("{}-{}.dat", plot.name, slug(run_label(*r))), 0);
    for (size_t k = 0; k < l.frames; ++k) {
      const auto& frame = r->series.frames[l.held(r, k)];
      DataBlock& block = f.blocks.emplace_back(3);
      for (size_t b = 0; b < frame.size(); ++b) block.add({frame[b][0], frame[b][1], ball_radius(*r, b)});
    }
  }
}

// Run i's panel of GIF frame k: `common` placed in pixels, titled, with the run's balls.
PlotPanel animation_panel(const PlotPanel& common, const AnimationLayout& l, const Result* r, size_t i, size_t k,
                          const std::string& base) {
  const size_t h = l.held(r, k);
  const bool stopped = h < k * l.stride;
  const double t = r->series.frame_t[h];
  const double left = kGap + (i % l.cols) * (kSide + kGap) + (kSide - l.pw) / 2,
               top = kGap + (i / l.cols) * (l.ph + kTitle + kGap) + kTitle;
  PlotPanel p = common;
  p.margins = {left / l.width, (left + l.pw) / l.width, 1 - top / l.height, 1 - (top + l.ph) / l.height};
  if (stopped) {
    p.title = fmt::format("{}   t = {:.2f} s, its last frame", run_label(*r), t);
    const std::string when = fmt::format("{} at t = {:.2f} s", run_status_text(r->status), stop_time(*r));
    p.labels.push_back({when, Coordinates::graph, 0.5, 0.5, Align::centre, ",13", ""});
  } else {
    p.title = fmt::format("{}   t = {:.1f} s", run_label(*r), t);
  }
  if (const std::string note = outside_note(l.view, r->series.frames[h]); !note.empty())
    p.labels.push_back({note, Coordinates::graph, 0.02, 0.04, Align::left, ",9", ""});
  const std::string data = fmt::format("{}-{}.dat", base, slug(run_label(*r)));
  // The radius in metres as a gd point size, its third column.
  const std::string columns = fmt::format("1:2:($3 * {} / {})", l.scale, kGdPixelsPerPointSize);
  const std::string colour = stopped ? std::string(kStoppedGrey) : run_style(r->engine, r->profile).colour;
  p.series.assign(2, PlotSeries{});
  for (PlotSeries& s : p.series) {
    s.data = data, s.index = int(k), s.columns = columns, s.style = SeriesStyle::points;
    s.point_size_from_column = true;
  }
  p.series[0].colour = colour, p.series[0].point = 7;     // the disc
  p.series[1].colour = "#404040", p.series[1].point = 6;  // its outline
  return p;
}

Figure animation_figure(const std::string& scene, const std::vector<const Result*>& runs) {
  const AnimationLayout l = animation_layout(runs);
  Plot plot;
  plot.name = slug(scene) + "-animation";
  plot.terminal.kind = TerminalKind::animated_gif, plot.terminal.width = l.width, plot.terminal.height = l.height;
  plot.layout = LayoutKind::free, plot.panels_per_frame = runs.size();
  PlotPanel common;
  common.key.place = KeyPlace::hidden;
  common.x.tics = common.y.tics = false;
  common.border_colour = kStoppedGrey;
  set_view(common, l.view);
  common.rectangles = walls(runs.front()->series.box, false);
  add_animation_data(runs, l, plot);
  for (size_t k = 0; k < l.frames; ++k)
    for (size_t i = 0; i < runs.size(); ++i)
      plot.panels.push_back(animation_panel(common, l, runs[i], i, k, plot.name));
  draw_plot(plot);
  return {FigureKind::animation, scene, "figures/" + plot.output(),
          fmt::format("The scene in motion ({} frames, animated GIF): the thesis's algorithm, ours and an external "
                      "engine side by side, balls to scale in their engine's colour; a run that stopped early shows its "
                      "last frame greyed, with when and why it stopped.",
                      l.frames)};
}

// The trajectory viewer (viewer_page.h): every run of the scene that has frames, on one page.
Figure viewer_figure(const std::string& scene, const std::vector<const Result*>& runs) {
  const std::string file = slug(scene) + "-viewer.html";
  const std::string page = viewer_page(runs);
  write_file_atomically(file, page, "the viewer page");
  size_t frames = 0;
  for (const Result* r : runs) frames = std::max(frames, r->series.frames.size());
  return {FigureKind::viewer, scene, "figures/" + file,
          fmt::format("every engine and profile side by side, {} frames ({:.1f} MB, opens offline in any browser): "
                      "play, pause, scrub and speed, the tracks of four balls, every tunnelling and sticking event "
                      "marked where and when it happened (click one in the list to jump there), energy over time "
                      "beside the playback, one colour per engine as in these figures",
                      frames, static_cast<double>(page.size()) / 1e6)};
}

// Per engine and profile (but the reference) its step-size line, x bars from the timing repeats'
// spread, and its other knob settings as open points, their data files added to `plot`; `ymax`
// the largest error among them.
std::vector<PlotSeries> work_precision_series(const SweepResult& sw, Plot& plot, double& ymax) {
  std::vector<std::string> order;     // engine/profile in the sweep's order
  std::map<std::string, RunStyle> looks;  // its palette style
  for (const SweepPoint& p : sw.points) {
    const std::string label = run_label(p.engine, p.profile);
    if (p.engine != sw.reference) add_once(order, label), looks[label] = run_style(p.engine, p.profile);
  }
  std::vector<PlotSeries> series;
  for (const std::string& label : order) {
    DataFile line(fmt::format("{}-{}-dt.dat", plot.name, slug(label)), 1, 4),
        knobs(fmt::format("{}-{}-knobs.dat", plot.name, slug(label)), 1, 4);
    for (const SweepPoint& p : sw.points) {
      if (run_label(p.engine, p.profile) != label || p.status != RunStatus::ok || p.engine_s.empty() || !(p.pos_rms > 0)) continue;
      const auto [lo, hi] = std::minmax_element(p.engine_s.begin(), p.engine_s.end());
      (p.knob == "dt" ? line : knobs).blocks[0].add({1e3 * p.engine_s_median(), p.pos_rms, 1e3 * *lo, 1e3 * *hi});
      ymax = std::max(ymax, p.pos_rms);
    }
    if (line.blocks[0].rows() == 0) continue;
    const RunStyle& s = looks[label];
    PlotSeries& steps = series.emplace_back();
    steps.data = line.name, steps.columns = "1:2:3:4", steps.style = SeriesStyle::xerrorlines, steps.title = label;
    steps.colour = s.colour, steps.dash = s.dash, steps.point = s.point, steps.point_size = 0.8, steps.line_width = 2;
    PlotSeries& knob_points = series.emplace_back();
    knob_points.data = knobs.name, knob_points.columns = "1:2", knob_points.style = SeriesStyle::points;
    knob_points.colour = s.colour, knob_points.point = s.open_point(), knob_points.point_size = 1.2;
    plot.data.push_back(std::move(line)), plot.data.push_back(std::move(knobs));
  }
  return series;
}

// Error against step time, log-log, the lines and points of work_precision_series. The reference
// itself (error 0) cannot be drawn on a log scale.
Figure work_precision_figure(const SweepResult& sw) {
  Plot plot;
  plot.name = slug(sw.scene) + "-work-precision";
  plot.terminal.width = 1300, plot.terminal.height = 560, plot.terminal.enhanced_text = true;
  plot.layout = LayoutKind::grid, plot.rows = 1, plot.columns = 2;
  double ymax = 0;  // the largest error drawn
  PlotPanel all;
  all.series = work_precision_series(sw, plot, ymax);
  all.title = fmt::format("Work against precision, {}: error at t = {:g} s", sw.scene, sw.horizon);
  all.x.label = fmt::format("engine time to t = {:g} s (ms, median of {})", sw.horizon, sw.repeats);
  all.y.label = fmt::format("position RMS error against {} (m)", sw.reference);
  all.log = LogAxes::xy;
  all.grid = Grid::xy;
  all.key.place = KeyPlace::bottom_right, all.key.font = ",8";
  // Two panels: every point, and the top two decades of error, where engines that differ by a
  // factor of two would otherwise share a pixel when another engine is at round-off.
  PlotPanel top = all;
  top.title = "The same, top two decades of error";
  top.key.place = KeyPlace::hidden;
  top.y.range.min = ymax > 0 ? ymax / 100 : 1e-3, top.y.range.max = ymax > 0 ? ymax * 2 : 1.0;
  plot.panels = {all, top};
  draw_plot(plot);
  std::vector<double> dts;
  for (const SweepPoint& p : sw.points)
    if (p.knob == "dt") add_once(dts, p.dt);
  return {FigureKind::work_precision, sw.scene, "figures/" + plot.output(),
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

// ns per ball-step against ball count on one benchmark scene, one line per engine and profile in
// `order` in its palette style, the key beside the plot, and the points that are missing named
// under it. Log scales: ball counts span decades, and so do costs (an asleep pile costs next to
// nothing).
Figure scaling_figure(const BenchResults& bench, const std::string& scene, const std::vector<std::string>& order,
                      const std::map<std::string, RunStyle>& looks) {
  Plot plot;
  plot.name = "scaling-" + slug(scene);
  PlotPanel& p = plot.panels.emplace_back();
  std::vector<const BenchRow*> failed;
  for (const std::string& label : order) {
    DataFile f(fmt::format("{}-{}.dat", plot.name, slug(label)));
    for (const BenchRow& r : bench.rows) {
      if (r.scene != scene || run_label(r.engine, r.profile) != label) continue;
      if (r.error.empty() && r.ns_per_ball_step > 0) f.blocks[0].add({double(r.n), r.ns_per_ball_step});
      else failed.push_back(&r);
    }
    if (f.blocks[0].rows() == 0) continue;
    const RunStyle& s = looks.at(label);
    PlotSeries& line = p.series.emplace_back();
    line.data = f.name, line.style = SeriesStyle::linespoints, line.title = label;
    line.colour = s.colour, line.dash = s.dash, line.point = s.point, line.point_size = 0.8, line.line_width = 2;
    plot.data.push_back(std::move(f));
  }
  const std::vector<std::string> missing = missing_lines(failed);
  constexpr int kPlotHeight = 470, kLineHeight = 15;
  plot.terminal.height = kPlotHeight + kLineHeight * static_cast<int>(missing.size());
  p.title = "Step cost against ball count, " + scene;
  p.x.label = "balls", p.y.label = "engine ns per ball-step";
  p.x.format = "%.0f";
  p.log = LogAxes::xy;
  p.grid = Grid::xy;
  p.key.place = KeyPlace::outside_right_top, p.key.font = ",9";
  p.margins.bottom = (kLineHeight * (missing.size() + 1.0) + 45) / plot.terminal.height;
  for (size_t k = 0; k < missing.size(); ++k)
    p.labels.push_back({missing[k], Coordinates::screen, 0.01,
                        (kLineHeight * (missing.size() - k) - 4.0) / plot.terminal.height, Align::left, ",8", "#b03030"});
  if (p.series.empty()) {
    p.labels.push_back({"no engine ran this scene", Coordinates::graph, 0.5, 0.5, Align::centre, "", ""});
    p.x.range.min = p.y.range.min = 1, p.x.range.max = p.y.range.max = 10;
  }
  draw_plot(plot);
  return {FigureKind::scaling, "", "figures/" + plot.output(),
          fmt::format("Step cost against ball count on {} (bench/ballbench_step_benchmark, engine step only), one "
                      "line per engine and profile, log-log: flat is linear scaling. Points an engine did not reach "
                      "are named under the plot.",
                      scene)};
}

std::vector<Figure> scaling_figures(const BenchResults& bench) {
  std::vector<std::string> scenes, order;
  std::map<std::string, RunStyle> looks;  // run label -> its palette style
  for (const BenchRow& r : bench.rows) {
    add_once(scenes, r.scene);
    add_once(order, run_label(r.engine, r.profile));
    looks[run_label(r.engine, r.profile)] = run_style(r.engine, r.profile);
  }
  std::vector<Figure> figures;
  for (const std::string& scene : scenes) figures.push_back(scaling_figure(bench, scene, order, looks));
  return figures;
}

// Doublings each engine survived per knob, as clustered bars (engines along x, one bar per knob).
Figure frontier_figure(const FrontierResult& f) {
  Plot plot;
  plot.name = slug(f.scene) + "-frontier";
  plot.terminal.width = 1000, plot.terminal.height = 480, plot.terminal.enhanced_text = true;
  std::vector<std::string> knobs, engines;
  for (const FrontierRow& r : f.rows) add_once(knobs, r.knob), add_once(engines, run_label(r.engine, r.profile));
  DataFile& d = plot.data.emplace_back(plot.name + ".dat", 1, knobs.size());
  d.column_names = {"engine"};
  d.column_names.insert(d.column_names.end(), knobs.begin(), knobs.end());
  for (const auto& e : engines) {
    d.blocks[0].row_names.push_back(e);
    for (const auto& k : knobs) {
      int passed = 0;
      for (const FrontierRow& r : f.rows)
        if (run_label(r.engine, r.profile) == e && r.knob == k) passed = r.levels_passed;
      d.blocks[0].values.push_back(passed);
    }
  }
  PlotPanel& p = plot.panels.emplace_back();
  p.title = fmt::format("Stability frontier, {}: levels passed of {} (level k: knob x 2^(k-1))", f.scene, f.levels);
  p.extra_commands = {"set style histogram cluster gap 1", "set style fill solid 0.8 border -1", "set boxwidth 0.9"};
  p.y.range.min = 0, p.y.range.max = f.levels + 0.5;
  p.y.tic_step = 1;
  p.grid = Grid::y;
  p.key.place = KeyPlace::outside_right;
  p.x.tic_rotation = -30;
  p.y.label = "levels passed";
  for (size_t k = 0; k < knobs.size(); ++k) {
    PlotSeries& bars = p.series.emplace_back();
    bars.data = d.name, bars.columns = fmt::format("{}:xtic(1)", k + 2), bars.style = SeriesStyle::histograms;
    bars.title_from_column_header = true;
  }
  draw_plot(plot);
  return {FigureKind::frontier, f.scene, "figures/" + plot.output(),
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
  fs::current_path(dir);  // the plots and the viewer page are written into the working folder (plot.h)
  std::vector<Figure> figures;
  try {
    std::vector<std::string> order;
    std::map<std::string, std::vector<const Result*>> by_scene;
    for (const auto& r : in.results) {
      if (!by_scene.contains(r.scene)) order.push_back(r.scene);
      by_scene[r.scene].push_back(&r);
    }
    for (const auto& scene : order) {
      if (auto energy = energy_figure(scene, by_scene[scene], in)) figures.push_back(std::move(*energy));
      std::vector<const Result*> pictured;  // the thesis's algorithm beside ours
      for (const Result* r : by_scene[scene])
        if ((role_of(in, r->engine) == EngineRole::thesis || role_of(in, r->engine) == EngineRole::ours) &&
            !r->series.final_pos.empty()) pictured.push_back(r);
      if (!pictured.empty()) figures.push_back(scene_figure(scene, pictured));
      // Animated: the thesis's port and ours, with the first external engine that ran to the end.
      std::vector<const Result*> animated;
      for (const Result* r : pictured)
        if (!r->series.frames.empty()) animated.push_back(r);
      for (const Result* r : by_scene[scene])
        if (role_of(in, r->engine) == EngineRole::external && r->status == RunStatus::ok && !r->series.frames.empty()) {
          animated.push_back(r);
          break;
        }
      if (animated.size() >= 2) figures.push_back(animation_figure(scene, animated));
      if (std::any_of(by_scene[scene].begin(), by_scene[scene].end(), [](const Result* r) { return !r->series.frames.empty(); }))
        figures.push_back(viewer_figure(scene, by_scene[scene]));
    }
    for (const SweepResult& sw : in.sweeps) figures.push_back(work_precision_figure(sw));
    for (Figure& f : front_figures(in)) figures.push_back(std::move(f));
    for (const FrontierResult& f : in.frontiers) figures.push_back(frontier_figure(f));
    if (in.bench && !in.bench->rows.empty())
      for (Figure& f : scaling_figures(*in.bench)) figures.push_back(std::move(f));
  } catch (...) {
    fs::current_path(here);
    throw;
  }
  fs::current_path(here);
  return figures;
}

}  // namespace ballbench

#include "front_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "gnuplot.h"
#include "palette.h"
#include "plot.h"
#include "result.h"

namespace ballbench {
namespace {

// Where a front measures error: the spec's principal term (accuracy_spec.h), or the worst term over
// its bound where the spec bounds only counts and the horizon.
struct ErrorAxis {
  std::optional<SpecTerm> term;
  double bound = 1;  // the spec's line on the axis
  std::string label;
};

ErrorAxis error_axis(const AccuracySpec& spec) {
  ErrorAxis a;
  a.term = principal_term(spec);
  if (a.term) {
    const SpecTermDef& d = spec_term(*a.term);
    a.bound = *spec[*a.term];
    a.label = fmt::format("{}{}{}{} (at most {:g} meets the spec)", d.key, *d.unit ? " (" : "", d.unit, *d.unit ? ")" : "",
                          a.bound);
  } else {
    a.label = "error / spec: the worst term over its bound (at most 1 meets the spec)";
  }
  return a;
}

// A figure of 0 cannot sit on a log axis: it is drawn at a thousandth of the spec's bound.
double on_log_axis(double x, const ErrorAxis& axis) { return std::max(x, axis.bound * 1e-3); }

// Where a try lies on an axis of the worst term over its bound (1: the spec): its miss, drawn at
// 0.001 at least (a try at 0 on every term).
double spec_axis_x(const MatchTry& t, const AccuracySpec& spec) { return std::max(miss(t, spec), 1e-3); }

// One engine and profile's tries on a front: its data file, its palette style.
struct FrontSeries {
  std::string label, data;
  RunStyle style;
  double x_max = 0;  // the largest error drawn
};

// The x range of a panel of `series` whose spec's line is at `bound`: the line inside the plot, not
// on its edge, where every point lies left of it (gnuplot's own `2<*` is lost to its log tics).
PlotRange x_range(const std::vector<FrontSeries>& series, double bound) {
  double x_max = 0;
  for (const FrontSeries& s : series) x_max = std::max(x_max, s.x_max);
  PlotRange range;
  if (x_max < 2 * bound) range.max = 2 * bound;
  return range;
}

// One data file per engine and profile, added to `plot`: block 0 the profile as it is from dt down
// (the line), block 1 the tries that met the spec, block 2 those that did not. None when no try
// ran ok.
std::optional<FrontSeries> front_series(const MatchResult& m, const MatchOutcome& oc, const ErrorAxis& axis,
                                        const std::string& base, bool normalised, Plot& plot) {
  std::vector<const MatchTry*> mine;
  for (const MatchTry& t : m.tries)
    if (t.engine == oc.engine && t.profile == oc.profile && front_error(t, m.spec)) mine.push_back(&t);
  if (mine.empty()) return std::nullopt;
  FrontSeries s{run_label(oc.engine, oc.profile), fmt::format("{}-{}.dat", base, slug(run_label(oc.engine, oc.profile))),
                run_style(oc.engine, oc.profile)};
  // Normalised (or a spec of counts alone): the worst term over its bound (1 is the spec on every panel).
  const auto x_of = [&](const MatchTry& t) {
    return normalised || !axis.term ? spec_axis_x(t, m.spec) : on_log_axis(*front_error(t, m.spec), axis);
  };
  std::vector<const MatchTry*> as_is;
  for (const MatchTry* t : mine)
    if (t->knob.empty()) as_is.push_back(t);
  std::sort(as_is.begin(), as_is.end(), [](auto* a, auto* b) { return a->halvings < b->halvings; });
  DataFile f(s.data, 3);
  for (const MatchTry* t : mine) s.x_max = std::max(s.x_max, x_of(*t));
  for (const MatchTry* t : as_is) f.blocks[0].add({x_of(*t), t->cost_ns});
  for (const MatchTry* t : mine) f.blocks[t->met ? 1 : 2].add({x_of(*t), t->cost_ns});
  plot.data.push_back(std::move(f));
  return s;
}

// Per engine and profile: its line (in the key where `titles`), the tries that met the spec filled,
// those that did not open.
std::vector<PlotSeries> front_plot_series(const std::vector<FrontSeries>& series, bool titles) {
  std::vector<PlotSeries> out;
  for (const FrontSeries& s : series) {
    PlotSeries line, met, missed;
    line.data = met.data = missed.data = s.data;
    line.colour = met.colour = missed.colour = s.style.colour;
    line.index = 0, line.dash = s.style.dash, line.line_width = 2;
    if (titles) line.title = s.label;
    met.index = 1, met.style = SeriesStyle::points, met.point = s.style.point, met.point_size = 1.2;
    missed.index = 2, missed.style = SeriesStyle::points, missed.point = s.style.open_point(), missed.point_size = 1.2;
    out.insert(out.end(), {line, met, missed});
  }
  return out;
}

// The picks, ringed: the cheapest external configuration that met the spec, and ours; their data
// file added to `plot`.
PlotSeries picks_series(const MatchResult& m, const std::string& base, Plot& plot) {
  DataFile f(base + "-picks.dat");
  for (const char* role : {"external", "ours"})
    if (const MatchOutcome* oc = cheapest_reached(m, role)) {
      const MatchTry& t = m.tries[oc->found];
      f.blocks[0].add({spec_axis_x(t, m.spec), t.cost_ns});
    }
  PlotSeries picks;
  picks.data = f.name, picks.style = SeriesStyle::points, picks.colour = "#000000";
  picks.point = 6, picks.point_size = 3, picks.line_width = 2;
  if (f.blocks[0].rows()) picks.title = "the picks";
  plot.data.push_back(std::move(f));
  return picks;
}

std::string not_drawn(const MatchResult& m) {
  std::vector<std::string> names;
  for (const MatchOutcome& oc : m.outcomes) {
    bool any = false;
    for (const MatchTry& t : m.tries)
      any = any || (t.engine == oc.engine && t.profile == oc.profile && front_error(t, m.spec));
    if (!any) names.push_back(run_label(oc.engine, oc.profile));
  }
  return names.empty() ? "" : fmt::format(" Not drawn (no run ended ok): {}.", fmt::join(names, ", "));
}

// A front's panel: cost against the worst term over its bound, log-log, the spec's line at 1;
// `series` and the picks.
PlotPanel front_panel(const std::vector<FrontSeries>& series, bool titles, PlotSeries picks) {
  PlotPanel p;
  p.log = LogAxes::xy;
  p.x.format = p.y.format = "%g";
  p.grid = Grid::xy;
  p.vertical_lines = {{.x = 1, .dash = 2, .width = 1.5, .colour = "#000000"}};
  p.x.range = x_range(series, 1);
  p.series = front_plot_series(series, titles);
  p.series.push_back(std::move(picks));
  return p;
}

Figure scene_front(const MatchResult& m) {
  const ErrorAxis axis = error_axis(m.spec);
  Plot plot;
  plot.name = slug(m.scene) + "-front";
  plot.terminal.width = 900, plot.terminal.height = 520, plot.terminal.enhanced_text = true;
  std::vector<FrontSeries> series;
  for (const MatchOutcome& oc : m.outcomes)
    if (auto s = front_series(m, oc, axis, plot.name, true, plot)) series.push_back(std::move(*s));
  PlotPanel p = front_panel(series, true, picks_series(m, plot.name, plot));
  p.title = fmt::format("Equal accuracy on {}: cost against error, every configuration tried", m.scene);
  p.x.label = "error / spec: the worst term over its bound (at most 1 meets the spec)";
  p.y.label = "cost (ns per ball per scene step)";
  p.key.place = KeyPlace::outside_right_top;
  plot.panels.push_back(std::move(p));
  draw_plot(plot);
  return {FigureKind::front, m.scene, "figures/" + plot.output(),
          fmt::format("Cost against error on `{}`, on the overview's axes: each engine and profile's tries, the "
                      "profile as it is from dt down (the line) and each knob on top of it, the error the spec's worst "
                      "term over its bound; filled: met the spec ({}), open: did not; ringed: the picks (the cheapest "
                      "external engine and ours that met it); the dashed line is the spec. A try at 0 on every term "
                      "is drawn at 0.001.{}",
                      m.scene, m.spec.text(), not_drawn(m))};
}

// The legend of every scene's fronts, in a panel of its own: every engine and profile once, drawn
// as its line with its markers.
PlotPanel fronts_legend(const std::vector<FrontSeries>& legend, PanelPlace place) {
  PlotPanel p;
  p.place = place;
  p.border = false;
  p.x.tics = p.y.tics = false;
  p.x.range.min = p.y.range.min = 0, p.x.range.max = p.y.range.max = 1;
  p.key.place = KeyPlace::centre, p.key.horizontal_rows = 4, p.key.width = 2;
  for (const FrontSeries& l : legend) {
    PlotSeries& entry = p.series.emplace_back();
    entry.expression = "NaN", entry.style = SeriesStyle::linespoints, entry.title = l.label;
    entry.colour = l.style.colour, entry.dash = l.style.dash, entry.point = l.style.point, entry.line_width = 2;
  }
  return p;
}

// Every scene's front in one figure, the error over the spec's bound so that 1 means the spec on
// each panel; the legend in a panel of its own below them.
Figure all_fronts(const std::vector<MatchResult>& matches) {
  const int columns = matches.size() > 1 ? 2 : 1, rows = int(matches.size() + columns - 1) / columns;
  const double panel_h = 340, legend_h = 150, height = rows * panel_h + legend_h;
  Plot plot;
  plot.name = "fronts", plot.layout = LayoutKind::free;
  plot.terminal.width = columns * 480.0, plot.terminal.height = double(int(height)), plot.terminal.enhanced_text = true;
  std::vector<FrontSeries> legend;
  for (size_t k = 0; k < matches.size(); ++k) {
    const MatchResult& m = matches[k];
    const ErrorAxis axis = error_axis(m.spec);
    const std::string base = slug(m.scene) + "-fronts";
    std::vector<FrontSeries> series;
    for (const MatchOutcome& oc : m.outcomes)
      if (auto s = front_series(m, oc, axis, base, true, plot)) {
        if (std::none_of(legend.begin(), legend.end(), [&](const FrontSeries& l) { return l.label == s->label; }))
          legend.push_back(*s);
        series.push_back(std::move(*s));
      }
    PlotPanel p = front_panel(series, false, picks_series(m, base, plot));
    const int row = int(k) / columns, col = int(k) % columns;
    p.place = PanelPlace{double(col) / columns, (height - (row + 1) * panel_h) / height, 1.0 / columns,
                         panel_h / height};
    p.title = fmt::format("{} ({})", m.scene, m.scene_class);
    p.x.label = "error / spec (the worst term)", p.y.label = "ns per ball per scene step";
    p.key.place = KeyPlace::hidden;
    plot.panels.push_back(std::move(p));
  }
  plot.panels.push_back(fronts_legend(legend, {0, 0, 1, legend_h / height}));
  draw_plot(plot);
  return {FigureKind::fronts, "", "figures/" + plot.output(),
          "Every scene's work-precision front: cost against the spec's worst term over its bound (the dashed "
          "line at 1: at most 1 meets the spec; 0 drawn at 0.001), each engine and profile's tries; filled: met the "
          "spec, open: did not; ringed: the picks (the cheapest external engine and ours that met it). Each engine has "
          "its colour, each profile its marker and line (terms: profiles)."};
}

}  // namespace

std::vector<Figure> front_figures(const ReportInputs& in) {
  std::vector<Figure> out;
  for (const MatchResult& m : in.matches) out.push_back(scene_front(m));
  if (!in.matches.empty()) out.push_back(all_fronts(in.matches));
  return out;
}

}  // namespace ballbench

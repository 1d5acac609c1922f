#include "front_figures.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "gnuplot.h"
#include "palette.h"
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

struct Series {
  std::string label, data;
  RunStyle style;
  double x_max = 0;  // the largest error drawn
};

// The x range of a panel of `series` whose spec's line is at `bound`: the line inside the plot, not
// on its edge, where every point lies left of it (gnuplot's own `2<*` is lost to its log tics).
std::string x_range(const std::vector<Series>& series, double bound) {
  double x_max = 0;
  for (const Series& s : series) x_max = std::max(x_max, s.x_max);
  return x_max < 2 * bound ? fmt::format("set xrange [*:{}]\n", 2 * bound) : "set xrange [*:*]\n";
}

// One data file per engine and profile: block 0 the profile as it is from dt down (the line),
// block 1 the tries that met the spec, block 2 those that did not. None when no try ran ok.
std::optional<Series> write_series(const MatchResult& m, const MatchOutcome& oc, const ErrorAxis& axis,
                                   const std::string& base, bool normalised) {
  std::vector<const MatchTry*> mine;
  for (const MatchTry& t : m.tries)
    if (t.engine == oc.engine && t.profile == oc.profile && front_error(t, m.spec)) mine.push_back(&t);
  if (mine.empty()) return std::nullopt;
  Series s{run_label(oc.engine, oc.profile), fmt::format("{}-{}.dat", base, slug(run_label(oc.engine, oc.profile))),
           run_style(oc.engine, oc.profile)};
  std::ofstream f(s.data);
  // Normalised (or a spec of counts alone): the worst term over its bound (1 is the spec on every panel).
  const auto x_of = [&](const MatchTry& t) {
    return normalised || !axis.term ? spec_axis_x(t, m.spec) : on_log_axis(*front_error(t, m.spec), axis);
  };
  std::vector<const MatchTry*> as_is;
  for (const MatchTry* t : mine)
    if (t->knob.empty()) as_is.push_back(t);
  std::sort(as_is.begin(), as_is.end(), [](auto* a, auto* b) { return a->halvings < b->halvings; });
  for (const MatchTry* t : mine) s.x_max = std::max(s.x_max, x_of(*t));
  for (const MatchTry* t : as_is) f << x_of(*t) << ' ' << t->cost_ns << '\n';
  // An empty block would shift the blocks after it: gnuplot does not count leading blank lines.
  if (as_is.empty()) f << "NaN NaN\n";
  for (bool met : {true, false}) {
    f << "\n\n";
    int n = 0;
    for (const MatchTry* t : mine)
      if (t->met == met) f << x_of(*t) << ' ' << t->cost_ns << '\n', ++n;
    if (n == 0) f << "NaN NaN\n";
  }
  return s;
}

std::string plot_series(const std::vector<Series>& series, bool titles) {
  std::string plot;
  for (const Series& s : series) {
    const std::string c = fmt::format("lc rgb '{}'", s.style.colour);
    plot += fmt::format("{}'{}' index 0 with lines lw 2 dt {} {} {}, '{}' index 1 with points pt {} ps 1.2 {} notitle, "
                        "'{}' index 2 with points pt {} ps 1.2 {} notitle",
                        plot.empty() ? "" : ", ", s.data, s.style.dash, c,
                        titles ? fmt::format("title '{}'", s.label) : "notitle", s.data, s.style.point, c, s.data,
                        s.style.open_point(), c);
  }
  return plot;
}

// The picks, ringed: the cheapest external configuration that met the spec, and ours. The file is
// never empty (gnuplot rejects a data file without points).
std::string write_picks(const MatchResult& m, const std::string& base) {
  const std::string path = base + "-picks.dat";
  std::ofstream f(path);
  int n = 0;
  for (const char* role : {"external", "ours"})
    if (const MatchOutcome* oc = cheapest_reached(m, role)) {
      const MatchTry& t = m.tries[oc->found];
      f << spec_axis_x(t, m.spec) << ' ' << t.cost_ns << '\n', ++n;
    }
  if (n == 0) f << "NaN NaN\n";
  return fmt::format(", '{}' with points pt 6 ps 3 lw 2 lc rgb '#000000' {}", path, n ? "title 'the picks'" : "notitle");
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

Figure scene_front(const MatchResult& m) {
  const ErrorAxis axis = error_axis(m.spec);
  const std::string base = slug(m.scene) + "-front";
  std::vector<Series> series;
  for (const MatchOutcome& oc : m.outcomes)
    if (auto s = write_series(m, oc, axis, base, true)) series.push_back(std::move(*s));
  std::ofstream gp(base + ".gp");
  gp << "set terminal pngcairo size 900,520 font 'sans,10'\nset output '" << base << ".png'\n"
     << "set title 'Equal accuracy on " << m.scene << ": cost against error, every configuration tried'\n"
     << "set xlabel 'error / spec: the worst term over its bound (at most 1 meets the spec)'\n"
     << "set ylabel 'cost (ns per ball per scene step)'\n"
     << "set logscale xy\nset format x '%g'\nset format y '%g'\nset grid\nset key outside right top\n"
     << "set arrow from 1, graph 0 to 1, graph 1 nohead dt 2 lw 1.5 lc rgb '#000000'\n" << x_range(series, 1)
     << "plot " << (series.empty() ? "NaN notitle" : plot_series(series, true)) << write_picks(m, base) << '\n';
  gp.close();
  run_gnuplot(base + ".gp");
  return {FigureKind::front, m.scene, "figures/" + base + ".png",
          fmt::format("Cost against error on `{}`, on the overview's axes: each engine and profile's tries, the "
                      "profile as it is from dt down (the line) and each knob on top of it, the error the spec's worst "
                      "term over its bound; filled: met the spec ({}), open: did not; ringed: the picks (the cheapest "
                      "external engine and ours that met it); the dashed line is the spec. A try at 0 on every term "
                      "is drawn at 0.001.{}",
                      m.scene, m.spec.text(), not_drawn(m))};
}

// Every scene's front in one figure, the error over the spec's bound so that 1 means the spec on
// each panel; the legend in a panel of its own below them.
Figure all_fronts(const std::vector<MatchResult>& matches) {
  const int columns = matches.size() > 1 ? 2 : 1, rows = int(matches.size() + columns - 1) / columns;
  const double panel_h = 340, legend_h = 150, height = rows * panel_h + legend_h;
  std::ofstream gp("fronts.gp");
  gp << fmt::format("set terminal pngcairo size {},{} font 'sans,10'\nset output 'fronts.png'\nset multiplot\n",
                    columns * 480, int(height))
     << "set logscale xy\nset format x '%g'\nset format y '%g'\nset grid\nunset key\n";
  std::vector<Series> legend;
  for (size_t k = 0; k < matches.size(); ++k) {
    const MatchResult& m = matches[k];
    const ErrorAxis axis = error_axis(m.spec);
    std::vector<Series> series;
    for (const MatchOutcome& oc : m.outcomes)
      if (auto s = write_series(m, oc, axis, slug(m.scene) + "-fronts", true)) {
        if (std::none_of(legend.begin(), legend.end(), [&](const Series& l) { return l.label == s->label; }))
          legend.push_back(*s);
        series.push_back(std::move(*s));
      }
    const int row = int(k) / columns, col = int(k) % columns;
    gp << fmt::format("set origin {},{}\nset size {},{}\n", double(col) / columns,
                      (height - (row + 1) * panel_h) / height, 1.0 / columns, panel_h / height)
       << fmt::format("set title '{} ({})'\n", m.scene, m.scene_class)
       << "set xlabel 'error / spec (the worst term)'\nset ylabel 'ns per ball per scene step'\n"
       << "unset arrow\nset arrow from 1, graph 0 to 1, graph 1 nohead dt 2 lw 1.5 lc rgb '#000000'\n"
       << x_range(series, 1)
       << "plot " << (series.empty() ? "NaN notitle" : plot_series(series, false))
       << write_picks(m, slug(m.scene) + "-fronts") << '\n';
  }
  // The legend: every engine and profile once, drawn as its line.
  gp << fmt::format("set origin 0,0\nset size 1,{}\n", legend_h / height)
     << "unset arrow\nunset logscale\nunset title\nunset xlabel\nunset ylabel\nunset border\nunset tics\nunset grid\n"
     << "set xrange [0:1]\nset yrange [0:1]\nset key center center horizontal maxrows 4 width 2\nplot ";
  for (size_t k = 0; k < legend.size(); ++k)
    gp << (k ? ", " : "") << fmt::format("NaN with linespoints lw 2 pt {} dt {} lc rgb '{}' title '{}'",
                                         legend[k].style.point, legend[k].style.dash, legend[k].style.colour,
                                         legend[k].label);
  if (legend.empty()) gp << "NaN notitle";
  gp << "\nunset multiplot\n";
  gp.close();
  run_gnuplot("fronts.gp");
  return {FigureKind::fronts, "", "figures/fronts.png",
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

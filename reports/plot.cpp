#include "plot.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "enum_words.h"
#include "gnuplot.h"

namespace ballbench {
namespace {

// Text as a gnuplot string: single-quoted, a quote doubled.
std::string quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// A number as the stream writes it (six significant digits), but whole numbers of a million and
// more whole: a ball count of 10^6 reads 1000000, not 1e+06. NaN as gnuplot spells it.
void put_number(std::ostream& out, double v) {
  if (std::isnan(v)) out << "NaN";
  else if (std::abs(v) >= 1e6 && std::abs(v) < 1e15 && v == std::trunc(v)) out << static_cast<long long>(v);
  else out << v;
}

// Blocks apart by two blank lines (gnuplot's `index`). An empty block is a row of NaN: gnuplot
// counts no leading blank lines, so an empty one would shift the blocks after it.
void write_data_file(const DataFile& file) {
  std::ofstream f(file.name);
  for (size_t k = 0; k < file.column_names.size(); ++k) f << (k ? " " : "") << file.column_names[k];
  if (!file.column_names.empty()) f << '\n';
  const std::vector<DataBlock> one_empty(1);
  const std::vector<DataBlock>& blocks = file.blocks.empty() ? one_empty : file.blocks;
  for (size_t b = 0; b < blocks.size(); ++b) {
    const DataBlock& block = blocks[b];
    if (b) f << "\n\n";
    for (size_t r = 0; r < block.rows(); ++r) {
      if (r < block.row_names.size()) f << block.row_names[r] << ' ';
      for (size_t c = 0; c < block.columns; ++c) {
        if (c) f << ' ';
        put_number(f, block.values[r * block.columns + c]);
      }
      f << '\n';
    }
    if (block.rows() == 0) {
      for (size_t c = 0; c < std::max<size_t>(block.columns, 1); ++c) f << (c ? " NaN" : "NaN");
      f << '\n';
    }
  }
}

// The canvas: its terminal, text as it is unless enhanced, the file drawn.
std::string terminal_lines(const Plot& plot) {
  const PlotTerminal& t = plot.terminal;
  std::string out = t.kind == TerminalKind::animated_gif
                        ? fmt::format("set terminal gif animate delay {} optimize size {},{} font {}\n", t.frame_delay,
                                      t.width, t.height, quoted(t.font))
                        : fmt::format("set terminal pngcairo size {},{} font {}\n", t.width, t.height, quoted(t.font));
  if (!t.enhanced_text) out += "set termoption noenhanced\n";
  return out + "set output " + quoted(plot.output()) + "\n";
}

// Gnuplot's words for each key place and series style.
constexpr EnumWords<KeyPlace, 7> kKeyPlaceWords{"key place",
                                               {{{KeyPlace::hidden, ""},
                                                 {KeyPlace::inside_top_right, "inside right top"},
                                                 {KeyPlace::outside_right_top, "outside right top"},
                                                 {KeyPlace::outside_right, "outside right"},
                                                 {KeyPlace::below, "below"},
                                                 {KeyPlace::bottom_right, "bottom right"},
                                                 {KeyPlace::centre, "center center"}}}};
constexpr EnumWords<SeriesStyle, 6> kSeriesStyleWords{"series style",
                                                     {{{SeriesStyle::lines, "lines"},
                                                       {SeriesStyle::linespoints, "linespoints"},
                                                       {SeriesStyle::points, "points"},
                                                       {SeriesStyle::circles, "circles"},
                                                       {SeriesStyle::xerrorlines, "xerrorlines"},
                                                       {SeriesStyle::histograms, "histograms"}}}};

// The key as declared: `set key` changes only the options it names, so a key after another one
// starts from the default.
std::string key_line(const PlotKey& k, const PlotKey& was) {
  if (k.place == KeyPlace::hidden) return "unset key\n";
  std::string out = was == PlotKey{} ? "" : "set key default\n";
  out += fmt::format("set key {}", kKeyPlaceWords.word(k.place));
  if (k.horizontal_rows) out += fmt::format(" horizontal maxrows {}", k.horizontal_rows);
  if (k.width) out += fmt::format(" width {}", k.width);
  if (!k.font.empty()) out += " font " + quoted(k.font);
  if (k.sample_length) out += fmt::format(" samplen {}", k.sample_length);
  return out + "\n";
}

std::string range_end(std::optional<double> value, std::optional<double> limit, bool is_min) {
  if (value) return fmt::format("{}", *value);
  if (!limit) return "*";
  return is_min ? fmt::format("{}<*", *limit) : fmt::format("*<{}", *limit);
}

// An axis's settings that differ from `was`; `name` is "x" or "y".
std::string axis_lines(const char* name, const PlotAxis& a, const PlotAxis& was) {
  std::string out;
  if (a.label != was.label || a.label_offset != was.label_offset)
    out += a.label.empty() ? fmt::format("unset {}label\n", name)
                           : fmt::format("set {}label {}{}\n", name, quoted(a.label),
                                         a.label_offset ? fmt::format(" offset {},0", a.label_offset) : "");
  if (a.range != was.range)
    out += fmt::format("set {}range [{}:{}]\n", name, range_end(a.range.min, a.range.floor, true),
                       range_end(a.range.max, a.range.ceiling, false));
  if (a.format != was.format)
    out += a.format.empty() ? fmt::format("set format {}\n", name)
                            : fmt::format("set format {} {}\n", name, quoted(a.format));
  if (!a.tics) {
    if (was.tics) out += fmt::format("unset {}tics\n", name);
    return out;
  }
  std::string tics;
  if (a.tic_step != was.tic_step) tics += a.tic_step ? fmt::format(" {}", a.tic_step) : " autofreq";
  if (a.tic_rotation != was.tic_rotation)
    tics += a.tic_rotation ? fmt::format(" rotate by {}", a.tic_rotation) : " norotate";
  if (!tics.empty() || !was.tics) out += fmt::format("set {}tics{}\n", name, tics);
  return out;
}

std::string margin_line(const char* side, std::optional<double> at, std::optional<double> was) {
  if (at == was) return "";
  return at ? fmt::format("set {}margin at screen {}\n", side, *at) : fmt::format("set {}margin -1\n", side);
}

// The look of a panel: its frame, axes, key and margins, as far as they differ from `was`.
std::string frame_lines(const PlotPanel& p, const PlotPanel& was) {
  std::string out;
  if (p.place && p.place != was.place)
    out += fmt::format("set origin {},{}\nset size {},{}\n", p.place->x, p.place->y, p.place->width, p.place->height);
  out += margin_line("l", p.margins.left, was.margins.left) + margin_line("r", p.margins.right, was.margins.right) +
         margin_line("t", p.margins.top, was.margins.top) + margin_line("b", p.margins.bottom, was.margins.bottom);
  if (p.title != was.title) out += p.title.empty() ? "unset title\n" : "set title " + quoted(p.title) + "\n";
  if (p.log != was.log) {
    static constexpr const char* kAxes[] = {"", "x", "y", "xy"};
    if (was.log != LogAxes::none) out += "unset logscale\n";
    if (p.log != LogAxes::none) out += fmt::format("set logscale {}\n", kAxes[static_cast<int>(p.log)]);
  }
  out += axis_lines("x", p.x, was.x) + axis_lines("y", p.y, was.y);
  if (p.grid != was.grid) {
    if (was.grid != Grid::none) out += "unset grid\n";
    if (p.grid != Grid::none) out += p.grid == Grid::y ? "set grid y\n" : "set grid\n";
  }
  if (p.key != was.key) out += key_line(p.key, was.key);
  if (p.border != was.border || p.border_colour != was.border_colour)
    out += !p.border ? "unset border\n"
                     : "set border" + (p.border_colour.empty() ? "" : " lc rgb " + quoted(p.border_colour)) + "\n";
  if (p.equal_scales != was.equal_scales) out += p.equal_scales ? "set size ratio -1\n" : "set size noratio\n";
  return out;
}

std::string label_line(size_t tag, const PlotLabel& l) {
  const char* system = l.coordinates == Coordinates::graph ? "graph" : "screen";
  std::string out = fmt::format("set label {} {} at {} {}, {} {} {} front", tag, quoted(l.text), system, l.x, system,
                                l.y, l.align == Align::left ? "left" : "center");
  if (!l.font.empty()) out += " font " + quoted(l.font);
  if (!l.colour.empty()) out += " textcolor rgb " + quoted(l.colour);
  return out + "\n";
}

// What a panel draws beside its series, each list set anew where it differs from `was`.
std::string overlay_lines(const PlotPanel& p, const PlotPanel& was) {
  std::string out;
  if (p.rectangles != was.rectangles) {
    if (!was.rectangles.empty()) out += "unset object\n";
    for (size_t k = 0; k < p.rectangles.size(); ++k) {
      const PlotRectangle& r = p.rectangles[k];
      out += fmt::format("set object {} rect from {},{} to {},{} fs empty border rgb {} lw {} {}\n", k + 1, r.x0, r.y0,
                         r.x1, r.y1, quoted(r.colour), r.width, r.in_front ? "front" : "back");
    }
  }
  if (p.vertical_lines != was.vertical_lines) {
    if (!was.vertical_lines.empty()) out += "unset arrow\n";
    for (size_t k = 0; k < p.vertical_lines.size(); ++k) {
      const VerticalLine& v = p.vertical_lines[k];
      out += fmt::format("set arrow {} from {}, graph 0 to {}, graph 1 nohead dt {} lw {} lc rgb {}\n", k + 1, v.x, v.x,
                         v.dash, v.width, quoted(v.colour));
    }
  }
  if (p.labels != was.labels) {
    if (!was.labels.empty()) out += "unset label\n";
    for (size_t k = 0; k < p.labels.size(); ++k) out += label_line(k + 1, p.labels[k]);
  }
  for (const std::string& command : p.extra_commands) out += command + "\n";
  return out;
}

std::string series_text(const PlotSeries& s) {
  std::string out = s.data.empty() ? s.expression : quoted(s.data);
  if (s.index) out += fmt::format(" index {}", *s.index);
  if (!s.columns.empty()) out += " using " + s.columns;
  out += fmt::format(" with {}", kSeriesStyleWords.word(s.style));
  if (s.line_width) out += fmt::format(" lw {}", s.line_width);
  if (s.dash) out += fmt::format(" dt {}", s.dash);
  if (s.point) out += fmt::format(" pt {}", s.point);
  if (s.point_size_from_column) out += " ps variable";
  else if (s.point_size) out += fmt::format(" ps {}", s.point_size);
  if (!s.colour.empty()) out += " lc rgb " + quoted(s.colour);
  if (s.fill_opacity) out += fmt::format(" fs transparent solid {} border lc rgb {}", s.fill_opacity, quoted(s.colour));
  if (s.title_from_column_header) return out + " title columnheader";
  return out + (s.title ? " title " + quoted(*s.title) : " notitle");
}

std::string plot_line(const PlotPanel& p) {
  if (p.series.empty()) return "plot 1/0 notitle\n";  // the frame alone
  std::string out = "plot ";
  for (size_t k = 0; k < p.series.size(); ++k) out += (k ? ", " : "") + series_text(p.series[k]);
  return out + "\n";
}

// The terminal, then per panel its settings where they differ from the panel before and its plot;
// a multiplot around the panels, or around each frame's panels of an animation.
std::string script(const Plot& plot) {
  std::string out = terminal_lines(plot);
  const std::string multiplot =
      plot.layout == LayoutKind::grid ? fmt::format("set multiplot layout {},{}\n", plot.rows, plot.columns)
      : plot.layout == LayoutKind::free ? "set multiplot\n"
                                        : "";
  const size_t per_frame = plot.panels_per_frame ? plot.panels_per_frame : plot.panels.size();
  const PlotPanel defaults;
  for (size_t k = 0; k < plot.panels.size(); ++k) {
    if (k % per_frame == 0) out += multiplot;
    const PlotPanel& was = k ? plot.panels[k - 1] : defaults;
    out += frame_lines(plot.panels[k], was) + overlay_lines(plot.panels[k], was) + plot_line(plot.panels[k]);
    if (!multiplot.empty() && (k + 1) % per_frame == 0) out += "unset multiplot\n";
  }
  return out;
}

}  // namespace

void draw_plot(const Plot& plot) {
  for (const DataFile& file : plot.data) write_data_file(file);
  const std::string path = plot.name + ".gp";
  std::ofstream(path) << script(plot);
  run_gnuplot(path);
}

}  // namespace ballbench

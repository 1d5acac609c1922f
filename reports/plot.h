#pragma once
// A gnuplot figure declared as data: its terminal, its panels with their settings and series, and
// the numbers of the data files the series read. One writer, draw_plot, turns it into those data
// files and a script, and runs gnuplot on them; the report's figures only fill the model in.
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ballbench {

enum class TerminalKind { png, animated_gif };  // gnuplot's pngcairo; its gif terminal, animated

struct PlotTerminal {
  TerminalKind kind = TerminalKind::png;
  double width = 900, height = 520;  // pixels
  std::string font = "sans,10";
  bool enhanced_text = false;  // gnuplot's enhanced text: '^' raises, '_' lowers; off, text is itself
  int frame_delay = 10;        // animated_gif: hundredths of a second from one frame to the next
};

// Numbers in columns, one row a line; a data file's blocks are what gnuplot's `index` picks.
struct DataBlock {
  explicit DataBlock(size_t columns = 2) : columns(columns) {}
  size_t columns;
  std::vector<double> values;          // row after row
  std::vector<std::string> row_names;  // none, or a word before each row's numbers (read by xtic(1))
  void add(std::initializer_list<double> row) { values.insert(values.end(), row); }
  size_t rows() const { return columns ? values.size() / columns : 0; }
};

struct DataFile {
  explicit DataFile(std::string name, size_t blocks = 1, size_t columns = 2)
      : name(std::move(name)), blocks(blocks, DataBlock(columns)) {}
  std::string name;                       // in the working folder
  std::vector<std::string> column_names;  // a first line naming the columns (`title columnheader`), or none
  std::vector<DataBlock> blocks;
};

enum class SeriesStyle { lines, linespoints, points, circles, xerrorlines, histograms };

// One thing a panel plots: a data file's columns, or an expression ("NaN" for a key entry alone).
// A zero or empty field is gnuplot's own choice.
struct PlotSeries {
  std::string data;        // a DataFile's name
  std::string expression;  // used when `data` is empty
  std::optional<int> index;
  std::string columns;  // gnuplot's `using`: "1:2:3", "2:xtic(1)"
  SeriesStyle style = SeriesStyle::lines;
  std::string colour;  // "#rrggbb"
  int dash = 0;        // gnuplot dashtype
  int point = 0;       // gnuplot pointtype
  double point_size = 0;
  bool point_size_from_column = false;  // `ps variable`: the last `using` column sizes each point
  double line_width = 0;
  double fill_opacity = 0;  // circles: a transparent solid fill, bordered in `colour`
  std::optional<std::string> title;  // none: left out of the key
  bool title_from_column_header = false;
};

// An axis range; an end without a value is autoscaled (`*`), within `floor`/`ceiling` if given.
struct PlotRange {
  std::optional<double> min, max, floor, ceiling;
  bool operator==(const PlotRange&) const = default;
};

struct PlotAxis {
  std::string label;
  double label_offset = 0;  // characters along x (a y label moved towards the plot)
  PlotRange range;
  std::string format;  // the tic labels' printf format, "" gnuplot's
  bool tics = true;
  double tic_step = 0;      // 0: gnuplot's
  double tic_rotation = 0;  // degrees
  bool operator==(const PlotAxis&) const = default;
};

enum class LogAxes { none, x, y, xy };
enum class Grid { none, xy, y };
enum class KeyPlace { hidden, inside_top_right, outside_right_top, outside_right, below, bottom_right, centre };

struct PlotKey {
  KeyPlace place = KeyPlace::inside_top_right;  // gnuplot's default
  std::string font;                             // ",9": the size alone
  double sample_length = 0;                     // 0: gnuplot's
  int horizontal_rows = 0;                      // a horizontal key in at most this many rows; 0 vertical
  double width = 0;                             // characters added to each entry
  bool operator==(const PlotKey&) const = default;
};

enum class Coordinates { graph, screen };  // 0 to 1 across the plot area, across the canvas
enum class Align { left, centre };

// Text on a panel, over its series.
struct PlotLabel {
  std::string text;
  Coordinates coordinates = Coordinates::graph;
  double x = 0, y = 0;
  Align align = Align::left;
  std::string font;
  std::string colour;
  bool operator==(const PlotLabel&) const = default;
};

// A line across the plot's height at `x` (a spec's bound).
struct VerticalLine {
  double x = 0;
  int dash = 1;
  double width = 1;
  std::string colour = "#000000";
  bool operator==(const VerticalLine&) const = default;
};

// An unfilled rectangle in the axes' units (a container's walls), over the series or behind them.
struct PlotRectangle {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::string colour;
  double width = 1;
  bool in_front = true;
  bool operator==(const PlotRectangle&) const = default;
};

// Where a panel of a free layout sits: its origin and size, fractions of the canvas.
struct PanelPlace {
  double x = 0, y = 0, width = 1, height = 1;
  bool operator==(const PanelPlace&) const = default;
};

// Plot-area margins at fixed fractions of the canvas; none: gnuplot's.
struct PanelMargins {
  std::optional<double> left, right, top, bottom;
  bool operator==(const PanelMargins&) const = default;
};

// One plot of a figure. Each panel declares all of its settings; the script sets what differs from
// the panel before (the first: from gnuplot's defaults, which a default PlotPanel is).
struct PlotPanel {
  std::string title;
  PlotAxis x, y;
  LogAxes log = LogAxes::none;
  Grid grid = Grid::none;
  PlotKey key;
  bool border = true;
  std::string border_colour;
  bool equal_scales = false;  // a metre as long on y as on x
  PanelMargins margins;
  std::optional<PanelPlace> place;
  std::vector<PlotRectangle> rectangles;
  std::vector<VerticalLine> vertical_lines;
  std::vector<PlotLabel> labels;
  // Gnuplot commands no field covers, written before this panel's plot; what they set stays set.
  std::vector<std::string> extra_commands;
  // None: the frame alone, which gnuplot draws only with both axes' ranges given.
  std::vector<PlotSeries> series;
};

enum class LayoutKind { single, grid, free };  // one panel; rows x columns; each panel placed itself

struct Plot {
  std::string name;  // NAME.gp draws NAME.png (NAME.gif)
  PlotTerminal terminal;
  LayoutKind layout = LayoutKind::single;
  int rows = 1, columns = 1;  // LayoutKind::grid
  size_t panels_per_frame = 0;  // animated_gif: each run of this many panels is a frame; 0: all in one
  std::vector<PlotPanel> panels;
  std::vector<DataFile> data;
  std::string output() const { return name + (terminal.kind == TerminalKind::animated_gif ? ".gif" : ".png"); }
};

// Writes the plot's data files and NAME.gp into the working folder (the script names its data
// files bare) and runs gnuplot on it; throws std::runtime_error naming the script if gnuplot fails.
void draw_plot(const Plot& plot);

}  // namespace ballbench

// The gnuplot writer (reports/plot.h): a declared figure comes out as its script and data files,
// and a command gnuplot refuses is an error naming the script.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "plot.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs `body` in a scratch folder of its own, the writer's working folder.
template <class Body>
void in_scratch_folder(const std::string& name, Body body) {
  const fs::path dir = fs::temp_directory_path() / (name + "." + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path here = fs::current_path();
  fs::current_path(dir);
  try {
    body();
  } catch (...) {
    fs::current_path(here), fs::remove_all(dir);
    throw;
  }
  fs::current_path(here), fs::remove_all(dir);
}

Plot two_panels() {
  Plot plot;
  plot.name = "two", plot.terminal.width = 600, plot.terminal.height = 300;
  plot.layout = LayoutKind::grid, plot.rows = 1, plot.columns = 2;
  DataFile& data = plot.data.emplace_back("two-a.dat", 3);
  for (const size_t b : {0, 2}) {
    data.blocks[b].add({1, 10}), data.blocks[b].add({10, 1000});
    data.blocks[b].add({1e6, 3});  // a ball count of a million
  }
  PlotPanel left;
  left.title = "left";
  left.log = LogAxes::xy;
  PlotSeries& line = left.series.emplace_back();
  line.data = "two-a.dat", line.index = 0, line.style = SeriesStyle::linespoints, line.title = "it's a";
  line.colour = "#0072B2", line.dash = 2, line.point = 5, line.line_width = 2;
  PlotPanel right = left;
  right.title = "right";
  right.log = LogAxes::y;
  right.key.place = KeyPlace::hidden;
  right.series.assign(2, PlotSeries{});
  right.series[0].data = "two-a.dat", right.series[0].index = 2, right.series[0].style = SeriesStyle::points;
  right.series[0].colour = "#E69F00", right.series[0].point = 6;
  right.series[1].expression = "x", right.series[1].colour = "#000000";
  plot.panels = {left, right};
  return plot;
}

// Each panel's series in its colour, each its own log axes (the right panel's set anew, not
// added to the left's), the settings they share written once; an empty block is a row of NaN,
// so that the blocks after it keep their index.
TEST(PlotFigure, ATwoPanelFigureWritesEachPanelsSeriesColoursAndLogAxes) {
  in_scratch_folder("ballbench_plot", [] {
    draw_plot(two_panels());
    EXPECT_TRUE(fs::exists("two.png"));
    const std::string gp = text_of("two.gp");
    const size_t right = gp.find("set title 'right'");
    ASSERT_NE(right, std::string::npos) << gp;
    EXPECT_LT(gp.find("set multiplot layout 1,2\n"), gp.find("set title 'left'")) << gp;
    EXPECT_LT(gp.find("set logscale xy\n"), right) << gp;
    EXPECT_NE(gp.find("'two-a.dat' index 0 with linespoints lw 2 dt 2 pt 5 lc rgb '#0072B2' title 'it''s a'"),
              std::string::npos) << gp;
    EXPECT_NE(gp.find("unset logscale\nset logscale y\n", right), std::string::npos) << gp;
    EXPECT_NE(gp.find("unset key\n", right), std::string::npos) << gp;
    EXPECT_NE(gp.find("'two-a.dat' index 2 with points pt 6 lc rgb '#E69F00' notitle, x with lines lc rgb '#000000'"),
              std::string::npos) << gp;
    EXPECT_EQ(gp.find("set termoption noenhanced"), gp.rfind("set termoption noenhanced")) << "the terminal once";
    EXPECT_NE(gp.find("unset multiplot\n"), std::string::npos) << gp;
    // Blocks two blank lines apart; a ball count of a million whole.
    EXPECT_EQ(text_of("two-a.dat"), "1 10\n10 1000\n1000000 3\n\n\nNaN NaN\n\n\n1 10\n10 1000\n1000000 3\n");
  });
}

TEST(PlotFigure, ABadCommandFailsNamingTheScript) {
  in_scratch_folder("ballbench_plot_bad", [] {
    Plot plot = two_panels();
    plot.name = "bad";
    plot.panels[1].extra_commands = {"set no-such-setting"};
    try {
      draw_plot(plot);
      FAIL() << "gnuplot took an unknown command";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("bad.gp"), std::string::npos) << e.what();
    }
  });
}

}  // namespace
}  // namespace ballbench

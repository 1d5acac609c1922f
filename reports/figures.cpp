#include "figures.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace ballbench {
namespace {

namespace fs = std::filesystem;

void run_gnuplot(const fs::path& script) {
  const std::string cmd = fmt::format("gnuplot '{}' 2>'{}.log'", script.string(), script.string());
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error(fmt::format("gnuplot failed on {} (see {}.log)", script.string(), script.string()));
  fs::remove(script.string() + ".log");  // kept only when it has something to say
}

// A name safe for files: "box2d/tuned" -> "box2d-tuned".
std::string slug(std::string s) {
  for (char& c : s)
    if (c == '/' || c == ' ') c = '-';
  return s;
}

Figure energy_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
  const std::string base = slug(scene) + "-energy";
  std::string plot;
  int lines = 0;
  for (const Result* r : runs) {
    if (r->series.t.empty() || r->metrics.energy.initial <= 0) continue;
    const std::string data = base + "-" + slug(run_label(*r)) + ".dat";
    std::ofstream f(dir / data);
    for (size_t k = 0; k < r->series.t.size(); ++k)
      f << r->series.t[k] << ' ' << r->series.energy[k] / r->metrics.energy.initial << '\n';
    // gnuplot cycles through 8 colours: later lines get dashes so no two look alike.
    plot += fmt::format("{}'{}' with lines lw 2 dt {} title '{}'", plot.empty() ? "" : ", ", data, 1 + lines++ / 8,
                        run_label(*r));
  }
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size 900,500 font 'sans,10'\n"
     << "set output '" << base << ".png'\n"
     << "set title 'Energy over time, " << scene << "'\nset xlabel 'time (s)'\nset ylabel 'E / E0'\n"
     << "set logscale y\nset key outside right\nset grid\n"
     << "plot " << plot << '\n';
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {scene, "figures/" + base + ".png",
          "Energy over time, relative to the start (log scale), one line per engine and profile."};
}

// One panel per run: the balls at the end (circles of the mean radius), the tracks of the first
// few balls, and the centre-of-mass trail; the container drawn as its walls.
Figure scene_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
  const std::string base = slug(scene) + "-picture";
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size " << 450 * runs.size() << ",480 font 'sans,10'\n"
     << "set output '" << base << ".png'\nset multiplot layout 1," << runs.size() << "\n"
     << "set size ratio -1\nunset key\n";
  for (const Result* r : runs) {
    const std::string name = slug(run_label(*r));
    {
      std::ofstream f(dir / fmt::format("{}-{}-balls.dat", base, name));
      for (const auto& p : r->series.final_pos) f << p[0] << ' ' << p[1] << ' ' << r->series.radius_mean << '\n';
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
      for (size_t k = 0; k < r->series.com_x.size(); ++k) f << r->series.com_x[k] << ' ' << r->series.com_y[k] << '\n';
    }
    gp << "unset object\n";
    if (r->series.box) {
      const auto& b = *r->series.box;
      gp << fmt::format("set object 1 rect from {},{} to {},{} fs empty border rgb 'red' lw 2\n", b[0], b[1], b[2], b[3]);
      const double m = 0.1 * std::max(b[2] - b[0], b[3] - b[1]);
      gp << fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\n", b[0] - m, b[2] + m, b[1] - m, b[3] + m);
    } else {
      gp << "set autoscale\n";
    }
    gp << "set title '" << run_label(*r) << " at t = " << (r->series.t.empty() ? 0.0 : r->series.t.back()) << " s'\n"
       << fmt::format("plot '{0}-{1}-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', "
                      "'{0}-{1}-tracks.dat' index 0:3 using 1:2 with lines lw 1, "
                      "'{0}-{1}-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'\n",
                      base, name);
  }
  gp << "unset multiplot\n";
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {scene, "figures/" + base + ".png",
          "The scene at the end: balls (blue), the tracks of four balls, and the centre-of-mass trail (pink), as in "
          "the thesis's figures 3 to 5."};
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
      figures.push_back(energy_figure(scene, by_scene[scene], "."));
      std::vector<const Result*> pictured;  // the thesis's algorithm beside ours
      for (const Result* r : by_scene[scene])
        if ((r->engine == "home-seed" || r->engine == "home") && !r->series.final_pos.empty()) pictured.push_back(r);
      if (!pictured.empty()) figures.push_back(scene_figure(scene, pictured, "."));
    }
  } catch (...) {
    fs::current_path(here);
    throw;
  }
  fs::current_path(here);
  return figures;
}

}  // namespace ballbench

#include "figures.h"

#include <algorithm>
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
#include "viewer_page.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

// None when no run of the scene has an energy to plot (every engine refused it, say).
std::optional<Figure> energy_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
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
  if (lines == 0) return std::nullopt;
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size 900,500 font 'sans,10'\n"
     << "set output '" << base << ".png'\n"
     << "set title 'Energy over time, " << scene << "'\nset xlabel 'time (s)'\nset ylabel 'E / E0'\n"
     << "set logscale y\nset key outside right\nset grid\n"
     << "plot " << plot << '\n';
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return Figure{"energy", scene, "figures/" + base + ".png",
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
  return {"picture", scene, "figures/" + base + ".png",
          "The scene at the end: balls (blue), the tracks of four balls, and the centre-of-mass trail (pink), as in "
          "the thesis's figures 3 to 5."};
}


// The scene in motion, one panel per run (the thesis's port, ours, an external engine), as an
// animated GIF (gnuplot's gif terminal): every ball at each of about kGifFrames frames taken evenly
// from Result::series::frames (which hold more, for the viewer).
Figure animation_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
  const std::string base = slug(scene) + "-animation";
  constexpr size_t kGifFrames = 80;  // 8 s at 10 frames per second, and the GIF under 2 MB
  // As many frames as the longest run; a run that stopped early (diverged, failed) holds its last.
  size_t recorded = 0;
  for (const Result* r : runs) recorded = std::max(recorded, r->series.frames.size());
  const size_t stride = std::max<size_t>(1, (recorded + kGifFrames - 1) / kGifFrames);
  const size_t frames = (recorded + stride - 1) / stride;  // GIF frame k shows recorded frame k * stride
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal gif animate delay 8 optimize size " << 320 * runs.size() << ",340 font 'sans,9'\n"
     << "set output '" << base << ".gif'\nset size ratio -1\nunset key\nunset xtics\nunset ytics\n";
  if (const auto& b = runs.front()->series.box)
    gp << fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\nset object 1 rect from {},{} to {},{} fs empty border "
                      "rgb 'red' lw 2\n",
                      (*b)[0], (*b)[2], (*b)[1], (*b)[3], (*b)[0], (*b)[1], (*b)[2], (*b)[3]);
  for (const Result* r : runs) {
    std::ofstream f(dir / fmt::format("{}-{}.dat", base, slug(run_label(*r))));
    for (size_t k = 0; k < frames; ++k) {
      for (const auto& p : r->series.frames[std::min(k * stride, r->series.frames.size() - 1)])
        f << p[0] << ' ' << p[1] << ' ' << r->series.radius_mean << '\n';
      f << "\n\n";  // a gnuplot data block per frame
    }
  }
  for (size_t k = 0; k < frames; ++k) {
    gp << "set multiplot layout 1," << runs.size() << "\n";
    for (const Result* r : runs) {
      const size_t held = std::min(k * stride, r->series.frames.size() - 1);
      const std::string stopped = held < k * stride ? fmt::format(" ({})", run_status_text(r->status)) : "";
      gp << fmt::format("set title '{} t = {:.1f} s{}'\nplot '{}-{}.dat' index {} using 1:2:3 with circles fs solid 0.6 "
                        "lc rgb '#3060c0'\n",
                        run_label(*r), r->series.frame_t[held], stopped, base,
                        slug(run_label(*r)), k);
    }
    gp << "unset multiplot\n";
  }
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {"animation", scene, "figures/" + base + ".gif",
          fmt::format("The scene in motion ({} frames, animated GIF): the thesis's algorithm, ours and an external "
                      "engine side by side; a run that stopped early holds its last frame, its status in its title.",
                      frames)};
}

// The trajectory viewer (viewer_page.h): every run of the scene that has frames, on one page.
Figure viewer_figure(const std::string& scene, const std::vector<const Result*>& runs, const fs::path& dir) {
  const std::string file = slug(scene) + "-viewer.html";
  const std::string page = viewer_page(runs);
  write_file_atomically((dir / file).string(), page, "the viewer page");
  size_t frames = 0;
  for (const Result* r : runs) frames = std::max(frames, r->series.frames.size());
  return {"viewer", scene, "figures/" + file,
          fmt::format("every engine and profile side by side, {} frames ({:.1f} MB, opens offline in any browser): "
                      "play, pause, scrub and speed, the tracks of four balls, every tunnelling and sticking event "
                      "marked where and when it happened (click one in the list to jump there), energy over time "
                      "under the playback",
                      frames, static_cast<double>(page.size()) / 1e6)};
}

// gnuplot line style k: 8 colours, then the same colours dashed, so no two lines look alike.
std::string style(int k) { return fmt::format("lc {} dt {}", 1 + k % 8, 1 + k / 8); }

// Error against step time, log-log: per engine and profile a line through its step-size series
// (x error bars: the spread of the timing repeats), and its other knob settings as open points in
// the same colour. The reference itself (error 0) cannot be drawn on a log scale.
Figure work_precision_figure(const SweepResult& sw, const fs::path& dir) {
  const std::string base = slug(sw.scene) + "-work-precision";
  std::vector<std::string> order;  // engine/profile in the sweep's order
  for (const SweepPoint& p : sw.points) {
    const std::string l = run_label(p.engine, p.profile);
    if (p.engine != sw.reference) add_once(order, l);
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
    plot += fmt::format("{}'{}-{}-dt.dat' using 1:2:3:4 with xerrorlines {} lw 2 pt 7 ps 0.8 title '{}', "
                        "'{}-{}-knobs.dat' using 1:2 with points {} pt 6 ps 1.2 notitle",
                        plot.empty() ? "" : ", ", base, name, style(k), order[k], base, name, style(k));
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
  return {"work-precision", sw.scene, "figures/" + base + ".png",
          fmt::format("Work against precision on {}: each line is one engine and profile at the step sizes {} s "
                      "(cost grows as dt shrinks), x bars the spread of {} timing runs; open circles are the same "
                      "engine with one of its own knobs changed at the scene's dt (table below); the right panel "
                      "zooms on the top two decades of error. Lower left is better.",
                      sw.scene, fmt::join(dts, ", "), sw.repeats)};
}

// ns per ball-step against ball count, log-log, one panel per benchmark scene, one line per engine
// and profile.
Figure scaling_figure(const BenchResults& bench, const fs::path& dir) {
  const std::string base = "scaling";
  std::vector<std::string> scenes, order;
  for (const BenchRow& r : bench.rows) {
    add_once(scenes, r.scene);
    const std::string l = run_label(r.engine, r.profile);
    add_once(order, l);
  }
  std::ofstream gp(dir / (base + ".gp"));
  gp << "set terminal pngcairo size " << 560 * scenes.size() << ",520 font 'sans,10'\n"
     << "set output '" << base << ".png'\nset multiplot layout 1," << scenes.size() << "\n"
     << "set logscale xy\nset grid\nset key top left font ',8'\n"
     << "set xlabel 'balls'\nset ylabel 'ns per ball-step'\n";
  for (const std::string& scene : scenes) {
    std::string plot;
    for (size_t k = 0; k < order.size(); ++k) {
      const std::string data = fmt::format("{}-{}-{}.dat", base, scene, slug(order[k]));
      std::ofstream f(dir / data);
      int points = 0;
      for (const BenchRow& r : bench.rows)
        if (r.scene == scene && run_label(r.engine, r.profile) == order[k] && r.error.empty())
          f << r.n << ' ' << r.ns_per_ball_step << '\n', ++points;
      if (points)
        plot += fmt::format("{}'{}' with linespoints {} lw 2 pt 7 title '{}'", plot.empty() ? "" : ", ", data, style(k),
                            order[k]);
    }
    gp << "set title 'Step cost, " << scene << "'\nplot " << (plot.empty() ? "1/0 notitle" : plot) << '\n';
  }
  gp << "unset multiplot\n";
  gp.close();
  run_gnuplot(dir / (base + ".gp"));
  return {"scaling", "", "figures/" + base + ".png",
          "Step cost against ball count (bench/ballbench_step_benchmark, engine step only), one line per engine and "
          "profile: flat is linear scaling."};
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
  return {"frontier", f.scene, "figures/" + base + ".png",
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
      if (auto energy = energy_figure(scene, by_scene[scene], ".")) figures.push_back(std::move(*energy));
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
    if (in.bench && !in.bench->rows.empty()) figures.push_back(scaling_figure(*in.bench, "."));
  } catch (...) {
    fs::current_path(here);
    throw;
  }
  fs::current_path(here);
  return figures;
}

}  // namespace ballbench

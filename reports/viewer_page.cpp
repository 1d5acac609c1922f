#include "viewer_page.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <string_view>

#include <fmt/format.h>

#include "input_error.h"
#include "palette.h"

namespace ballbench {

extern const std::string_view kViewerTemplate;  // viewer/viewer.html (viewer_template.cpp, generated)

namespace {

constexpr double kUnit = 1e-4;  // frames are rounded to 0.1 mm (runner.cpp): whole numbers of this
constexpr int kTracks = 4;      // balls whose paths the page draws, as the report's pictures do

long fixed(double v) { return std::lround(v / kUnit); }

// Six significant digits: what a line on a 200-pixel chart can show, at a third of the bytes.
double short_number(double v) { return std::isfinite(v) ? std::stod(fmt::format("{:.6g}", v)) : v; }

// The page is shared beyond the machine that made it: a path of that machine ("/home/me/x/seed-box.toml",
// in a scene source or an error message) is shown by its last part.
std::string without_machine_paths(const std::string& text) {
  static const std::regex path(R"((^|[\s'"(=])(?:/[^\s/'"():,;]+)+/([^\s/'"():,;]+))");
  return std::regex_replace(text, path, "$1$2");
}

std::string label(const Result& r) {
  const std::string l = run_label(r);
  return r.seed_offset == 0 ? l : fmt::format("{} (placement {})", l, r.seed_offset);
}

nlohmann::json run_json(const Result& r) {
  nlohmann::json frames = nlohmann::json::array();
  for (const auto& frame : r.series.frames) {
    std::vector<long> flat;
    flat.reserve(2 * frame.size());
    for (const auto& p : frame) flat.push_back(fixed(p[0])), flat.push_back(fixed(p[1]));
    frames.push_back(std::move(flat));
  }
  std::vector<double> energy;
  for (double e : r.series.energy) energy.push_back(short_number(e));
  nlohmann::json events = nlohmann::json::array();
  for (const Event& e : r.events) {
    nlohmann::json j = {{"kind", event_kind_name(e.kind)}, {"step", e.step}, {"t", short_number(e.t)}, {"i", e.i},
                        {"x", fixed(e.x) * kUnit}, {"y", fixed(e.y) * kUnit}};
    if (e.j >= 0) j["j"] = e.j;
    events.push_back(std::move(j));
  }
  const RunStyle style = run_style(r.engine, r.profile);
  return {{"label", label(r)},
          {"engine", r.engine},
          {"profile", r.profile},
          {"colour", style.colour},
          {"dash", style.dash},
          {"status", run_status_text(r.status)},
          {"stopped_t", r.status == RunStatus::ok ? nlohmann::json(nullptr) : nlohmann::json(stop_time(r))},
          {"error", without_machine_paths(r.error)},
          {"frame_t", r.series.frame_t},
          {"frames", std::move(frames)},
          {"t", r.series.t},
          {"energy", std::move(energy)},
          {"e0", r.metrics.value(Metric::energy_initial)},
          {"events", std::move(events)},
          {"totals",
           {{"tunnel-wall", r.metrics.count(Metric::tunnelling_wall)},
            {"tunnel-pair", r.metrics.count(Metric::tunnelling_pair)},
            {"stick-wall", r.metrics.count(Metric::sticking_wall)},
            {"stick-pair", r.metrics.count(Metric::sticking_pair)}}}};
}

std::vector<std::string> track_colours() {
  std::vector<std::string> colours;
  for (int b = 0; b < kTracks; ++b) colours.push_back(track_colour(b));
  return colours;
}

}  // namespace

double stop_time(const Result& r) {
  return static_cast<double>(r.diverged() && r.diverged_step > 0 ? r.diverged_step : r.steps_done) * r.dt;
}

int viewer_frames(const Scene& scene, int runs) {
  // Digits of the widest coordinate: the container's, and a ball that left it by up to a diameter
  // before its run stopped; 7 digits (+-999 m) in open space. Then its sign and comma.
  double digits = 7;
  if (scene.container.kind == ContainerKind::Box && scene.n() > 0) {
    const double reach = std::max(scene.container.min.cwiseAbs().maxCoeff(), scene.container.max.cwiseAbs().maxCoeff()) +
                         2 * scene.radius.maxCoeff();
    digits = std::floor(std::log10(std::max(1.0, reach / kUnit))) + 1;
  }
  constexpr double kFrameBytes = 24;  // a frame's brackets and its time
  const double per_frame = std::max(1, runs) * (scene.n() * 2 * (digits + 2) + kFrameBytes);
  return static_cast<int>(
      std::clamp(std::floor(kViewerFrameBudget / per_frame), 1.0, static_cast<double>(std::max(1L, scene.steps()))));
}

namespace {

// A results file is read, not trusted: its frames must be what a run writes, or the page would draw
// garbage (a null as -9.2e18) or the count would exhaust memory.
constexpr double kMaxCoordinate = 1e12;  // m: a scene's own bound on coordinates

void check_frames(const std::vector<const Result*>& runs) {
  for (size_t k = 0; k < runs.size(); ++k) {
    const Result& r = *runs[k];
    const std::string where = fmt::format("run {} ({})", k + 1, printable(run_label(r), 200));
    if (r.series.frames.empty()) continue;
    if (r.series.frame_t.size() != r.series.frames.size())
      throw InputError(fmt::format("{}: series.frame_t has {} times for {} frames", where, r.series.frame_t.size(),
                                   r.series.frames.size()));
    if (!r.series.radius.empty() && static_cast<int>(r.series.radius.size()) != r.n)
      throw InputError(fmt::format("{}: series.radius has {} radii for {} balls", where, r.series.radius.size(), r.n));
    for (double radius : r.series.radius)
      if (!(radius > 0 && radius <= kMaxCoordinate))
        throw InputError(fmt::format("{}: series.radius holds {}, not a radius", where, radius));
    for (size_t f = 0; f < r.series.frames.size(); ++f) {
      if (!std::isfinite(r.series.frame_t[f]))
        throw InputError(fmt::format("{}: series.frame_t[{}] is {}, not a time", where, f, r.series.frame_t[f]));
      const auto& frame = r.series.frames[f];
      if (static_cast<int>(frame.size()) != r.n)
        throw InputError(fmt::format("{}: series.frames[{}] holds {} positions for {} balls", where, f, frame.size(), r.n));
      for (size_t b = 0; b < frame.size(); ++b)
        for (double v : frame[b])
          if (!(std::abs(v) <= kMaxCoordinate))
            throw InputError(fmt::format("{}: series.frames[{}][{}] holds {}, not a position (finite, at most {:g} m)",
                                         where, f, b, v, kMaxCoordinate));
    }
  }
}

}  // namespace

std::string viewer_page(const std::vector<const Result*>& runs) {
  if (runs.empty()) throw InputError("no runs to show");
  const Result* shown = nullptr;  // the first run with frames: the scene's geometry
  for (const Result* r : runs) {
    if (r->scene != runs.front()->scene || r->n != runs.front()->n)
      throw InputError(fmt::format("runs of different scenes ({} with {} balls, {} with {}): a page shows one scene",
                                   runs.front()->scene, runs.front()->n, r->scene, r->n));
    if (!shown && !r->series.frames.empty()) shown = r;
  }
  if (!shown) throw InputError("no run has frames to show");
  constexpr int kMaxFrameBalls = 1000;  // the runner keeps frames of scenes up to this many balls
  if (shown->n < 1 || shown->n > kMaxFrameBalls)
    throw InputError(fmt::format("n: {} balls, not a run with frames (those have 1 to {} balls)", shown->n, kMaxFrameBalls));
  check_frames(runs);
  const Result& s = *shown;
  std::vector<double> radius = s.series.radius;
  if (static_cast<int>(radius.size()) != s.n) radius.assign(s.n, s.series.radius_mean);  // files without radii
  nlohmann::json data = {{"scene", s.scene},
                         {"source", without_machine_paths(s.scene_source)},
                         {"n", s.n},
                         {"dt", s.dt},
                         {"steps", s.steps},
                         {"box", s.series.box ? nlohmann::json(*s.series.box) : nlohmann::json(nullptr)},
                         {"radius", radius},
                         {"unit", kUnit},
                         {"tracks", kTracks},
                         {"track_colours", track_colours()},
                         {"runs", nlohmann::json::array()}};
  for (const Result* r : runs) data["runs"].push_back(run_json(*r));
  // Inside <script>, "</script>" in a string (an error message) would end the element: '<' is
  // written as its JSON escape, which JSON.parse reads back as '<'.
  std::string json = data.dump();
  std::string escaped;
  escaped.reserve(json.size());
  for (char c : json)
    if (c == '<') escaped += "\\u003c";
    else escaped += c;
  constexpr std::string_view kMarker = "@BALLBENCH_VIEWER_DATA@";
  const size_t at = kViewerTemplate.find(kMarker);
  std::string page(kViewerTemplate.substr(0, at));
  page += escaped;
  page += kViewerTemplate.substr(at + kMarker.size());
  return page;
}

}  // namespace ballbench

#pragma once
// A metric family: the catalog rows of one measurement (metrics/catalog.h) and the meter that
// measures them, with the stage of a run it watches. Each family lives in one file,
// core/metrics/NAME_metric.cpp, defining `MetricFamily NAME_metric()`; the build lists every such
// file (core/CMakeLists.txt), so adding a metric is that file and its test. A run's MeterSet
// (metrics/meter_set.h) builds the meters of the families that apply to its scene and feeds them.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "metrics/catalog.h"
#include "metrics/events.h"
#include "metrics/metric_values.h"
#include "metrics/metrics_config.h"
#include "overlap.h"
#include "scene.h"
#include "state.h"

namespace ballbench {

// The stage of a run a meter watches.
enum class MetricStage {
  sample,       // every sampled state (every k-th step and the last; MetricsConfig::sample_every)
  motion,       // every step's motion, from the state before to the state after: what a step can skip
  final_state,  // the last good state, once
};

// The nearest wall of a ball in a box: its gap (m; negative inside the wall) and the ball's speed
// along that wall's inward normal (m/s, > 0: moving out of the wall).
struct NearestWall {
  double gap = 0, inward_speed = 0;
};

// One sampled state, and what several meters derive from it, computed once on first asking.
class SampleView {
 public:
  SampleView(const State& state, const Scene& scene, long step, bool first, OverlapScratch& scratch,
             std::vector<Overlap>& overlaps, std::vector<NearestWall>& walls)
      : state(state), scene(scene), step(step), first(first), scratch_(scratch), overlaps_(overlaps), walls_(walls) {}
  const State& state;
  const Scene& scene;
  long step;   // the motion steps seen so far (the step of the state)
  bool first;  // the initial state
  // Every overlapping pair (overlap.h).
  const std::vector<Overlap>& overlaps();
  // Each ball's nearest wall, for a box (empty for open space or a bowl).
  const std::vector<NearestWall>& walls();

 private:
  OverlapScratch& scratch_;
  std::vector<Overlap>& overlaps_;
  std::vector<NearestWall>& walls_;
  bool have_overlaps_ = false, have_walls_ = false;
};

// Where a meter's tunnelling and sticking events go: the run keeps the first kEventsKept.
class EventLog {
 public:
  void keep(const Event& e) {
    if (events_.size() < kEventsKept) events_.push_back(e);
  }
  const std::vector<Event>& events() const { return events_; }

 private:
  std::vector<Event> events_;
};

class Meter {
 public:
  virtual ~Meter() = default;
  // The stage's call: MetricStage::sample, motion or final_state (one per meter).
  virtual void sample(SampleView&, EventLog&) {}
  virtual void motion(const State& /*prev*/, const State& /*cur*/, long /*step*/, EventLog&) {}
  virtual void final_state(const State&) {}
  // Why the run cannot go on (it diverged), after the meter's last call; none to go on.
  virtual std::optional<std::string> stop() const { return std::nullopt; }
  // Its rows' values so far.
  virtual void write(MetricValues& out) const = 0;
  // Notes for the result's `skipped` list, once the run is over (a figure it could not measure).
  virtual std::vector<std::string> notes() const { return {}; }
};

// Whether a family's meter runs on a scene, and a note for the result's `skipped` list either way
// (why it does not run, or how to read it where it does); "" for none.
struct Applies {
  bool runs = true;
  std::string note;
};

struct MetricFamily {
  std::string name;
  // Where its rows stand in the catalog, lowest first: the order of every table's columns (the
  // run's figures, then what its states conserve, then collisions, then the final state).
  int order = 0;
  MetricStage stage = MetricStage::sample;
  std::vector<MetricDef> rows;
  std::function<Applies(const Scene&)> applies = [](const Scene&) { return Applies{}; };
  // Its meter; none for a family whose rows read figures the run's other stages measured (the
  // reference's error, the step time), which has no keyed rows.
  std::function<std::unique_ptr<Meter>(const Scene&, const MetricsConfig&)> make;
};

// Every family the build found, by order, then by name.
const std::vector<MetricFamily>& metric_families();

}  // namespace ballbench

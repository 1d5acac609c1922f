// A run's figures that come from outside its states, as the seed ensembles summarise them: the
// error against the reference (its tracker runs beside the engine, run_stages.h) and the step time
// (the timing stage). No meter: the rows read them from the result.
#include "metrics/meter.h"
#include "result.h"

namespace ballbench {

MetricFamily run_figures_metric() {
  MetricFamily f;
  f.name = "run_figures";
  f.order = 200;
  MetricDef pos_err = derived_row("m", fixed("position RMS error against the reference at the last step"));
  pos_err.ensemble = "pos.err";
  pos_err.meaningful = MeaningfulOn::predictable_scenes;
  pos_err.get = [](const Result& r) {
    return r.reference.reference.empty() ? nlohmann::json() : nlohmann::json(r.reference.pos_rms_final);
  };
  MetricDef cost = derived_row("ns", fixed("the engine's own step time per ball per step"));
  cost.ensemble = "ns/ball-step";
  cost.get = [](const Result& r) { return nlohmann::json(r.ns_per_ball_step); };
  f.rows = {pos_err, cost};
  return f;
}

}  // namespace ballbench

#include "metrics/meter_set.h"

#include <algorithm>

#include "interrupt.h"

namespace ballbench {

MeterSet::MeterSet(const Scene& scene, const MetricsConfig& config) : scene_(scene) {
  for (const MetricFamily& f : metric_families()) {
    Applies a = f.applies(scene);
    if (!a.note.empty()) family_notes_.push_back(std::move(a.note));
    if (!a.runs || !f.make) continue;
    std::unique_ptr<Meter> m = f.make(scene, config);
    meters_.emplace_back(&f, m.get());
    (f.stage == MetricStage::sample ? sample_ : f.stage == MetricStage::motion ? motion_ : final_).push_back(std::move(m));
  }
}

void MeterSet::sample(const State& s, bool interruptible) {
  SampleView view(s, scene_, motion_steps_, samples_ == 0, scratch_, overlaps_, walls_);
  for (auto& m : sample_) {
    if (interruptible && interrupt_signal()) throw Interrupted{"measuring the initial state"};
    m->sample(view, events_);
  }
  ++samples_;
}

void MeterSet::motion(const State& prev, const State& cur) {
  ++motion_steps_;
  for (auto& m : motion_) m->motion(prev, cur, motion_steps_, events_);
}

void MeterSet::final_state(const State& s) {
  for (auto& m : final_) m->final_state(s);
}

std::optional<std::string> MeterSet::first_stop(const std::vector<std::unique_ptr<Meter>>& meters) {
  for (const auto& m : meters)
    if (auto why = m->stop()) return why;
  return std::nullopt;
}

MetricValues MeterSet::values_of(Metric m) const {
  MetricValues v;
  for (const auto& [family, meter] : meters_)
    for (const MetricDef& row : family->rows)
      if (row.metric == m) {
        meter->write(v);
        return v;
      }
  return v;
}

void MeterSet::write(MetricValues& out) const {
  for (const auto& [family, meter] : meters_) meter->write(out);
}

std::vector<std::string> MeterSet::notes() const {
  std::vector<std::string> out = family_notes_;
  for (const auto& [family, meter] : meters_)
    for (std::string& n : meter->notes()) out.push_back(std::move(n));
  return out;
}

MetricValues resting_values() {
  Scene one;
  one.radius = one.mass = Eigen::VectorXd::Ones(1);
  one.initial.pos = one.initial.vel = Eigen::MatrixX2d::Zero(1, 2);
  MeterSet meters(one, MetricsConfig{});
  meters.sample(one.initial);
  meters.final_state(one.initial);
  return meters.values();
}

}  // namespace ballbench

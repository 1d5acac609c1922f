#include "ensemble.h"

#include <algorithm>
#include <map>
#include <random>

#include <fmt/format.h>

#include "metrics/catalog.h"

namespace ballbench {
namespace {

constexpr int kResamples = 2000;
constexpr uint64_t kResampleSeed = 2017;

double mean_of(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

}  // namespace

Interval bootstrap_mean(const std::vector<double>& values) {
  Interval out;
  out.n = static_cast<int>(values.size());
  if (values.empty()) return out;
  out.mean = mean_of(values);
  std::mt19937_64 rng(kResampleSeed);
  std::uniform_int_distribution<size_t> pick(0, values.size() - 1);
  std::vector<double> means(kResamples);
  for (double& m : means) {
    double sum = 0;
    for (size_t k = 0; k < values.size(); ++k) sum += values[pick(rng)];
    m = sum / static_cast<double>(values.size());
  }
  std::sort(means.begin(), means.end());
  out.lo = means[static_cast<size_t>(0.025 * (kResamples - 1))];
  out.hi = means[static_cast<size_t>(0.975 * (kResamples - 1))];
  return out;
}

const std::vector<EnsembleMetric>& ensemble_metrics() {
  static const std::vector<EnsembleMetric> metrics = [] {
    std::vector<EnsembleMetric> out;
    for (const MetricDef& m : metric_catalog())
      if (!m.ensemble.empty()) out.push_back({m.ensemble, &m});
    return out;
  }();
  return metrics;
}

std::optional<double> EnsembleMetric::read(const Result& r) const {
  const nlohmann::json v = def->get(r);
  return v.is_number() ? std::optional(v.get<double>()) : std::nullopt;
}

std::vector<EnsembleRow> summarise_ensemble(const std::vector<Result>& results, const std::string& ours) {
  std::vector<std::string> labels;
  std::map<std::string, std::vector<const Result*>> by_label;
  for (const Result& r : results) {
    const std::string label = run_label(r);
    if (!by_label.contains(label)) labels.push_back(label);  // once, even if none of its runs ended ok
    auto& runs = by_label[label];
    if (r.status == RunStatus::ok) runs.push_back(&r);
  }
  std::map<int64_t, const Result*> ours_at;  // our run on each placement
  if (!ours.empty())
    for (const Result* o : by_label[ours]) ours_at[o->seed_offset] = o;
  const auto& metrics = ensemble_metrics();
  std::vector<EnsembleRow> rows;
  for (const std::string& label : labels) {
    EnsembleRow row;
    row.label = label;
    const auto& runs = by_label[label];
    row.placements = static_cast<int>(runs.size());
    for (const EnsembleMetric& m : metrics) {
      std::vector<double> values;
      for (const Result* r : runs)
        if (const auto v = m.read(*r)) values.push_back(*v);
      row.metrics.push_back(values.empty() ? std::nullopt : std::optional(bootstrap_mean(values)));
      // Paired with ours on the same placements.
      std::vector<double> differences;
      if (!ours.empty() && label != ours)
        for (const Result* r : runs)
          if (const auto o = ours_at.find(r->seed_offset); o != ours_at.end()) {
            const auto a = m.read(*r), b = m.read(*o->second);
            if (a && b) differences.push_back(*a - *b);
          }
      const char* verdict = "";
      if (differences.size() >= 2) {
        const Interval d = bootstrap_mean(differences);
        verdict = d.lo > 0 ? "+" : d.hi < 0 ? "-" : "=";
      }
      row.versus_ours.emplace_back(verdict);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string interval_text(const Interval& i) {
  return fmt::format("{:.3g} [{:.3g}, {:.3g}]", i.mean, i.lo, i.hi);
}

}  // namespace ballbench

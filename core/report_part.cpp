#include "report_part.h"

namespace ballbench {
namespace {

struct PartKindDef {
  PartKind kind;
  const char* word;         // before ':' and the scene, or alone
  const char* file_prefix;  // before the scene's name in its results file
  bool per_scene;
};

constexpr PartKindDef kKinds[] = {
    {PartKind::table, "table", "", true},           {PartKind::match, "match", "match-", true},
    {PartKind::measured, "measured", "measured-", true},
    {PartKind::sweep, "sweep", "sweep-", true},     {PartKind::stress, "stress", "stress-", true},
    {PartKind::conform, "conform", "", false},         {PartKind::calibration, "calibration", "", false},
    {PartKind::bench, "bench", "", false},
};

const PartKindDef& def(PartKind k) {
  for (const PartKindDef& d : kKinds)
    if (d.kind == k) return d;
  return kKinds[0];
}

}  // namespace

std::string part_word(const ReportPart& p) {
  const PartKindDef& d = def(p.kind);
  return d.per_scene ? std::string(d.word) + ":" + p.scene : d.word;
}

std::optional<ReportPart> part_from_word(std::string_view word) {
  const size_t colon = word.find(':');
  const std::string_view head = word.substr(0, colon);
  for (const PartKindDef& d : kKinds)
    if (head == d.word && d.per_scene == (colon != std::string_view::npos) &&
        (!d.per_scene || colon + 1 < word.size()))
      return ReportPart{d.kind, d.per_scene ? std::string(word.substr(colon + 1)) : ""};
  return std::nullopt;
}

std::string part_file(const ReportPart& p) {
  const PartKindDef& d = def(p.kind);
  return d.per_scene ? d.file_prefix + p.scene + ".json" : std::string(d.word) + ".json";
}

std::vector<ReportPart> report_parts(const ReportSuite& suite, bool bench) {
  std::vector<ReportPart> parts;
  const auto each = [&](PartKind k, const std::vector<std::string>& scenes) {
    for (const auto& s : scenes) parts.push_back({k, s});
  };
  each(PartKind::table, suite.scenes);
  each(PartKind::match, suite.match_scenes);
  for (const MeasuredMatch& m : suite.measured_matches) parts.push_back({PartKind::measured, m.scene});
  each(PartKind::sweep, suite.sweep_scenes);
  each(PartKind::stress, suite.stress_scenes);
  parts.push_back({PartKind::conform, ""});
  parts.push_back({PartKind::calibration, ""});
  if (bench) parts.push_back({PartKind::bench, ""});
  return parts;
}

}  // namespace ballbench

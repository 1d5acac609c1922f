#pragma once
// The parts of a report (`ballbench report`), each run once and kept as its results file(s): a
// scene's comparison table, an equal-accuracy search, a sweep, a stability frontier, the
// closed-form checks of every engine, the restitution calibration, the benchmarks, and a search
// measured before (ReportSuite::measured_matches), carried in. A shard runs every N-th part; a report that stopped
// resumes from the parts it finished.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "report_suite.h"

namespace ballbench {

enum class PartKind { table, match, measured, sweep, stress, conform, calibration, bench };

struct ReportPart {
  PartKind kind = PartKind::table;
  std::string scene;  // "" for the parts of every engine (conform, calibration, bench)
  bool operator==(const ReportPart&) const = default;
};

// The part's word in run.json's "parts" and a shard's "ran": "table:pile", "calibration".
std::string part_word(const ReportPart& p);
// The word read back; none for a word of no part.
std::optional<ReportPart> part_from_word(std::string_view word);

// Its results file in the results folder: "pile.json", "match-pile.json", "measured-pile-10k-settled.json", "calibration.json",
// "bench.json" (the benchmarks also write "harness.json").
std::string part_file(const ReportPart& p);

// The suite's parts in run order; the benchmarks last, where `bench`.
std::vector<ReportPart> report_parts(const ReportSuite& suite, bool bench);

}  // namespace ballbench

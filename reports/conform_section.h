#pragma once
// The report's closed-form checks (results/conform.json, `ballbench conform`): each engine and
// profile's passes and failures, and the capabilities its handshake claims that a closed form
// refutes, which every table that shows the engine marks.
#include <string>

#include "report_writer.h"

namespace ballbench {

// " ⚠ friction refuted" for an engine and profile whose claim of friction a closed form refuted
// (a link to the checks), "" otherwise.
std::string refuted_mark(const ReportInputs& in, const std::string& engine, const std::string& profile);

std::string conform_section(const ReportInputs& in);

}  // namespace ballbench

#pragma once
// The report's terms: every word and figure its pages use, with its unit (the accuracy spec's terms,
// cost, the step dt/2^k, the profiles, the search's budget and ceiling, the metrics' columns).
#include <string>

#include "report_writer.h"

namespace ballbench {

std::string terms_section(const ReportInputs& in);

}  // namespace ballbench

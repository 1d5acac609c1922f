#pragma once
// The report's engines, their versions, profiles, limits and settings, the machine and build, and
// what the report left out.
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

std::string engines_section(const ReportInputs& in);

}  // namespace ballbench

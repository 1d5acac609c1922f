#pragma once
// The report's first screen: which engine for which scene, at what accuracy and cost, generated
// from the equal-accuracy results; every claim links to the section that holds its evidence.
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

std::string summary_section(const ReportInputs& in, const std::vector<Figure>& figures);

}  // namespace ballbench

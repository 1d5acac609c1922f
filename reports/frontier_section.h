#pragma once
// The report's stability frontier of one scene (results/stress-SCENE.json, `ballbench stress`).
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

std::string frontier_section(const FrontierResult& f, const std::vector<Figure>& figures);

}  // namespace ballbench

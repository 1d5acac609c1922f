#pragma once
// JSON has no NaN or infinity: nlohmann writes them as null, so null reads back as NaN (a metric of
// a run that blew up to infinity must not make its whole file unreadable).
#include <cmath>

#include <nlohmann/json.hpp>

namespace ballbench {

inline double json_number(const nlohmann::json& j) { return j.is_null() ? std::nan("") : j.get<double>(); }

}  // namespace ballbench

#pragma once
// JSON values read back as numbers and shown as text.
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

namespace ballbench {

// JSON has no NaN or infinity: nlohmann writes them as null, so null reads back as NaN (a metric of
// a run that blew up to infinity must not make its whole file unreadable).
inline double json_number(const nlohmann::json& j) { return j.is_null() ? std::nan("") : j.get<double>(); }

// A setting's value for a table or a message: strings without their quotes, anything else as JSON.
inline std::string json_text(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

}  // namespace ballbench

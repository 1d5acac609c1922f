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

// A string field of a record that may lack it (a run's context from an older build): `fallback` if
// the record is not an object or the field is absent.
inline std::string json_string_field(const nlohmann::json& record, const char* key, const std::string& fallback = "") {
  return record.is_object() ? record.value(key, fallback) : fallback;
}

}  // namespace ballbench

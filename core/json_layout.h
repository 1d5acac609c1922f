#pragma once
// JSON text for files people read and diff: objects and arrays of objects indented two spaces, as
// nlohmann's dump(2), but an array holding only numbers (at any depth: a series, a frame of
// positions) on one line. dump(2) gives every number a line of its own: for the viewer's frames,
// ten times the bytes of the numbers themselves.
#include <string>

#include <nlohmann/json.hpp>

namespace ballbench {

std::string json_layout(const nlohmann::json& j);

}  // namespace ballbench

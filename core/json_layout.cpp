#include "json_layout.h"

namespace ballbench {
namespace {

// Numbers (and nulls, which NaN becomes) only, at any depth.
bool numeric(const nlohmann::json& j) {
  if (j.is_number() || j.is_null()) return true;
  if (!j.is_array()) return false;
  for (const auto& x : j)
    if (!numeric(x)) return false;
  return true;
}

void lay_out(const nlohmann::json& j, int indent, std::string& out) {
  const bool object = j.is_object() && !j.empty(), array = j.is_array() && !j.empty() && !numeric(j);
  if (!object && !array) {
    out += j.dump();  // a scalar, an empty container, or numbers: one line
    return;
  }
  out += object ? "{\n" : "[\n";
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out.append(indent + 2, ' ');
    if (object) out += nlohmann::json(it.key()).dump() + ": ";
    lay_out(*it, indent + 2, out);
  }
  out += '\n';
  out.append(indent, ' ');
  out += object ? '}' : ']';
}

}  // namespace

std::string json_layout(const nlohmann::json& j) {
  std::string out;
  lay_out(j, 0, out);
  return out;
}

}  // namespace ballbench

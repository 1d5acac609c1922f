#pragma once
// The closed-form checks (`ballbench conform`, the report's conform part) as data: one row per
// engine, profile and case, with its figure against the case's tolerance, and a capability the
// engine's handshake claims that the case refutes. The report marks such an engine wherever it
// shows it.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace ballbench {

enum class ConformVerdict { pass, fail, refused };
const char* conform_verdict_text(ConformVerdict v);

// A check's figure in a table or a line: three digits, "inf" for a run that failed, "-" for none
// (refused).
std::string conform_figure_text(const std::optional<double>& figure);
ConformVerdict conform_verdict_from_text(std::string_view text);

struct ConformRow {
  std::string engine, profile;
  std::string check;               // the case's key: "slide-to-roll-disk"
  double tolerance = 0;
  std::optional<double> figure;    // its error against the closed form (infinite: a run of it failed); none: refused
  ConformVerdict verdict = ConformVerdict::pass;
  std::string refuted;             // the capability the engine claims and this case refutes, or ""
  std::string why;                 // a refusal's reason
};

struct ConformResult {
  nlohmann::json context;  // machine, compiler, command, date
  std::vector<ConformRow> rows;
  std::string interrupted;  // the signal that cut it short, or ""
};

// The capabilities the engine's handshake claims that a case refuted in `profile` ("" for any
// profile), each once.
std::vector<std::string> refuted_claims(const ConformResult& c, const std::string& engine,
                                        const std::string& profile = "");

nlohmann::json to_json(const ConformResult& c);
ConformResult conform_from_json(const nlohmann::json& j);
void write_conform_file(const std::string& path, const ConformResult& c);
ConformResult read_conform_file(const std::string& path);

}  // namespace ballbench

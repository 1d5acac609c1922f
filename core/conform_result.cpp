#include "conform_result.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "data_file.h"
#include "enum_words.h"
#include "json_value.h"

namespace ballbench {
namespace {

constexpr EnumWords<ConformVerdict, 3> kVerdictWords{"conformance verdict",
                                                     {{
                                                         {ConformVerdict::pass, "pass"},
                                                         {ConformVerdict::fail, "fail"},
                                                         {ConformVerdict::refused, "refused"},
                                                     }}};

// JSON has no infinity: a case whose run failed is written as the string "inf".
nlohmann::json figure_json(const std::optional<double>& f) {
  if (!f) return nullptr;
  return std::isfinite(*f) ? nlohmann::json(*f) : nlohmann::json("inf");
}

std::optional<double> figure_from_json(const nlohmann::json& j) {
  if (j.is_null()) return std::nullopt;
  if (j.is_string() && j.get<std::string>() == "inf") return HUGE_VAL;
  return json_number(j);
}

}  // namespace

const char* conform_verdict_text(ConformVerdict v) { return kVerdictWords.word(v); }

std::string conform_figure_text(const std::optional<double>& figure) {
  if (!figure) return "-";
  return std::isfinite(*figure) ? fmt::format("{:.3g}", *figure) : "inf";
}

ConformVerdict conform_verdict_from_text(std::string_view text) { return kVerdictWords.value(text); }

std::vector<std::string> refuted_claims(const ConformResult& c, const std::string& engine, const std::string& profile) {
  std::vector<std::string> out;
  for (const ConformRow& r : c.rows)
    if (r.engine == engine && (profile.empty() || r.profile == profile) && !r.refuted.empty() &&
        std::find(out.begin(), out.end(), r.refuted) == out.end())
      out.push_back(r.refuted);
  return out;
}

nlohmann::json to_json(const ConformResult& c) {
  nlohmann::json rows = nlohmann::json::array();
  for (const ConformRow& r : c.rows)
    rows.push_back({{"engine", r.engine},
                    {"profile", r.profile},
                    {"check", r.check},
                    {"tolerance", r.tolerance},
                    {"figure", figure_json(r.figure)},
                    {"verdict", conform_verdict_text(r.verdict)},
                    {"refuted", r.refuted},
                    {"why", r.why}});
  return {{"kind", "conform"}, {"context", c.context}, {"interrupted", c.interrupted}, {"rows", rows}};
}

ConformResult conform_from_json(const nlohmann::json& j) {
  if (j.value("kind", "") != "conform") throw InputError("not a conformance result (no \"kind\": \"conform\")");
  ConformResult c;
  c.context = j.value("context", nlohmann::json::object());
  c.interrupted = j.value("interrupted", "");
  for (const auto& q : j.at("rows")) {
    ConformRow r;
    r.engine = q.at("engine").get<std::string>();
    r.profile = q.at("profile").get<std::string>();
    r.check = q.at("check").get<std::string>();
    r.tolerance = json_number(q.at("tolerance"));
    r.figure = figure_from_json(q.at("figure"));
    r.verdict = conform_verdict_from_text(q.at("verdict").get<std::string>());
    r.refuted = q.at("refuted").get<std::string>();
    r.why = q.at("why").get<std::string>();
    c.rows.push_back(std::move(r));
  }
  return c;
}

void write_conform_file(const std::string& path, const ConformResult& c) {
  write_file_atomically(path, to_json(c).dump(2) + "\n", "the conformance checks");
}

ConformResult read_conform_file(const std::string& path) {
  return read_json_file(path, "a conformance result", [](const nlohmann::json& j) { return conform_from_json(j); },
                        [](const nlohmann::json&) {
                          ConformResult c;  // the shape of a conformance file: one row
                          c.rows.emplace_back();
                          return JsonShape{to_json(c), ""};
                        });
}

}  // namespace ballbench

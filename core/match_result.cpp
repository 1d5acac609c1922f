#include "match_result.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "data_file.h"
#include "enum_words.h"
#include "engine.h"
#include "input_error.h"
#include "json_value.h"
#include "runner.h"
#include "shard_roll.h"

namespace ballbench {
namespace {

// "" for none: an outcome that met the spec has no stop.
constexpr EnumWords<SearchStop, 6> kStopWords{"search stop",
                                              {{
                                                  {SearchStop::none, ""},
                                                  {SearchStop::finest_step, "finest step"},
                                                  {SearchStop::budget, "budget"},
                                                  {SearchStop::ceiling, "ceiling"},
                                                  {SearchStop::outpaced, "outpaced"},
                                                  {SearchStop::interrupt, "interrupt"},
                                              }}};

}  // namespace

const char* search_stop_text(SearchStop s) { return kStopWords.word(s); }

SearchStop search_stop_from_text(std::string_view text) { return kStopWords.value(text); }

std::string cost_text(double ns) { return ns >= 100 ? fmt::format("{:.0f}", ns) : fmt::format("{:.3g}", ns); }

namespace {
// The range of an outcome's timing runs (its cost alone where it was timed once).
std::pair<double, double> cost_range(const MatchOutcome& oc) {
  if (oc.cost_repeats.empty()) return {oc.cost_ns, oc.cost_ns};
  const auto [lo, hi] = std::minmax_element(oc.cost_repeats.begin(), oc.cost_repeats.end());
  return {*lo, *hi};
}
}  // namespace

std::string cost_spread_text(const MatchOutcome& oc) {
  if (oc.cost_repeats.size() < 2 || oc.cost_ns <= 0) return cost_text(oc.cost_ns);
  const auto [lo, hi] = cost_range(oc);
  return fmt::format("{} ±{:.0f}%", cost_text(oc.cost_ns), 50 * (hi - lo) / oc.cost_ns);
}

std::string step_text(int halvings) { return halvings == 0 ? "dt" : fmt::format("dt/{}", 1 << halvings); }

std::string figure_text(const nlohmann::json& v) {
  if (!v.is_number()) return "n/a";
  const double x = v.get<double>();
  return x == std::floor(x) && std::abs(x) < 1e9 ? fmt::format("{:.0f}", x) : fmt::format("{:.3g}", x);
}

std::string configuration_text(const MatchTry& t) {
  std::string s = step_text(t.halvings);
  if (!t.knob.empty()) s += fmt::format(", {}={}", t.knob, json_text(t.value));
  return s;
}

double term_miss(const SpecTermDef& d, double bound, double figure) {
  if (d.at_least) return figure > 0 ? bound / figure : std::numeric_limits<double>::infinity();
  // A bound of 0 (a count: tunnelling <= 0) met is no distance at all; missed, 1 + the count.
  if (bound <= 0) return figure <= 0 ? 0.0 : 1 + figure;
  return figure / bound;
}

double miss(const MatchTry& t, const AccuracySpec& spec) {
  const bool missed = t.status == RunStatus::missed;
  if (t.status != RunStatus::ok && !missed) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (const SpecTermDef& d : spec_terms()) {
    const auto& bound = spec[d.term];
    if (!bound || (missed && !d.grows)) continue;
    const auto f = t.figures.value(d.key, nlohmann::json());
    if (!f.is_number()) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, term_miss(d, *bound, f.get<double>()));
  }
  return missed ? worst / std::max(t.done, 1e-9) : worst;
}

std::optional<double> front_error(const MatchTry& t, const AccuracySpec& spec) {
  if (t.status != RunStatus::ok) return std::nullopt;
  if (const auto term = principal_term(spec)) {
    const auto f = t.figures.value(spec_term(*term).key, nlohmann::json());
    return f.is_number() ? std::optional(f.get<double>()) : std::nullopt;
  }
  const double x = miss(t, spec);
  return std::isfinite(x) ? std::optional(x) : std::nullopt;
}

const MatchOutcome* cheapest_reached(const MatchResult& m, const std::string& role) {
  const MatchOutcome* best = nullptr;
  for (const MatchOutcome& oc : m.outcomes)
    if (oc.ranked() && oc.role == role && (!best || oc.cost_ns < best->cost_ns)) best = &oc;
  return best;
}

std::vector<const MatchOutcome*> tied_with(const MatchResult& m, const MatchOutcome& pick) {
  std::vector<const MatchOutcome*> out;
  const auto [lo, hi] = cost_range(pick);
  for (const MatchOutcome& oc : m.outcomes) {
    if (oc.engine == pick.engine || !oc.ranked() || oc.role != pick.role) continue;
    if (const auto [a, b] = cost_range(oc); a <= hi && b >= lo) out.push_back(&oc);
  }
  return out;
}

std::optional<double> ratio_at_least(const MatchResult& m, const MatchOutcome& ours) {
  if (!ours.reached || !(m.ceiling_ns > 0) || !(ours.cost_ns > 0)) return std::nullopt;
  bool ceiling = false;
  for (const MatchOutcome& oc : m.outcomes) {
    if (oc.role != role_name(EngineRole::external)) continue;
    if (oc.ranked() || oc.stop == SearchStop::budget || oc.stop == SearchStop::interrupt) return std::nullopt;
    ceiling = ceiling || oc.stop == SearchStop::ceiling;
  }
  return ceiling ? std::optional(m.ceiling_ns / ours.cost_ns) : std::nullopt;
}

std::optional<double> outpace_ns(const MatchResult& m, const std::string& role) {
  if (!(m.within > 0)) return std::nullopt;
  std::optional<double> cheapest;
  for (const MatchOutcome& oc : m.outcomes)
    if (oc.reached && oc.role == role && oc.cost_ns > 0) cheapest = std::min(cheapest.value_or(oc.cost_ns), oc.cost_ns);
  return cheapest ? std::optional(m.within * *cheapest) : std::nullopt;
}

std::string outpace_text(double within, const std::string& role, std::optional<double> cheapest_ns) {
  return fmt::format("{:g}x the cheapest {} engine's cost{}", within, role,
                     cheapest_ns ? fmt::format(" ({} ns)", cost_text(*cheapest_ns)) : "");
}

void mark_outpaced(MatchResult& m) {
  for (MatchOutcome& oc : m.outcomes) {
    const auto bound = outpace_ns(m, oc.role);
    if (!bound) continue;
    const std::string what = outpace_text(m.within, oc.role, *bound / m.within);
    if (oc.ranked() && oc.cost_ns > *bound)
      oc.stop = SearchStop::outpaced, oc.stopped = fmt::format("{}, met at {} ns", what, cost_text(oc.cost_ns));
    else if (!oc.reached && oc.stop == SearchStop::outpaced)
      oc.stopped = what;
  }
}

const MatchOutcome* nearest_unreached(const MatchResult& m, const std::string& role) {
  const MatchOutcome* nearest = nullptr;
  double nearest_miss = 0;
  for (const MatchOutcome& oc : m.outcomes) {
    const bool met_unranked = oc.over_ceiling() || oc.outpaced();
    const int shown = met_unranked ? oc.found : oc.best;
    if ((oc.reached && !met_unranked) || oc.role != role || shown < 0) continue;
    const double d = miss(m.tries[shown], m.spec);
    if (std::isfinite(d) && (!nearest || d < nearest_miss)) nearest = &oc, nearest_miss = d;
  }
  return nearest;
}

nlohmann::json to_json(const MatchTry& t) {
  return {{"engine", t.engine},       {"profile", t.profile}, {"knob", t.knob},
          {"value", t.value},         {"halvings", t.halvings}, {"dt", t.dt},
          {"status", run_status_text(t.status)},       {"error", t.error},   {"met", t.met},
          {"why_not", t.why_not},     {"figures", t.figures}, {"cost_ns", t.cost_ns},
          {"cost_pipe_ns", t.cost_pipe_ns ? nlohmann::json(*t.cost_pipe_ns) : nlohmann::json()},
          {"wall_s", t.wall_s},       {"work", t.work}, {"done", t.done}, {"stored", t.stored},
          {"settings", t.settings}};
}

MatchTry match_try_from_json(const nlohmann::json& q) {
  const auto opt = [](const nlohmann::json& v) { return v.is_null() ? std::nullopt : std::optional(v.get<double>()); };
  MatchTry t;
  t.engine = q.at("engine").get<std::string>(), t.profile = q.at("profile").get<std::string>();
  t.knob = q.at("knob").get<std::string>(), t.value = q.at("value");
  t.halvings = q.at("halvings").get<int>(), t.dt = q.at("dt").get<double>();
  t.status = run_status_from_text(q.at("status").get<std::string>()), t.error = q.at("error").get<std::string>();
  t.met = q.at("met").get<bool>(), t.why_not = q.at("why_not").get<std::string>(), t.figures = q.at("figures");
  t.cost_ns = q.at("cost_ns").get<double>(), t.cost_pipe_ns = opt(q.at("cost_pipe_ns"));
  t.wall_s = q.at("wall_s").get<double>(), t.settings = q.at("settings");
  t.work = q.value("work", 0.0), t.done = q.value("done", 1.0), t.stored = q.value("stored", false);
  return t;
}

namespace {

nlohmann::json also_met_json(const MatchOutcome& o) {
  nlohmann::json out = nlohmann::json::array();
  for (const MatchAlternative& a : o.also_met) out.push_back({{"try", a.index}, {"cost_ns", a.cost_ns}});
  return out;
}

}  // namespace

void MatchOutcome::shift_tries(int offset) {
  for (int* k : {&found, &best})
    if (*k >= 0) *k += offset;
  for (MatchAlternative& a : also_met) a.index += offset;
}

nlohmann::json to_json(const MatchResult& m) {
  nlohmann::json tries = nlohmann::json::array(), outcomes = nlohmann::json::array();
  for (const MatchTry& t : m.tries) tries.push_back(to_json(t));
  for (const MatchOutcome& o : m.outcomes)
    outcomes.push_back({{"engine", o.engine},       {"profile", o.profile},   {"role", o.role},   {"reached", o.reached},
                        {"found", o.found},         {"best", o.best},         {"tries", o.tries},
                        {"finest_dt", o.finest_dt}, {"cost_repeats", o.cost_repeats}, {"cost_ns", o.cost_ns},
                        {"cost_pipe_ns", o.cost_pipe_ns ? nlohmann::json(*o.cost_pipe_ns) : nlohmann::json()},
                        {"work", o.work}, {"stored", o.stored}, {"timing_stored", o.timing_stored},
                        {"stop", search_stop_text(o.stop)}, {"stopped", o.stopped}, {"command", o.command},
                        {"also_met", also_met_json(o)}});
  return {{"kind", "match"},         {"scene", m.scene},     {"scene_source", m.scene_source},
          {"scene_class", m.scene_class}, {"use_case", m.use_case}, {"scene_digest", m.scene_digest},
          {"searches", m.searches},  {"n", m.n},        {"dt", m.dt},
          {"spec", m.spec.to_json()}, {"budget_runs", m.budget_runs}, {"run_ball_steps", m.run_ball_steps},
          {"ceiling", m.ceiling}, {"ceiling_ns", m.ceiling_ns}, {"within", m.within}, {"context", m.context}, {"interrupted", m.interrupted},
          {"shard", {{"index", m.shard_index}, {"count", m.shard_count}}},
          {"tries", tries},          {"outcomes", outcomes}};
}

MatchResult match_from_json(const nlohmann::json& j) {
  if (j.value("kind", "") != "match") throw InputError("not a match result (no \"kind\": \"match\")");
  MatchResult m;
  m.scene = j.at("scene").get<std::string>();
  m.scene_source = j.at("scene_source").get<std::string>();
  m.scene_class = j.at("scene_class").get<std::string>();
  m.use_case = j.value("use_case", "");  // files written before it was recorded have none
  m.scene_digest = j.value("scene_digest", "");
  m.searches = j.value("searches", std::vector<std::string>{});
  m.n = j.at("n").get<int>();
  m.dt = j.at("dt").get<double>();
  for (const auto& [key, value] : j.at("spec").items()) {
    const auto term = spec_term_named(key);
    if (!term) throw InputError(fmt::format("spec: unknown term '{}'", key));
    m.spec[*term] = value.get<double>();
  }
  m.budget_runs = j.value("budget_runs", 0.0);
  m.run_ball_steps = j.value("run_ball_steps", 0L);
  m.ceiling = j.value("ceiling", 0.0), m.ceiling_ns = j.value("ceiling_ns", 0.0);
  m.within = j.value("within", 0.0);  // files written before it was recorded: none
  m.context = j.at("context");
  m.interrupted = j.at("interrupted").get<std::string>();
  m.shard_index = j.at("shard").at("index").get<int>();
  m.shard_count = j.at("shard").at("count").get<int>();
  const auto opt = [](const nlohmann::json& v) { return v.is_null() ? std::nullopt : std::optional(v.get<double>()); };
  for (const auto& q : j.at("tries")) m.tries.push_back(match_try_from_json(q));
  for (const auto& q : j.at("outcomes")) {
    MatchOutcome o;
    o.engine = q.at("engine").get<std::string>(), o.profile = q.at("profile").get<std::string>();
    o.role = q.at("role").get<std::string>();
    o.reached = q.at("reached").get<bool>(), o.found = q.at("found").get<int>(), o.best = q.at("best").get<int>();
    o.tries = q.at("tries").get<int>(), o.finest_dt = q.at("finest_dt").get<double>();
    o.cost_repeats = q.at("cost_repeats").get<std::vector<double>>(), o.cost_ns = q.at("cost_ns").get<double>();
    o.cost_pipe_ns = opt(q.at("cost_pipe_ns"));
    o.stopped = q.at("stopped").get<std::string>(), o.command = q.at("command").get<std::string>();
    o.stop = search_stop_from_text(q.value("stop", ""));
    o.work = q.value("work", 0.0), o.stored = q.value("stored", 0), o.timing_stored = q.value("timing_stored", false);
    for (const auto& a : q.value("also_met", nlohmann::json::array()))  // none in files written before
      o.also_met.push_back({a.at("try").get<int>(), a.at("cost_ns").get<double>()});
    for (int k : {o.found, o.best})
      if (k >= int(m.tries.size())) throw InputError(fmt::format("outcomes: try {} is not in tries", k));
    for (const MatchAlternative& a : o.also_met)
      if (a.index < 0 || a.index >= int(m.tries.size()))
        throw InputError(fmt::format("outcomes: also_met try {} is not in tries", a.index));
    m.outcomes.push_back(std::move(o));
  }
  return m;
}

namespace {

std::string match_csv(const MatchResult& m) {
  std::string out = "engine,profile,knob,value,halvings,dt,status,met,cost_ns,cost_pipe_ns,wall_s,work,done";
  for (const SpecTermDef& d : spec_terms()) out += fmt::format(",{}", d.key);
  out += ",why_not\n";
  const auto csv_text = [](std::string s) {  // quoted, as RFC 4180
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  for (const MatchTry& t : m.tries) {
    out += fmt::format("{},{},{},{},{},{:.17g},{},{},{:.6g},{},{:.3f},{:.6g},{:.6g}", t.engine, t.profile, t.knob,
                       csv_text(t.value.is_null() ? "" : json_text(t.value)), t.halvings, t.dt, csv_text(run_status_text(t.status)),
                       t.met ? 1 : 0, t.cost_ns, t.cost_pipe_ns ? fmt::format("{:.6g}", *t.cost_pipe_ns) : "", t.wall_s,
                       t.work, t.done);
    for (const SpecTermDef& d : spec_terms()) {
      const auto v = t.figures.value(d.key, nlohmann::json());
      out += v.is_null() ? "," : fmt::format(",{:.6g}", v.get<double>());
    }
    out += "," + csv_text(t.why_not) + "\n";
  }
  return out;
}

}  // namespace

void write_match_files(const MatchResult& m, const std::string& json_path, const std::string& csv_path) {
  write_file_atomically(json_path, to_json(m).dump(2) + "\n", "the match results");
  write_file_atomically(csv_path, match_csv(m), "the match CSV");
}

MatchResult read_match_file(const std::string& path) {
  return read_json_file(path, "a match result", [](const nlohmann::json& j) { return match_from_json(j); },
                        [](const nlohmann::json&) {
                          MatchResult m;  // the shape of a match file: one try and one outcome, every field set
                          m.tries.emplace_back().cost_pipe_ns = 0;
                          m.outcomes.emplace_back().cost_pipe_ns = 0;
                          return JsonShape{to_json(m), ""};
                        });
}

MatchResult merge_match_shards(const std::vector<MatchResult>& shards, const std::vector<std::string>& names) {
  if (shards.empty()) throw InputError("merge: no shards given");
  const MatchResult& first = shards.front();
  ShardRoll roll(first.shard_count, names);
  MatchResult out = first;
  out.tries.clear(), out.outcomes.clear();
  out.shard_index = out.shard_count = 1;
  out.context["shards"] = nlohmann::json::array();
  for (size_t k = 0; k < shards.size(); ++k) {
    const MatchResult& s = shards[k];
    if (s.scene != first.scene || s.scene_source != first.scene_source || s.scene_digest != first.scene_digest ||
        s.spec.to_json() != first.spec.to_json() || s.searches != first.searches || s.shard_count != first.shard_count ||
        s.n != first.n || s.dt != first.dt || s.budget_runs != first.budget_runs || s.ceiling != first.ceiling ||
        s.within != first.within)
      throw InputError(fmt::format("merge: {} is a shard of another match than {} (its scene's content, spec, "
                                   "searches, budget, ceiling, within or shard count differs)",
                                   names[k], names.front()));
    roll.take(k, s.shard_index, s.interrupted, json_string_field(s.context, "build"));
    out.context["shards"].push_back(s.context);
    const int offset = int(out.tries.size());
    out.tries.insert(out.tries.end(), s.tries.begin(), s.tries.end());
    for (MatchOutcome o : s.outcomes) {
      o.shift_tries(offset);
      out.outcomes.push_back(std::move(o));
    }
  }
  roll.check_complete();
  std::vector<std::string> searched;
  for (const MatchOutcome& o : out.outcomes) searched.push_back(o.engine + "/" + o.profile);
  check_plan_covered(first.searches, searched, "search");
  mark_outpaced(out);  // against the cheapest of every shard
  return out;
}

std::string timing_method_text() {
  return fmt::format(
      "the found configuration timed alone after the searches over a tenth of its run (or the first part of it "
      "that held {:g} s of the engine's time) from the state it saved there, or over its whole run where that held "
      "at most as much, run again in one process until a "
      "pass is under {:g}% faster than the one before and the passes hold {:g} s of the engine's time (the engine "
      "warm: a JIT's compiled code, caches), the mean of the warm passes scaled to the whole run; the fastest of "
      "the repeats, each round on the next core",
      kTimedWindowSeconds, 100 * kWarmGain, kWarmSeconds);
}

}  // namespace ballbench

#pragma once
// An engine's settings: reading its overrides (a JSON object) into its typed settings struct, with
// one clear line for an unknown key or a value of the wrong type (SettingsReader), and the table
// that declares each setting once (SettingsTable): its key, its member, the values it takes, its
// unit and one line of doc, from which reading, checking, settings() and `ballbench list
// --settings` all come. Adding a setting is its member in the struct and its row in the table.
#include <functional>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "engine.h"
#include "input_error.h"

namespace ballbench {

class SettingsReader {
 public:
  SettingsReader(std::string engine, const nlohmann::json& overrides);

  // Each get_* consumes a key if present; `value` keeps its default otherwise.
  void get(const char* key, double& value);
  void get(const char* key, int& value);
  void get(const char* key, bool& value);
  // A string that must be one of `choices`.
  void get(const char* key, std::string& value, const std::vector<const char*>& choices);
  // Any string (a path, a command).
  void get(const char* key, std::string& value);

  // Throws for any key that no get() consumed.
  void finish() const;

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& why) const;
  const nlohmann::json* find(const char* key);

  std::string engine_;
  nlohmann::json overrides_;
  std::vector<std::string> known_;
};

// The values a number may take, and what a refusal says after the key: at_least(1) refuses 0 with
// "must be >= 1", above(0, "m") refuses 0 with "must be > 0 (m)"; says() words it otherwise.
struct Bound {
  std::function<bool(double)> holds;  // empty: any value
  std::string range;                  // SettingInfo::range: ">= 1", "[0, 1]"
  std::string refusal;                // "must be >= 1"

  Bound says(std::string words) const { return {holds, range, std::move(words)}; }
};
inline const Bound any_value{};
Bound at_least(double lo, const char* why = "");
Bound above(double lo, const char* why = "");
Bound within(double lo, double hi);       // lo <= x <= hi: "[lo, hi]"
Bound inside(double lo, double hi);       // lo < x < hi: "(lo, hi)"
Bound bound(std::function<bool(double)> holds, std::string range, std::string refusal);

// One user setting of an engine whose settings are the struct S; made by setting() or choice().
template <class S>
struct SettingRow {
  const char* name;
  const char* unit;  // "" for a flag, a word or a text
  const char* doc;
  std::string range;                              // SettingInfo::range
  std::function<void(SettingsReader&, S&)> read;  // consumes the key if present
  std::function<std::string(const S&)> check;     // "" or the refusal
  std::function<nlohmann::json(const S&)> value;  // as settings() writes it
};

// An engine's settings declared once: each row reads, checks, writes and lists its setting.
template <class S>
class SettingsTable {
 public:
  SettingsTable(std::string engine, std::vector<SettingRow<S>> rows)
      : engine_(std::move(engine)), rows_(std::move(rows)) {}

  // `overrides` on top of `s`: every row reads its key, an unknown key is refused, then every row's
  // value (overridden or not) is checked; InputError "settings.ENGINE.KEY: why".
  void read(const nlohmann::json& overrides, S& s) const {
    SettingsReader r(engine_, overrides);
    for (const auto& row : rows_) row.read(r, s);
    r.finish();
    for (const auto& row : rows_)
      if (const std::string why = row.check(s); !why.empty())
        throw InputError(fmt::format("settings.{}.{}: {}", engine_, row.name, why));
  }

  // Every row's key and value, for Engine::settings().
  nlohmann::json json(const S& s) const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& row : rows_) j[row.name] = row.value(s);
    return j;
  }

  // Every row with its value in `defaults` (the struct's own, before any profile), for
  // EngineInfo::settings.
  std::vector<SettingInfo> describe(const S& defaults = S{}) const {
    std::vector<SettingInfo> out;
    for (const auto& row : rows_) out.push_back({row.name, row.value(defaults), row.range, row.unit, row.doc});
    return out;
  }

 private:
  std::string engine_;
  std::vector<SettingRow<S>> rows_;
};

namespace settings_detail {

// A row over the T that `at` finds in S.
template <class S, class T, class At>
SettingRow<S> row(const char* name, At at, Bound b, const char* unit, const char* doc) {
  static_assert(std::is_same_v<T, int> || std::is_same_v<T, double> || std::is_same_v<T, bool> ||
                    std::is_same_v<T, std::string>,
                "a setting is an int, a double, a bool or a string");
  const auto get = [at](const S& s) -> const T& { return at(const_cast<S&>(s)); };
  SettingRow<S> r{name, unit, doc, b.range, {}, {}, {}};
  r.read = [name, at](SettingsReader& reader, S& s) { reader.get(name, at(s)); };
  r.check = [get, b](const S& s) -> std::string {
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
      if (b.holds && !b.holds(static_cast<double>(get(s)))) return b.refusal;
    return "";
  };
  r.value = [get](const S& s) { return nlohmann::json(get(s)); };
  return r;
}

}  // namespace settings_detail

// A number, a flag or a text: the member `m` of S, or the member `m` of S's nested struct `sub`;
// a number is held to `b`.
template <class S, class T>
SettingRow<S> setting(const char* name, T S::*m, const Bound& b, const char* unit, const char* doc) {
  return settings_detail::row<S, T>(name, [m](S& s) -> T& { return s.*m; }, b, unit, doc);
}
template <class S, class Sub, class T>
SettingRow<S> setting(const char* name, Sub S::*sub, T Sub::*m, const Bound& b, const char* unit, const char* doc) {
  return settings_detail::row<S, T>(name, [sub, m](S& s) -> T& { return (s.*sub).*m; }, b, unit, doc);
}

// A word from a closed set: an enum member whose values `names` spells (the only place its words
// live).
template <class S, class E>
SettingRow<S> choice(const char* name, E S::*m, std::initializer_list<std::pair<E, const char*>> names,
                     const char* doc) {
  const std::vector<std::pair<E, const char*>> n(names);
  std::vector<const char*> words;
  for (const auto& entry : n) words.push_back(entry.second);
  const auto word_of = [n](E e) -> std::string {
    for (const auto& [value, word] : n)
      if (value == e) return word;
    return "";
  };
  SettingRow<S> r{name, "", doc, fmt::format("one of: {}", fmt::join(words, ", ")), {}, {}, {}};
  r.read = [name, m, n, words, word_of](SettingsReader& reader, S& s) {
    std::string word = word_of(s.*m);
    reader.get(name, word, words);
    for (const auto& [value, w] : n)
      if (word == w) s.*m = value;
  };
  r.check = [](const S&) { return std::string(); };
  r.value = [m, word_of](const S& s) { return nlohmann::json(word_of(s.*m)); };
  return r;
}

}  // namespace ballbench

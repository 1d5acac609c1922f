#pragma once
// Reading a TOML table (toml++) with every problem named by file, line and dotted field path: the
// scene files and the report's suites.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>
#include <toml++/toml.h>

#include "input_error.h"

namespace ballbench {

// "an integer", "an array of 3": what a node is, for messages.
inline std::string node_type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return fmt::format("an array of {}", n.as_array()->size());
    case toml::node_type::table: return "a table";
    default: return "a date or time";
  }
}

// Reads one TOML table, naming every problem by file, line and dotted field path.
class TableReader {
 public:
  TableReader(const toml::table& t, std::string source, std::string prefix)
      : t_(t), source_(std::move(source)), prefix_(std::move(prefix)) {}

  [[noreturn]] void fail(const toml::node* at, const std::string& field, const std::string& why) const {
    const auto line = at ? at->source().begin.line : t_.source().begin.line;
    throw InputError(fmt::format("{}:{}: {}: {}", source_, line, path(field), why));
  }
  std::string path(const std::string& field) const { return prefix_.empty() ? field : prefix_ + "." + field; }

  // Every key must be one of `allowed`.
  void check_keys(std::initializer_list<const char*> allowed) const {
    check_keys(std::vector<const char*>(allowed));
  }
  void check_keys(const std::vector<const char*>& allowed) const {
    for (const auto& [k, v] : t_) {
      const std::string key(k.str());
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; })) {
        std::vector<std::string> names(allowed.begin(), allowed.end());
        fail(&v, key, "unknown key" + did_you_mean(key, names));
      }
    }
  }

  bool has(const char* key) const { return t_.contains(key); }
  const toml::node* node(const char* key) const { return t_.get(key); }

  double number(const char* key) const {
    const toml::node* n = t_.get(key);
    if (!n) fail(nullptr, key, "missing (a number is required)");
    return as_number(n, key);
  }
  double number_or(const char* key, double fallback) const { return has(key) ? number(key) : fallback; }

  int64_t integer(const char* key, int64_t fallback) const {
    const toml::node* n = t_.get(key);
    if (!n) return fallback;
    if (!n->is_integer()) fail(n, key, fmt::format("expected an integer, got {}", type_name(*n)));
    return n->as_integer()->get();
  }

  bool boolean(const char* key, bool fallback) const {
    const toml::node* n = t_.get(key);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(n, key, fmt::format("expected true or false, got {}", type_name(*n)));
    return n->as_boolean()->get();
  }

  std::string string(const char* key, const std::string& fallback) const {
    const toml::node* n = t_.get(key);
    if (!n) return fallback;
    if (!n->is_string()) fail(n, key, fmt::format("expected a string, got {}", type_name(*n)));
    return n->as_string()->get();
  }

  // A 2-vector whose components stay within +-max_abs.
  Eigen::Vector2d vec2(const char* key, double max_abs) const {
    const toml::node* n = t_.get(key);
    if (!n) fail(nullptr, key, "missing (an array of two numbers is required)");
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2)
      fail(n, key, fmt::format("expected an array of two numbers [x, y], got {}", type_name(*n)));
    Eigen::Vector2d v{as_number(a->get(0), std::string(key) + "[0]"), as_number(a->get(1), std::string(key) + "[1]")};
    for (int i = 0; i < 2; ++i)
      if (std::abs(v[i]) > max_abs)
        fail(a->get(i), fmt::format("{}[{}]", key, i), fmt::format("must be within +-{:g}, got {}", max_abs, v[i]));
    return v;
  }
  Eigen::Vector2d vec2_or(const char* key, double max_abs, Eigen::Vector2d fallback) const {
    return has(key) ? vec2(key, max_abs) : fallback;
  }

  // An array of strings.
  std::vector<std::string> strings(const char* key, std::vector<std::string> fallback) const {
    const toml::node* n = t_.get(key);
    if (!n) return fallback;
    const toml::array* a = n->as_array();
    if (!a) fail(n, key, fmt::format("expected an array of strings, got {}", type_name(*n)));
    std::vector<std::string> out;
    for (size_t i = 0; i < a->size(); ++i) {
      const toml::node* e = a->get(i);
      if (!e->is_string()) fail(e, fmt::format("{}[{}]", key, i), fmt::format("expected a string, got {}", type_name(*e)));
      out.push_back(e->as_string()->get());
    }
    return out;
  }

 private:
  static std::string type_name(const toml::node& n) { return node_type_name(n); }
  double as_number(const toml::node* n, const std::string& field) const {
    double v;
    if (n->is_floating_point()) v = n->as_floating_point()->get();
    else if (n->is_integer()) v = static_cast<double>(n->as_integer()->get());
    else fail(n, field, fmt::format("expected a number, got {}", type_name(*n)));
    if (!std::isfinite(v)) fail(n, field, fmt::format("must be finite, got {}", v));
    return v;
  }

  const toml::table& t_;
  std::string source_;
  std::string prefix_;
};

}  // namespace ballbench

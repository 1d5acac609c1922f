#include "engines_file.h"

#include <filesystem>
#include <set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "data_file.h"
#include "input_error.h"

namespace ballbench {
namespace {

constexpr std::uintmax_t kMaxEnginesFileBytes = 1 << 20;  // a few dozen [[engine]] tables take kilobytes

std::string where(const std::string& path, const toml::node& n) {
  const auto line = n.source().begin.line;
  return line > 0 ? fmt::format("{}:{}", path, line) : path;
}

}  // namespace

std::vector<ProcessEngineSpec> read_engines_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(fmt::format("{}: engines file not found", path));
  check_readable_file(path, "the engines file", kMaxEnginesFileBytes);
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: {}", path, e.source().begin.line, e.description()));
  }
  const std::string folder = std::filesystem::absolute(path).parent_path().string();
  std::vector<ProcessEngineSpec> out;
  std::set<std::string> names;
  for (const auto& [key, node] : root)
    if (key.str() != "engine")
      throw InputError(fmt::format("{}: {}: unknown key (an engines file holds [[engine]] tables)", where(path, node), key.str()));
  const toml::array* engines = root["engine"].as_array();
  if (root.contains("engine") && !engines)
    throw InputError(fmt::format("{}: engine: expected [[engine]] tables", where(path, *root.get("engine"))));
  if (!engines) return out;
  for (const toml::node& n : *engines) {
    const toml::table* t = n.as_table();
    if (!t) throw InputError(fmt::format("{}: engine: expected a table", where(path, n)));
    ProcessEngineSpec spec;
    spec.cwd = folder;
    spec.source = where(path, n);
    spec.file = path;
    for (const auto& [key, value] : *t) {
      const std::string k(key.str()), at = where(path, value);
      if (k == "name") {
        const auto s = value.value<std::string>();
        if (!s || s->empty() || s->find_first_of(" ,.=:/") != std::string::npos || s->rfind("process", 0) == 0 ||
            has_control_character(*s) || *s == "all")
          throw InputError(fmt::format("{}: engine.name: expected a name without spaces, control characters or any of "
                                       "',.=:/', not starting 'process' and not 'all'", at));
        spec.name = *s;
      } else if (k == "command") {
        const toml::array* a = value.as_array();
        if (a)
          for (const toml::node& arg : *a)
            if (auto s = arg.value<std::string>()) spec.command.push_back(*s);
        if (!a || a->empty() || spec.command.size() != a->size() || spec.command.front().empty())
          throw InputError(fmt::format("{}: engine.command: expected a list of strings, the program first", at));
      } else if (k == "timeout_s") {
        const auto s = value.value<double>();
        if (!s || !(*s > 0) || *s > 1e6) throw InputError(fmt::format("{}: engine.timeout_s: expected seconds > 0", at));
        spec.timeout_s = *s;
      } else {
        throw InputError(fmt::format("{}: engine.{}: unknown key (known: name, command, timeout_s)", at, k));
      }
    }
    if (spec.name.empty()) throw InputError(fmt::format("{}: engine.name: missing", spec.source));
    if (spec.command.empty()) throw InputError(fmt::format("{}: engine.command: missing", spec.source));
    if (!names.insert(spec.name).second)
      throw InputError(fmt::format("{}: engine.name: '{}' is named twice", spec.source, spec.name));
    out.push_back(std::move(spec));
  }
  return out;
}

}  // namespace ballbench

#pragma once
// Reading an engine's settings overrides (a JSON object) into its typed settings struct, with one
// clear line for an unknown key or a value of the wrong type.
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

namespace ballbench {

class SettingsReader {
 public:
  SettingsReader(std::string engine, const nlohmann::json& overrides);

  // Each get_* consumes a key if present; `value` keeps its default otherwise.
  void get(const char* key, double& value);
  void get(const char* key, int& value);
  void get(const char* key, bool& value);
  // A string that must be one of `choices`.
  void get(const char* key, std::string& value, std::initializer_list<const char*> choices);
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

}  // namespace ballbench

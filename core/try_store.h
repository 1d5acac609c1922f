#pragma once
// The results store: tries measured before, kept on disk, so that a search measures only what
// changed. Each entry is keyed by everything that decides what the try measures (the scene's
// content, the engine and its version, the profile, the knob, the step, the spec, the reference
// and the build); an entry whose key differs in anything is another entry. One JSON file an entry,
// written atomically, so searches side by side and an interrupted one leave it whole.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace ballbench {

class TryStore {
 public:
  // `dir` "": keeps nothing. `fresh`: reads nothing (every try measured again) but keeps what runs.
  TryStore(std::string dir, bool fresh);

  // The value kept under `key`, or none.
  std::optional<nlohmann::json> find(const nlohmann::json& key) const;
  // Keeps `value` under `key`; a store that cannot be written says so once on stderr and goes on
  // without it (the search's results do not depend on it).
  void keep(const nlohmann::json& key, const nlohmann::json& value) const;

  bool enabled() const { return !dir_.empty(); }
  const std::string& dir() const { return dir_; }

  // $XDG_CACHE_HOME/ballbench/tries, else $HOME/.cache/ballbench/tries, else "" (none).
  static std::string default_dir();

 private:
  std::string path_of(const nlohmann::json& key) const;
  std::string dir_;
  bool fresh_;
};

}  // namespace ballbench

#include "try_store.h"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <xxhash.h>

#include "data_file.h"

namespace ballbench {

TryStore::TryStore(std::string dir, bool fresh) : dir_(std::move(dir)), fresh_(fresh) {}

std::string TryStore::default_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/ballbench/tries";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/ballbench/tries";
  return "";
}

std::string TryStore::path_of(const nlohmann::json& key) const {
  const std::string text = key.dump();
  const XXH128_hash_t h = XXH3_128bits(text.data(), text.size());
  const std::string hex = fmt::format("{:016x}{:016x}", h.high64, h.low64);
  return fmt::format("{}/{}/{}.json", dir_, hex.substr(0, 2), hex);
}

std::optional<nlohmann::json> TryStore::find(const nlohmann::json& key) const {
  if (dir_.empty() || fresh_) return std::nullopt;
  std::ifstream in(path_of(key));
  if (!in) return std::nullopt;
  const nlohmann::json entry = nlohmann::json::parse(in, nullptr, false);
  // A file cut short, or one of another key that hashed alike: not this entry.
  if (entry.is_discarded() || !entry.is_object() || entry.value("key", nlohmann::json()) != key ||
      !entry.contains("value"))
    return std::nullopt;
  return entry.at("value");
}

void TryStore::keep(const nlohmann::json& key, const nlohmann::json& value) const {
  if (dir_.empty()) return;
  static std::atomic<bool> warned{false};
  try {
    write_file_atomically(path_of(key), nlohmann::json{{"key", key}, {"value", value}}.dump() + "\n",
                          "the results store");
  } catch (const std::exception& e) {
    if (!warned.exchange(true)) fmt::print(stderr, "results store not written ({}): the search goes on without it\n", e.what());
  }
}

}  // namespace ballbench

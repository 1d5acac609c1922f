#include "shard.h"

#include <charconv>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench::cli {

Shard parse_shard(const std::string& text, const std::string& option) {
  Shard s;
  const char* const end = text.data() + text.size();
  const auto first = std::from_chars(text.data(), end, s.index);
  const bool slash = first.ec == std::errc() && first.ptr != end && *first.ptr == '/';
  const auto second = slash ? std::from_chars(first.ptr + 1, end, s.count) : first;
  if (!slash || second.ec != std::errc() || second.ptr != end || s.count < 1 || s.index < 1 || s.index > s.count)
    throw InputError(fmt::format("{} {}: expected I/N with whole numbers 1 <= I <= N, e.g. 2/3", option, text));
  return s;
}

std::string shard_file_name(const std::string& stem, const Shard& shard) {
  return shard.all() ? stem + ".json" : fmt::format("{}.shard{}of{}.json", stem, shard.index, shard.count);
}

}  // namespace ballbench::cli

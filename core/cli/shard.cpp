#include "shard.h"

#include <charconv>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench::cli {

Shard parse_shard(const std::string& text, const std::string& option) {
  Shard s;
  const char* const end = text.data() + text.size();
  const auto [slash, e1] = std::from_chars(text.data(), end, s.index);
  const bool ok = e1 == std::errc() && slash != end && *slash == '/' &&
                  [&] {
                    const auto [tail, e2] = std::from_chars(slash + 1, end, s.count);
                    return e2 == std::errc() && tail == end;
                  }() &&
                  s.count >= 1 && s.index >= 1 && s.index <= s.count;
  if (!ok) throw InputError(fmt::format("{} {}: expected I/N with whole numbers 1 <= I <= N, e.g. 2/3", option, text));
  return s;
}

}  // namespace ballbench::cli

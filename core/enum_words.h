#pragma once
// A closed set of words for an enum, declared once as a table: the word of a value, and the value
// of a word read back from a file (an unknown word is one line naming the set and its words).
#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "input_error.h"

namespace ballbench {

template <class Enum, size_t N>
struct EnumWords {
  const char* what;  // "run status", for the error
  std::array<std::pair<Enum, const char*>, N> words;

  const char* word(Enum e) const {
    for (const auto& [value, w] : words)
      if (value == e) return w;
    return "unknown";
  }
  Enum value(std::string_view w) const {
    for (const auto& [value, text] : words)
      if (text == w) return value;
    std::vector<const char*> known;
    for (const auto& entry : words) known.push_back(entry.second);
    throw InputError(fmt::format("unknown {} '{}' (known: {})", what, w, fmt::join(known, ", ")));
  }
};

}  // namespace ballbench

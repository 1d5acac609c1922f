#pragma once
// An error in what the user gave us (a scene file, a flag, an engine name). The CLI prints its
// message as one line and exits non-zero; library code never exits on its own.
#include <stdexcept>
#include <string>

namespace ballbench {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Text from outside (an engine's name or error, a file's field) made safe for one line of a
// terminal: control characters escaped (\n, \t, \x1b), and text beyond `max_bytes` cut from its
// middle, saying how much, its head and its tail kept: "HEAD... (N bytes cut) ...TAIL".
std::string printable(const std::string& text, size_t max_bytes = 2000);

// True if `text` holds a control character (a newline, an escape): not allowed in names.
bool has_control_character(const std::string& text);

// Levenshtein distance, for "did you mean" hints on unknown names.
int edit_distance(const std::string& a, const std::string& b);

// ", did you mean 'x'?" for the closest candidate within a small distance, or "".
template <class Range>
std::string did_you_mean(const std::string& word, const Range& candidates) {
  std::string best;
  int best_d = 3;  // more than two edits away is not a typo
  for (const auto& c : candidates) {
    const int d = edit_distance(word, std::string(c));
    if (d < best_d) best_d = d, best = std::string(c);
  }
  return best.empty() ? std::string() : ", did you mean '" + best + "'?";
}

}  // namespace ballbench

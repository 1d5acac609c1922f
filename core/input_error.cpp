#include "input_error.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace ballbench {

std::string printable(const std::string& text, size_t max_bytes) {
  static const char* kHex = "0123456789abcdef";
  std::string out;
  size_t k = 0;
  for (; k < text.size() && out.size() < max_bytes; ++k) {
    const unsigned char c = static_cast<unsigned char>(text[k]);
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else if (c < 0x20 || c == 0x7f) out += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
    else out += static_cast<char>(c);
  }
  if (k < text.size()) out += "... (" + std::to_string(text.size() - k) + " bytes cut)";
  return out;
}

bool has_control_character(const std::string& text) {
  return std::any_of(text.begin(), text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  });
}

int edit_distance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diag = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace ballbench

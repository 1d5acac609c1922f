#include "input_error.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace ballbench {

namespace {

void put_escaped(std::string& out, unsigned char c) {
  static const char* kHex = "0123456789abcdef";
  if (c == '\n') out += "\\n";
  else if (c == '\t') out += "\\t";
  else if (c == '\r') out += "\\r";
  else if (c < 0x20 || c == 0x7f) out += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
  else out += static_cast<char>(c);
}

}  // namespace

std::string printable(const std::string& text, size_t max_bytes) {
  // The head and the tail are kept: a message's reason follows the value it quotes.
  const size_t head_bytes = max_bytes - max_bytes / 3, tail_bytes = max_bytes / 3;
  std::string head, tail;
  size_t front = 0, back = text.size();
  for (; front < back && head.size() < head_bytes; ++front) put_escaped(head, static_cast<unsigned char>(text[front]));
  std::vector<std::string> pieces;  // the tail's characters, last first
  for (size_t taken = 0; back > front && taken < tail_bytes;) {
    std::string piece;
    put_escaped(piece, static_cast<unsigned char>(text[--back]));
    taken += piece.size();
    pieces.push_back(std::move(piece));
  }
  for (auto it = pieces.rbegin(); it != pieces.rend(); ++it) tail += *it;
  if (front == back) return head + tail;
  return head + "... (" + std::to_string(back - front) + " bytes cut) ..." + tail;
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

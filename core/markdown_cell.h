#pragma once
// Text for a Markdown table cell: a `|` would end the cell and a line break the row.
#include <string>

namespace ballbench {

inline std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

}  // namespace ballbench

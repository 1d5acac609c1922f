#pragma once
// A report section's text, appended to with format strings checked at compile time.
#include <iterator>
#include <string>

#include <fmt/format.h>

namespace ballbench {

struct MarkdownBuffer {
  fmt::memory_buffer out;
  template <class... Args>
  void operator()(fmt::format_string<Args...> f, Args&&... args) {
    fmt::format_to(std::back_inserter(out), f, std::forward<Args>(args)...);
  }
  std::string str() const { return fmt::to_string(out); }
};

}  // namespace ballbench

#pragma once
// Command-line checks whose failure reads as one line naming the rule and the value given. CLI11's
// own PositiveNumber lets "nan" through and prints its range with DBL_MAX's 309 digits.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

namespace ballbench::cli {

// A finite number > 0.
inline const CLI::Validator kPositiveNumber(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0') return "expected a number, got '" + text + "'";
      if (!std::isfinite(v) || errno == ERANGE) return "must be a finite number, got '" + text + "'";
      if (!(v > 0)) return "must be > 0, got '" + text + "'";
      return {};
    },
    "POSITIVE", "positive number");

// A whole number >= 1 that fits the option's int.
inline const CLI::Validator kPositiveCount(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      errno = 0;
      const long long v = std::strtoll(text.c_str(), &end, 10);
      if (end == text.c_str() || *end != '\0') return "expected a whole number, got '" + text + "'";
      if (v < 1) return "must be >= 1, got '" + text + "'";
      if (errno == ERANGE || v > 2147483647LL) return "must be at most 2147483647, got '" + text + "'";
      return {};
    },
    "COUNT", "positive count");

}  // namespace ballbench::cli

#pragma once
// Command-line checks whose failure reads as one line naming the rule and the value given. CLI11's
// own PositiveNumber lets "nan" through and prints its range with DBL_MAX's 309 digits.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
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

// A finite number > 0, or "none", which it turns into 0 (no limit).
inline const CLI::Validator kPositiveNumberOrNone(
    [](std::string& text) -> std::string {
      if (text == "none") {
        text = "0";
        return {};
      }
      return kPositiveNumber(text);
    },
    "POSITIVE|none", "positive number or none");

// A finite number >= 1, or "none", which it turns into 0 (no limit): a multiple of a cost that must
// not fall below the cost itself.
inline const CLI::Validator kMultipleOrNone(
    [](std::string& text) -> std::string {
      if (std::string bad = kPositiveNumberOrNone(text); !bad.empty()) return bad;
      if (text != "0" && std::strtod(text.c_str(), nullptr) < 1) return "must be at least 1, got '" + text + "'";
      return {};
    },
    "MULTIPLE|none", "number at least 1, or none");

// A whole number from `least` to `most` (CLI11's Range says "not in range" of 1.5 or 0x10).
inline CLI::Validator whole_in_range(long long least, long long most) {
  return CLI::Validator(
      [least, most](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(text.c_str(), &end, 10);
        if (end == text.c_str() || *end != '\0' || errno == ERANGE || v < least || v > most)
          return "expected a whole number from " + std::to_string(least) + " to " + std::to_string(most) + ", got '" +
                 text + "'";
        return {};
      },
      "INT in [" + std::to_string(least) + " - " + std::to_string(most) + "]", "whole number in range");
}

// A whole number from 1 to `most`; `too_many` names the cap in the refusal.
inline CLI::Validator whole_number_validator(long long most, std::string too_many, std::string name,
                                             std::string description) {
  return CLI::Validator(
      [most, too_many](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(text.c_str(), &end, 10);
        if (end == text.c_str() || *end != '\0') return "expected a whole number, got '" + text + "'";
        if (v < 1) return "must be >= 1, got '" + text + "'";
        if (errno == ERANGE || v > most) return "must be at most " + too_many + ", got '" + text + "'";
        return {};
      },
      std::move(name), std::move(description));
}

// A whole number >= 1 that fits the option's int.
inline const CLI::Validator kPositiveCount = whole_number_validator(2147483647LL, "2147483647", "COUNT", "positive count");

// A step count: a whole number from 1 to the cap of 1e9 steps (the scenes' own cap, README).
inline const CLI::Validator kStepCount = whole_number_validator(1000000000LL, "1e9 steps", "STEPS", "step count");

// A file to write: not empty, and not a folder (an existing one, or a path ending in '/'), which
// would pass every check before the run and fail only when the results are written after it.
inline const CLI::Validator kOutputFile(
    [](std::string& text) -> std::string {
      if (text.empty()) return "expected a file to write, got an empty path";
      std::error_code ec;
      if (text.back() == '/' || std::filesystem::is_directory(text, ec))
        return "'" + text + "' is a folder: name a file to write";
      return {};
    },
    "FILE", "file to write");

}  // namespace ballbench::cli

#pragma once
// Progress on stderr for long work (runs, placing a large scene's balls): a self-updating line on a
// terminal, plain lines otherwise, with an estimate of the time left. Silent for work that
// finishes within a second, and everywhere once a command's --quiet has set `quiet`. Work of items
// too unlike to estimate from (a match's searches: seconds to an hour each) is counted instead.
#include <chrono>
#include <cstddef>
#include <string>

namespace ballbench {

class Progress {
 public:
  explicit Progress(std::string label);
  ~Progress();
  void update(double fraction);
  // Item `done` of `total` finished (`what`: which, and how it ended): a line each, with the time so
  // far and no estimate.
  void count(size_t done, size_t total, const std::string& what);

  static inline bool quiet = false;

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  bool tty_;
  bool shown_ = false;
  int last_decile_ = -1;
};

}  // namespace ballbench

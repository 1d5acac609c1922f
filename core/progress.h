#pragma once
// Progress on stderr for long work (runs, placing a large scene's balls): a self-updating line on a
// terminal, plain lines otherwise, with an estimate of the time left. Silent for work that
// finishes within a second, and everywhere once a command's --quiet has set `quiet`.
#include <chrono>
#include <string>

namespace ballbench {

class Progress {
 public:
  explicit Progress(std::string label);
  ~Progress();
  void update(double fraction);

  static inline bool quiet = false;

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  bool tty_;
  bool shown_ = false;
  int last_decile_ = -1;
};

}  // namespace ballbench

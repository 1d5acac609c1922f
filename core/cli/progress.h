#pragma once
// Progress on stderr for long runs: a self-updating line on a terminal, plain lines otherwise,
// with an estimate of the time left. Silent for runs that finish within a second.
#include <chrono>
#include <string>

namespace ballbench {

class Progress {
 public:
  explicit Progress(std::string label);
  ~Progress();
  void update(double fraction);

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  bool tty_;
  bool shown_ = false;
  int last_decile_ = -1;
};

}  // namespace ballbench

#include "progress.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

namespace ballbench {

Progress::Progress(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), tty_(isatty(STDERR_FILENO)) {}

Progress::~Progress() {
  if (shown_ && tty_) std::fputs("\n", stderr);
}

void Progress::update(double fraction) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (quiet || elapsed < 1.0 || fraction <= 0) return;
  const double left = elapsed * (1 - fraction) / fraction;
  if (tty_) {
    const int width = 30, filled = static_cast<int>(fraction * width);
    fmt::print(stderr, "\r{} [{}{}] {:3.0f}%  ~{:.0f} s left ", label_, std::string(filled, '#'),
               std::string(width - filled, '.'), 100 * fraction, left);
    shown_ = true;
  } else if (const int decile = static_cast<int>(fraction * 10); decile > last_decile_) {
    last_decile_ = decile;
    fmt::print(stderr, "{}: {:.0f}% done, ~{:.0f} s left\n", label_, 100 * fraction, left);
  }
}

void Progress::count(size_t done, size_t total, const std::string& what) {
  if (quiet) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  fmt::print(stderr, "{}{}: {} of {} done after {:.0f} s ({})\n", tty_ && shown_ ? "\n" : "", label_, done, total,
             elapsed, what);
  shown_ = false;
}

}  // namespace ballbench

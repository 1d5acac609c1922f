#include "gnuplot.h"

#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

namespace ballbench {

void run_gnuplot(const std::filesystem::path& script) {
  const std::string cmd = fmt::format("gnuplot '{}' 2>'{}.log'", script.string(), script.string());
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error(fmt::format("gnuplot failed on {} (see {}.log)", script.string(), script.string()));
  std::filesystem::remove(script.string() + ".log");  // kept only when it has something to say
}

std::string slug(std::string s) {
  for (char& c : s)
    if (c == '/' || c == ' ') c = '-';
  return s;
}

}  // namespace ballbench

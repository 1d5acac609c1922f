#pragma once
// Running the `ballbench` binary from a test, as a user would: exit status, stdout and stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>

namespace ballbench::testing {

struct CliOutcome {
  int status;  // exit status, or 128 + the signal that ended it
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs `ballbench ARGS` (BALLBENCH_CLI, set by tests/CMakeLists.txt).
inline CliOutcome run_cli(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string tag = std::to_string(::getpid());  // per process: ctest runs tests in parallel
  const std::string out = (dir / ("ballbench_cli_out." + tag)).string();
  const std::string err = (dir / ("ballbench_cli_err." + tag)).string();
  const int rc = std::system(fmt::format("{} {} >{} 2>{}", BALLBENCH_CLI, args, out, err).c_str());
  CliOutcome outcome{WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc), slurp(out), slurp(err)};
  std::error_code ec;  // nothing left behind in the temporary folder
  std::filesystem::remove(out, ec), std::filesystem::remove(err, ec);
  return outcome;
}

// Bad input: exit status 2 and one line on stderr holding `fragment`.
inline void expect_one_line_error(const CliOutcome& o, const std::string& fragment) {
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find(fragment), std::string::npos) << o.err;
  ASSERT_FALSE(o.err.empty());
  EXPECT_EQ(o.err.find('\n'), o.err.size() - 1) << "more than one line: " << o.err;
}

// A folder of a test's own in the temporary folder, empty at the start, removed at the end.
struct Scratch {
  std::filesystem::path dir;
  explicit Scratch(const std::string& name)
      : dir(std::filesystem::temp_directory_path() / (name + "." + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~Scratch() { std::filesystem::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

}  // namespace ballbench::testing

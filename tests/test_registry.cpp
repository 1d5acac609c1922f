// The registry lists our solvers, then the engine of every adapter folder whose CMakeLists.txt
// registers it with ballbench_adapter(NAME) (adapters/CMakeLists.txt), in the folders' order: the
// documented steps of adding an engine (docs/engines.md) are the real ones.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "registry.h"

namespace ballbench {
namespace {

namespace fs = std::filesystem;

struct AdapterFolder {
  std::string name;
  bool conditional;  // returns before registering when its library is missing
};

std::vector<AdapterFolder> registered_folders() {
  std::vector<AdapterFolder> out;
  const std::regex call(R"(^\s*ballbench_adapter\((\w+)\))");
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(fs::path(BALLBENCH_SOURCE_DIR) / "adapters"))
    if (e.is_directory() && fs::exists(e.path() / "CMakeLists.txt")) folders.push_back(e.path());
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    std::ifstream in(folder / "CMakeLists.txt");
    std::string line;
    bool returns = false;
    while (std::getline(in, line)) {
      std::smatch m;
      if (std::regex_search(line, m, call)) {
        EXPECT_EQ(m[1].str(), folder.filename().string()) << folder << ": registers another folder's name";
        out.push_back({m[1].str(), returns});
      }
      if (std::regex_search(line, std::regex(R"(^\s*return\(\))"))) returns = true;
    }
  }
  return out;
}

TEST(Registry, ListsOurSolversThenEveryRegisteredAdapterFolderInOrder) {
  std::vector<std::string> builtins;
  for (const std::string& name : engine_names())
    if (is_builtin_engine(name)) builtins.push_back(name);
  ASSERT_GE(builtins.size(), 3u);
  EXPECT_EQ(std::vector<std::string>(builtins.begin(), builtins.begin() + 3),
            (std::vector<std::string>{"home-seed", "home", "exact"}));
  const std::vector<std::string> adapters(builtins.begin() + 3, builtins.end());
  const std::vector<AdapterFolder> folders = registered_folders();
  ASSERT_GE(folders.size(), 4u);  // box2d, bullet, chipmunk, ode at least; lammps where liblammps is
  size_t next = 0;
  for (const AdapterFolder& f : folders) {
    if (next < adapters.size() && adapters[next] == f.name) {
      ++next;
      continue;
    }
    EXPECT_TRUE(f.conditional) << f.name << ": registered in its CMakeLists.txt but not in the registry";
  }
  EXPECT_EQ(next, adapters.size()) << "an adapter in the registry without a registering folder, or out of order";
}

}  // namespace
}  // namespace ballbench

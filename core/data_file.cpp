#include "data_file.h"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {

void write_file_atomically(const std::string& path, const std::string& text, const std::string& what) {
  const std::filesystem::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(fmt::format("{}: cannot write {}", path, what));
    out << text;
    if (!out.flush()) throw InputError(fmt::format("{}: writing {} failed (disk full?)", path, what));
  }
  std::filesystem::rename(tmp, target, ec);
  if (ec) throw InputError(fmt::format("{}: cannot write {}: {}", path, what, ec.message()));
}

nlohmann::json parse_json_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open {}", path, what));
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded()) throw InputError(fmt::format("{}: {} is not valid JSON", path, what));
  return j;
}

std::string json_shape_error(const std::string& path, const std::string& what, const std::exception& e) {
  return fmt::format("{}: not {}: {}", path, what, e.what());
}

}  // namespace ballbench

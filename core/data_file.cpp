#include "data_file.h"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {

namespace {

// An existing target that is not a regular file (a FIFO, a device such as /dev/null), or a symbolic
// link (/dev/stdout, a user's link to a file), is written in place: a rename would replace it with
// a regular file, and /dev/stdout with one for the whole machine.
bool special_target(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec))) return true;
  const auto st = std::filesystem::status(path, ec);
  return !ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) &&
         !std::filesystem::is_directory(st);
}

void fail_if_folder(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(fmt::format("{}: cannot write {}: it is a folder", path, what));
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text, const std::string& what) {
  fail_if_folder(path, what);
  // A FIFO or a device is written directly, with no temporary file beside it (a user may not
  // write into /dev), rather than through move_file_into_place's copy.
  const bool in_place = special_target(path);
  const std::filesystem::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
  const std::string tmp = in_place ? path : path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(fmt::format("{}: cannot write {}", path, what));
    out << text;
    if (!out.flush()) throw InputError(fmt::format("{}: writing {} failed (disk full?)", path, what));
  }
  if (in_place) return;
  std::filesystem::rename(tmp, target, ec);
  if (ec) throw InputError(fmt::format("{}: cannot write {}: {}", path, what, ec.message()));
}

void move_file_into_place(const std::string& from, const std::string& to, const std::string& what) {
  fail_if_folder(to, what);
  std::error_code ec;
  if (special_target(to)) {
    {
      std::ifstream in(from, std::ios::binary);
      std::ofstream out(to, std::ios::binary);
      if (!in || !out) throw InputError(fmt::format("{}: cannot write {}", to, what));
      out << in.rdbuf();
      if (!out.flush()) throw InputError(fmt::format("{}: writing {} failed", to, what));
    }
    std::filesystem::remove(from, ec);
    return;
  }
  std::filesystem::rename(from, to, ec);
  if (ec) throw InputError(fmt::format("{}: cannot write {}: {}", to, what, ec.message()));
}

void check_writable(const std::string& path, const std::string& what, bool create_parents) {
  fail_if_folder(path, what);
  if (special_target(path)) return;
  const std::filesystem::path target(path);
  std::error_code ec;
  if (create_parents && target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
  const std::string probe = path + ".tmp";
  const bool existed = std::filesystem::exists(probe, ec);
  {
    std::ofstream out(probe, std::ios::binary | std::ios::app);
    if (!out) throw InputError(fmt::format("{}: cannot write {} there", path, what));
  }
  if (!existed) std::filesystem::remove(probe, ec);
}

nlohmann::json parse_json_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(fmt::format("{}: cannot read {}: it is a folder", path, what));
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

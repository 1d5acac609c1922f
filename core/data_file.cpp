#include "data_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string_view>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {

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

std::string temp_base(const std::string& path) {
  if (!special_target(path)) return path;
  std::error_code ec;
  const auto dir = std::filesystem::temp_directory_path(ec);
  return ((ec ? std::filesystem::path("/tmp") : dir) / "ballbench-output").string();
}

namespace {

// A folder is never replaced by a file, nor a write-protected file by a rename (a rename needs only
// the folder's permission, and root's writes ignore the file's mode: its mode bits are the owner's
// word, so they are read as such).
void fail_if_not_replaceable(const std::string& path, const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  if (S_ISDIR(st.st_mode)) throw InputError(fmt::format("{}: cannot write {}: it is a folder", path, what));
  if (S_ISREG(st.st_mode) && ((st.st_mode & 0222) == 0 || ::access(path.c_str(), W_OK) != 0))
    throw InputError(fmt::format("{}: cannot write {}: the file is write-protected (mode {:04o}); ballbench does not "
                                 "replace it",
                                 path, what, st.st_mode & 07777));
}

// What identifies a file: its device and inode where it exists, else its resolved absolute path.
struct FileKey {
  bool exists = false, special = false;  // special: a device or a FIFO, which several outputs may share
  dev_t dev = 0;
  ino_t ino = 0;
  std::string resolved;
  bool operator==(const FileKey& o) const {
    return exists == o.exists && (exists ? dev == o.dev && ino == o.ino : resolved == o.resolved);
  }
};

// The absolute path with every symbolic link of its existing part followed, `..` and `.` resolved.
std::string resolved_path(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(path, ec);
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(abs, ec);
  return (ec ? abs : resolved).lexically_normal().string();
}

// A path that does not resolve yet ("new/../a.toml") is keyed as the OS will resolve it once the
// writer has created its missing folders: by the file it then names, if that exists.
FileKey file_key(const std::string& path) {
  FileKey k;
  struct stat st {};
  const std::string resolved = resolved_path(path);
  if (::stat(path.c_str(), &st) == 0 || ::stat(resolved.c_str(), &st) == 0) {
    k.exists = true, k.dev = st.st_dev, k.ino = st.st_ino;
    k.special = !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
    return k;
  }
  k.resolved = resolved;
  return k;
}

std::vector<PathUse>& noted_inputs() {
  static std::vector<PathUse> uses;
  return uses;
}

// A process id at the front of `name`, taken off it (decimal, no leading zero: Linux pids are
// below 2^22); 0, `name` untouched, if none.
pid_t take_pid(std::string_view& name) {
  size_t digits = 0;
  while (digits < name.size() && std::isdigit(static_cast<unsigned char>(name[digits]))) ++digits;
  if (digits == 0 || digits > 9 || name.front() == '0') return 0;
  const auto pid = static_cast<pid_t>(std::stol(std::string(name.substr(0, digits))));
  name.remove_prefix(digits);
  return pid;
}

// Removes the entries of `folder` that `owner_of` (name -> pid, 0 for a name not ours) says a
// process made that is gone: only a process known to be gone (ESRCH); a live one, or another
// user's (EPERM), keeps its files. `folders`: the entries are folders, removed with what they hold.
void remove_left_by_dead(const std::filesystem::path& folder, const std::function<pid_t(std::string_view)>& owner_of,
                         bool folders) {
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t owner = owner_of(it->path().filename().string());
    if (owner <= 0 || owner == ::getpid() || ::kill(owner, 0) == 0 || errno != ESRCH) continue;
    std::error_code rm;
    if (it->is_symlink(rm)) continue;
    if (folders && it->is_directory(rm)) std::filesystem::remove_all(it->path(), rm);
    else if (!folders && it->is_regular_file(rm)) std::filesystem::remove(it->path(), rm);
  }
}

// The process that made NAME, if NAME is a temporary file of writing BASE (beside it):
// BASE[.part].tmp.PID.TOKEN[.header|.tmp], TOKEN eight hex digits, as create_temp_beside names them
// and the trajectory's writers derive from them (run_engines.cpp, isolated_run.cpp); 0 otherwise.
pid_t temp_owner(std::string_view name, std::string_view base) {
  const auto take = [&](std::string_view part) {
    if (!name.starts_with(part)) return false;
    name.remove_prefix(part.size());
    return true;
  };
  if (!take(base)) return 0;
  take(".part");
  if (!take(".tmp.")) return 0;
  const pid_t pid = take_pid(name);
  if (!pid || !take(".") || name.size() < 8) return 0;
  for (size_t k = 0; k < 8; ++k)
    if (!std::isdigit(static_cast<unsigned char>(name[k])) && (name[k] < 'a' || name[k] > 'f')) return 0;
  name.remove_prefix(8);
  return name.empty() || name == ".header" || name == ".tmp" ? pid : 0;
}

}  // namespace

std::string write_error_text(int err) { return err ? std::strerror(err) : "an I/O error"; }

void remove_stale_temps(const std::string& path) {
  const std::filesystem::path target(path);
  const std::string base = target.filename().string();
  if (base.empty()) return;
  remove_left_by_dead(target.has_parent_path() ? target.parent_path() : ".",
                      [&](std::string_view name) { return temp_owner(name, base); }, false);
}

namespace {

// The process that made folder NAME with make_work_folder(PREFIX): PREFIX.PID.XXXXXX (mkdtemp's six
// letters and digits); 0 for any other name.
pid_t work_folder_owner(std::string_view name, std::string_view prefix) {
  if (!name.starts_with(prefix) || name.size() < prefix.size() + 1 || name[prefix.size()] != '.') return 0;
  name.remove_prefix(prefix.size() + 1);
  const pid_t pid = take_pid(name);
  if (!pid || name.size() != 7 || name.front() != '.') return 0;
  for (char c : name.substr(1))
    if (!std::isalnum(static_cast<unsigned char>(c))) return 0;
  return pid;
}

}  // namespace

std::string make_work_folder(const std::string& prefix) {
  std::error_code ec;
  const std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);
  const std::filesystem::path root = ec ? std::filesystem::path("/tmp") : tmp;
  remove_left_by_dead(root, [&](std::string_view name) { return work_folder_owner(name, prefix); }, true);
  std::string name = (root / fmt::format("{}.{}.XXXXXX", prefix, ::getpid())).string();
  if (!::mkdtemp(name.data()))
    throw InputError(fmt::format("{}: cannot make a working folder there: {}", root.string(), std::strerror(errno)));
  return name;
}

std::string create_temp_beside(const std::string& path, const std::string& what) {
  remove_stale_temps(path);
  static std::mt19937_64 rng{std::random_device{}() ^ static_cast<uint64_t>(::getpid())};
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string tmp = fmt::format("{}.tmp.{}.{:08x}", path, ::getpid(), static_cast<uint32_t>(rng()));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return tmp;
    }
    if (errno != EEXIST) throw InputError(fmt::format("{}: cannot write {} there: {}", path, what, std::strerror(errno)));
  }
  throw InputError(fmt::format("{}: cannot write {} there: no free temporary name", path, what));
}

void check_readable_file(const std::string& path, const std::string& what, std::uintmax_t max_bytes) {
  struct stat st {};
  if (path.empty()) throw InputError(fmt::format("cannot read {}: an empty path", what));
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(fmt::format("{}: cannot read {}: {}", path, what,
                                 errno == ENOENT ? "no such file" : std::strerror(errno)));
  if (S_ISDIR(st.st_mode)) throw InputError(fmt::format("{}: cannot read {}: it is a folder", path, what));
  if (!S_ISREG(st.st_mode))
    throw InputError(fmt::format("{}: cannot read {}: not a regular file (a {})", path, what,
                                 S_ISFIFO(st.st_mode) ? "FIFO" : S_ISSOCK(st.st_mode) ? "socket" : "device"));
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
    throw InputError(fmt::format("{}: cannot read {}: {} bytes, above the limit of {} MiB", path, what,
                                 static_cast<std::uintmax_t>(st.st_size), max_bytes >> 20));
}

void check_path_clashes(const std::vector<PathUse>& uses) {
  std::vector<FileKey> keys;
  for (const PathUse& u : uses) keys.push_back(file_key(u.path));
  for (const PathUse& folder : uses) {
    if (!folder.output || !folder.folder) continue;
    std::string root = resolved_path(folder.path);
    if (!root.ends_with('/')) root += '/';
    for (const PathUse& u : uses)
      if (!u.output && resolved_path(u.path).starts_with(root))
        throw InputError(fmt::format("{} {}: inside {} {}, which the command writes", u.flag, u.path, folder.flag, folder.path));
  }
  for (size_t i = 0; i < uses.size(); ++i)
    for (size_t j = 0; j < i; ++j) {
      if (uses[i].folder || uses[j].folder) continue;
      if (!uses[i].output && !uses[j].output) continue;  // reading one file twice is harmless
      if (!(keys[i] == keys[j])) continue;
      if (keys[i].special && uses[i].output && uses[j].output) continue;  // /dev/null twice
      // The output is named first: it is the one that would destroy the other.
      const PathUse& a = uses[i].output ? uses[i] : uses[j];
      const PathUse& b = uses[i].output ? uses[j] : uses[i];
      throw InputError(fmt::format("{} {}: same file as {} {}", a.flag, a.path, b.flag, b.path));
    }
}

void note_input_file(const std::string& flag, const std::string& path) { noted_inputs().push_back({flag, path, false}); }

const std::vector<PathUse>& noted_input_files() { return noted_inputs(); }

void write_file_atomically(const std::string& path, const std::string& text, const std::string& what) {
  if (path.empty()) throw InputError(fmt::format("cannot write {}: an empty path", what));
  fail_if_not_replaceable(path, what);
  // A FIFO or a device is written directly, with no temporary file beside it (a user may not
  // write into /dev), rather than through move_file_into_place's copy.
  const bool in_place = special_target(path);
  const std::filesystem::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
  const std::string tmp = in_place ? path : create_temp_beside(path, what);
  const auto fail = [&](const std::string& message) {
    if (!in_place) std::filesystem::remove(tmp, ec);
    throw InputError(message);
  };
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) fail(fmt::format("{}: cannot write {}", path, what));
    out << text;
    if (!out.flush()) fail(fmt::format("{}: writing {} failed: {}", path, what, write_error_text(errno)));
    out.close();
    if (!out) fail(fmt::format("{}: writing {} failed: {}", path, what, write_error_text(errno)));
  }
  if (in_place) return;
  std::filesystem::rename(tmp, target, ec);
  if (ec) fail(fmt::format("{}: cannot write {}: {}", path, what, ec.message()));
}

void move_file_into_place(const std::string& from, const std::string& to, const std::string& what) {
  fail_if_not_replaceable(to, what);
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
  fail_if_not_replaceable(path, what);
  if (special_target(path)) return;
  const std::filesystem::path target(path);
  std::error_code ec;
  if (create_parents && target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
  std::string probe;
  try {
    probe = create_temp_beside(path, what);
  } catch (const InputError&) {
    throw InputError(fmt::format("{}: cannot write {} there", path, what));
  }
  std::filesystem::remove(probe, ec);
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json parse_json_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(fmt::format("{}: cannot read {}: it is a folder", path, what));
  if (!std::filesystem::exists(path, ec)) throw InputError(fmt::format("{}: cannot open {}", path, what));
  check_readable_file(path, what, kMaxResultsFileBytes);
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open {}", path, what));
  // Nesting is bounded while parsing: a deeply nested value would be copied and destroyed
  // recursively afterwards, past the stack.
  struct TooDeep {};
  const nlohmann::json::parser_callback_t depth_cap = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (depth > kMaxJsonDepth) throw TooDeep{};
    return true;
  };
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in, depth_cap, false);
  } catch (const TooDeep&) {
    throw InputError(fmt::format("{}: {} nests deeper than {} levels: not a file ballbench wrote", path, what, kMaxJsonDepth));
  }
  if (j.is_discarded()) throw InputError(fmt::format("{}: {} is not valid JSON", path, what));
  return j;
}

std::string json_shape_error(const std::string& path, const std::string& what, const std::exception& e) {
  return fmt::format("{}: not {}: {}", path, what, e.what());
}

const char* json_kind_name(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::boolean: return "true or false";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::binary: return "binary data";
    default: return "a number";
  }
}

namespace {

bool same_kind(const nlohmann::json& shape, const nlohmann::json& got) {
  if (shape.is_null()) return true;
  if (shape.is_number()) return got.is_number() || got.is_null();
  return std::string_view(json_kind_name(shape)) == json_kind_name(got);
}

// Depth first, in `shape`'s order; `at` is the path so far.
std::string mismatch(const nlohmann::json& shape, const nlohmann::json& got, const std::string& at,
                     const std::string& missing) {
  const std::string here = at.empty() ? "the file" : at;
  if (!same_kind(shape, got)) return fmt::format("{}: expected {}, got {}", here, json_kind_name(shape), json_kind_name(got));
  if (shape.is_array() && !shape.empty())
    for (size_t k = 0; k < got.size(); ++k)
      if (std::string m = mismatch(shape.front(), got[k], fmt::format("{}[{}]", at, k), missing); !m.empty()) return m;
  if (shape.is_object())
    for (const auto& [key, value] : shape.items()) {
      const std::string field = at.empty() ? key : at + "." + key;
      const auto it = got.find(key);
      if (it == got.end()) {
        if (key == missing) return field + ": missing";
        continue;
      }
      if (std::string m = mismatch(value, *it, field, missing); !m.empty()) return m;
    }
  return "";
}

}  // namespace

std::string json_shape_mismatch(const JsonShape& shape, const nlohmann::json& got, const std::string& missing) {
  return mismatch(shape.value, got, shape.root, missing);
}

std::string json_type_error(const std::string& path, const std::string& what, const nlohmann::json::exception& e,
                            const nlohmann::json& j, const JsonShape* shape) {
  if (shape) {
    // The library names a missing key ("key 'engine' not found") but not where it is missing.
    const std::string text = e.what();
    const size_t open = text.find("key '"), close = text.find("' not found");
    const std::string missing = open != std::string::npos && close != std::string::npos && close > open + 5
                                    ? text.substr(open + 5, close - open - 5)
                                    : "";
    if (const std::string m = json_shape_mismatch(*shape, j, missing); !m.empty()) return fmt::format("{}: {}", path, m);
  }
  return json_shape_error(path, what, e);
}

}  // namespace ballbench

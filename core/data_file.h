#pragma once
// Result files: whole-file writes that a reader never sees half done (the text goes to a temporary
// file of this process's own beside PATH, then a rename; a FIFO or a device is written in place),
// JSON reads that are bounded and fail with one line naming the file, and the check that no
// output of a command lands on one of its inputs or on another output.
#include <cstdint>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "input_error.h"

namespace ballbench {

// The most a results file read back (a run, a sweep, a report's part) may hold, and how deeply its
// JSON may nest: far beyond what `ballbench` writes, short of what would exhaust memory or stack.
inline constexpr std::uintmax_t kMaxResultsFileBytes = 256ull << 20;
inline constexpr int kMaxJsonDepth = 64;

// True if `path` is written in place, not replaced by a rename: an existing FIFO, device or
// symbolic link (/dev/null, /dev/stdout, a user's link to a file).
bool special_target(const std::string& path);

// Where the temporary files for writing `path` go: `path` itself, or, for a special target (whose
// folder, /dev, is not for files), a name in the temporary folder.
std::string temp_base(const std::string& path);

// A temporary file of this process's own beside `path`, created empty (O_EXCL, so never a file
// that was there): "PATH.tmp.PID.TOKEN". Throws InputError naming `path` and `what` if it cannot.
// The temporary files that writers of `path` killed before they could remove theirs left beside
// it are removed first (remove_stale_temps).
std::string create_temp_beside(const std::string& path, const std::string& what);

// Removes the temporary files of writing `path` (named "PATH[.part].tmp.PID.TOKEN[.header|.tmp]",
// as this file's writers and the trajectory's name them) whose process no longer exists: those a
// killed run left (a SIGKILL gives no chance to clean up). Files of a live process, of another
// user's or of any other name are kept.
void remove_stale_temps(const std::string& path);

// A folder of this process's own for scratch files, in the temporary folder ($TMPDIR, else /tmp):
// "PREFIX.PID.XXXXXX" (mkdtemp). Such folders left by processes that are gone (a command killed
// before it could remove its own) are removed first. Throws InputError if it cannot make one.
std::string make_work_folder(const std::string& prefix);

// A regular file to read, checked before it is opened: it exists, is a regular file (not a
// folder, a FIFO or a device, which could block or never end) and holds at most `max_bytes`.
// Throws InputError "PATH: cannot read WHAT: WHY".
void check_readable_file(const std::string& path, const std::string& what, std::uintmax_t max_bytes);

// One file a command reads (`output` false) or writes, named by the flag that gave it.
struct PathUse {
  std::string flag;  // "--json", "--scene", "RESULTS"
  std::string path;
  bool output = false;
  bool folder = false;  // an output folder: every file in it, at any depth, may be written or removed
};

// Before anything runs: no output is the same file as an input or as another output, however
// spelled (./a, sub/../a, a symbolic link, a hard link: compared by device and inode where the
// file exists, by resolved path where it does not), and no input lies in an output folder. Two
// outputs into the same device or FIFO (/dev/null) are allowed. Throws InputError "--X PATH: same
// file as --Y PATH" or "--Y PATH: inside --X FOLDER, which the command writes".
void check_path_clashes(const std::vector<PathUse>& uses);

// Files read by options of the whole command (`--engines`), noted as they are read so that each
// subcommand checks its outputs against them too.
void note_input_file(const std::string& flag, const std::string& path);
const std::vector<PathUse>& noted_input_files();

// Why a write failed, for its one line: errno's text ("No space left on device", "File too large"),
// or "an I/O error" where the library left none.
std::string write_error_text(int err);

// Creates the parent folders; throws InputError naming `path` and `what` ("the results file") if
// the file cannot be written.
void write_file_atomically(const std::string& path, const std::string& text, const std::string& what);

// A whole file written elsewhere (`from`) becomes `to`: renamed over it, or, where `to` is a FIFO or
// a device, copied into it (a rename would replace it with a regular file).
void move_file_into_place(const std::string& from, const std::string& to, const std::string& what);

// Throws InputError naming `path` and `what` if a file could not be written there (checked before
// a long run, so that it is not found only at its end). `create_parents`: the writer will create
// the parent folders (write_file_atomically does), so they are created here.
void check_writable(const std::string& path, const std::string& what, bool create_parents);

// The whole of a file, byte for byte ("" for a file that cannot be opened).
std::string read_text_file(const std::string& path);

// Throws InputError naming the file and `what` if it cannot be opened, is not a regular file,
// holds more than kMaxResultsFileBytes, nests deeper than kMaxJsonDepth or is not JSON.
nlohmann::json parse_json_file(const std::string& path, const std::string& what);
std::string json_shape_error(const std::string& path, const std::string& what, const std::exception& e);

// What a kind of file holds, for naming the field a file gets wrong: `value` is such a file with
// every field ballbench may write present (an array's elements are all like its first), and
// `root` names the whole ("runs" for a results file's list, "" for an object).
struct JsonShape {
  nlohmann::json value;
  std::string root;
};

// "a number", "a string", "true or false", "an array", "an object" or "null": a value's type in a message.
const char* json_kind_name(const nlohmann::json& j);

// The first place, in `shape`'s order, where `got` holds another type than `shape` says, or lacks
// the key `missing` that `shape` has: "runs[3].metrics.energy.drift: expected a number, got a
// string", "runs[0].engine: missing"; "" if none. A number in `shape` takes null too (NaN is
// written as null); null takes anything.
std::string json_shape_mismatch(const JsonShape& shape, const nlohmann::json& got, const std::string& missing = "");

// The one line for a JSON exception `e` met while converting file `path` (`what`, as
// json_shape_error): the field `shape` finds wrong in `j` ("PATH: FIELD: expected a number, got a
// string"), or, if it finds none, the library's message.
std::string json_type_error(const std::string& path, const std::string& what, const nlohmann::json::exception& e,
                            const nlohmann::json& j, const JsonShape* shape);

// parse_json_file, then `convert` (JSON -> value); a field missing or of the wrong type (a JSON
// exception, or an InputError of the converter's naming the field) is an InputError naming the
// file too, and the field where `shape_of(j)` (a JsonShape) can tell it.
template <class Convert, class ShapeOf = std::nullptr_t>
auto read_json_file(const std::string& path, const std::string& what, Convert convert, ShapeOf shape_of = nullptr) {
  const nlohmann::json j = parse_json_file(path, what);
  try {
    return convert(j);
  } catch (const InputError& e) {  // a field the converter named: "points[3].dt: expected a number"
    throw InputError(path + ": " + e.what());
  } catch (const nlohmann::json::exception& e) {
    if constexpr (std::is_same_v<ShapeOf, std::nullptr_t>) {
      throw InputError(json_type_error(path, what, e, j, nullptr));
    } else {
      const JsonShape shape = shape_of(j);
      throw InputError(json_type_error(path, what, e, j, &shape));
    }
  } catch (const std::length_error& e) {  // a count no file of ours holds
    throw InputError(json_shape_error(path, what, e));
  } catch (const std::bad_alloc& e) {
    throw InputError(json_shape_error(path, what, e));
  }
}

}  // namespace ballbench

#pragma once
// Result files: whole-file writes that a reader never sees half done (the text goes to PATH.tmp,
// then a rename; a FIFO or a device is written in place), and JSON reads that fail with one line
// naming the file.
#include <exception>
#include <string>

#include <nlohmann/json.hpp>

#include "input_error.h"

namespace ballbench {

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

// Throws InputError naming the file and `what` if it cannot be opened or is not JSON.
nlohmann::json parse_json_file(const std::string& path, const std::string& what);
std::string json_shape_error(const std::string& path, const std::string& what, const std::exception& e);

// parse_json_file, then `convert` (JSON -> value); a field missing or of the wrong type is an
// InputError naming the file too.
template <class Convert>
auto read_json_file(const std::string& path, const std::string& what, Convert convert) {
  const nlohmann::json j = parse_json_file(path, what);
  try {
    return convert(j);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(json_shape_error(path, what, e));
  }
}

}  // namespace ballbench
